#version 450
// varyings_64: 64 varying components (16 vec4 outputs, Vulkan's minimum maxVertexOutputComponents),
// smooth, flat and noperspective in turn; each output is the vertex colour rotated by its index
// (moves only, no arithmetic). C++ twin: varyings_64.hpp.

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec4 inColour;

layout(push_constant) uniform Uniforms {
  mat4 modelViewProjection;
} u;

layout(location = 0) out vec4 v0;
layout(location = 1) flat out vec4 v1;
layout(location = 2) noperspective out vec4 v2;
layout(location = 3) out vec4 v3;
layout(location = 4) flat out vec4 v4;
layout(location = 5) noperspective out vec4 v5;
layout(location = 6) out vec4 v6;
layout(location = 7) flat out vec4 v7;
layout(location = 8) noperspective out vec4 v8;
layout(location = 9) out vec4 v9;
layout(location = 10) flat out vec4 v10;
layout(location = 11) noperspective out vec4 v11;
layout(location = 12) out vec4 v12;
layout(location = 13) flat out vec4 v13;
layout(location = 14) noperspective out vec4 v14;
layout(location = 15) out vec4 v15;

void main() {
  precise vec4 clip = u.modelViewProjection[0] * inPosition.x
                    + u.modelViewProjection[1] * inPosition.y
                    + u.modelViewProjection[2] * inPosition.z
                    + u.modelViewProjection[3];
  gl_Position = clip;
  v0 = inColour.xyzw;
  v1 = inColour.yzwx;
  v2 = inColour.zwxy;
  v3 = inColour.wxyz;
  v4 = inColour.xyzw;
  v5 = inColour.yzwx;
  v6 = inColour.zwxy;
  v7 = inColour.wxyz;
  v8 = inColour.xyzw;
  v9 = inColour.yzwx;
  v10 = inColour.zwxy;
  v11 = inColour.wxyz;
  v12 = inColour.xyzw;
  v13 = inColour.yzwx;
  v14 = inColour.zwxy;
  v15 = inColour.wxyz;
}
