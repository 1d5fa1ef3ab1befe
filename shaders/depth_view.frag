#version 450
// depth_view: grey near / z (above 1 only in front of the near plane, where the UNORM store
// clamps it). C++ twin: depth_view.hpp.

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
  float pointSize;
  float nearPlane;
} u;

layout(location = 0) in float vDepth;
layout(location = 0) out vec4 outColour;

void main() {
  precise float grey = u.nearPlane / vDepth;
  outColour = vec4(grey, grey, grey, 1.0);
}
