#version 450
// depth_only: writes no colour; the fixed-function depth test and write are the whole pass.
// C++ twin: depth_only.hpp.

void main() {
}
