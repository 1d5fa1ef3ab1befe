#version 450
// depth_view: the course's depth-buffer view as a shading model: each pixel's grey is
// near / z, z its distance along the view axis (clip w, interpolated perspective-correct), so
// the near plane is white and the grey falls off as the 1/z depth buffer does. C++ twin: depth_view.hpp.

layout(location = 0) in vec3 inPosition;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
  float pointSize;
  float nearPlane;  // the camera's near plane distance
} u;

layout(location = 0) out float vDepth;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  gl_PointSize = u.pointSize;
  vDepth = clip.w;
}
