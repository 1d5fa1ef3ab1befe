#version 450
// vertex_color: unlit, the vertex colour interpolated across the primitive.
// INTERPOLATION is the varying's qualifier: empty (perspective-correct), flat or noperspective;
// the build compiles one variant per qualifier. C++ twin: vertex_color.hpp.
// `precise` keeps every product rounded on its own (no FMA) and the sum in the written order,
// so softraster can reproduce it to the bit.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColour;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
  float pointSize;
} u;

layout(location = 0) INTERPOLATION out vec4 vColour;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  gl_PointSize = u.pointSize;
  vColour = inColour;
}
