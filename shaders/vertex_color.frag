#version 450
// vertex_color: unlit, the vertex colour interpolated across the primitive.
// INTERPOLATION: empty, flat or noperspective, as in vertex_color.vert. C++ twin: vertex_color.hpp.

layout(location = 0) INTERPOLATION in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  outColour = vColour;
}
