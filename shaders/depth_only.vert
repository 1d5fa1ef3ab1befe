#version 450
// depth_only: positions to clip space and nothing else, for a depth pass (a shadow map: the
// scene's "passes", rendered with no colour attachment). C++ twin: depth_only.hpp.
// `precise`: every product rounded on its own, the sum in the written order (vertex_color.vert's).

layout(location = 0) in vec3 inPosition;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
  float pointSize;
} u;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  gl_PointSize = u.pointSize;
}
