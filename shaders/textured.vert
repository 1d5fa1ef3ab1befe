#version 450
// textured: unlit, a texture modulated by the vertex colour. C++ twin: textured.hpp.
// `precise` keeps every product rounded on its own (no FMA) and the sum in the written order,
// so softraster can reproduce it to the bit.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec2 inTexcoord;
layout(location = 2) in vec4 inColour;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
} u;

layout(location = 0) out vec2 vTexcoord;
layout(location = 1) out vec4 vColour;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  vTexcoord = inTexcoord;
  vColour = inColour;
}
