#version 450
// vertex_color: unlit, the vertex colour interpolated perspective-correctly.
// C++ twin: vertex_color.hpp.

layout(location = 0) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  outColour = vColour;
}
