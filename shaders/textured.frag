#version 450
// textured: the texture at vTexcoord (implicit LOD: derivatives per 2x2 quad) times the vertex
// colour. C++ twin: textured.hpp.

layout(set = 1, binding = 0) uniform sampler2D uTexture;

layout(location = 0) in vec2 vTexcoord;
layout(location = 1) in vec4 vColour;
layout(location = 0) out vec4 outColour;

void main() {
  outColour = texture(uTexture, vTexcoord) * vColour;
}
