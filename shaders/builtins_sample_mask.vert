#version 450
// builtins_sample_mask: the fragment built-ins gl_SampleMask and gl_SampleMaskIn (the
// vertex stage is vertex_color's). C++ twin: builtins_sample_mask.hpp.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColour;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
} u;

layout(location = 0) out vec4 vColour;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  vColour = inColour;
}
