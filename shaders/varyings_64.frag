#version 450
// varyings_64: the 16 vec4 inputs (smooth, flat, noperspective in turn) weighted by (i + 1) / 256 (exact constants)
// and summed in index order; `precise` keeps every product and sum rounded on its own, in this
// order. C++ twin: varyings_64.hpp.

layout(location = 0) in vec4 v0;
layout(location = 1) flat in vec4 v1;
layout(location = 2) noperspective in vec4 v2;
layout(location = 3) in vec4 v3;
layout(location = 4) flat in vec4 v4;
layout(location = 5) noperspective in vec4 v5;
layout(location = 6) in vec4 v6;
layout(location = 7) flat in vec4 v7;
layout(location = 8) noperspective in vec4 v8;
layout(location = 9) in vec4 v9;
layout(location = 10) flat in vec4 v10;
layout(location = 11) noperspective in vec4 v11;
layout(location = 12) in vec4 v12;
layout(location = 13) flat in vec4 v13;
layout(location = 14) noperspective in vec4 v14;
layout(location = 15) in vec4 v15;
layout(location = 0) out vec4 outColour;

void main() {
  precise vec4 sum = v0 * (1.0 / 256.0);
  sum = sum + v1 * (2.0 / 256.0);
  sum = sum + v2 * (3.0 / 256.0);
  sum = sum + v3 * (4.0 / 256.0);
  sum = sum + v4 * (5.0 / 256.0);
  sum = sum + v5 * (6.0 / 256.0);
  sum = sum + v6 * (7.0 / 256.0);
  sum = sum + v7 * (8.0 / 256.0);
  sum = sum + v8 * (9.0 / 256.0);
  sum = sum + v9 * (10.0 / 256.0);
  sum = sum + v10 * (11.0 / 256.0);
  sum = sum + v11 * (12.0 / 256.0);
  sum = sum + v12 * (13.0 / 256.0);
  sum = sum + v13 * (14.0 / 256.0);
  sum = sum + v14 * (15.0 / 256.0);
  sum = sum + v15 * (16.0 / 256.0);
  outColour = sum;
}
