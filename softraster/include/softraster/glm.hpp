// GLM interop: GLM's float vectors and matrices to softraster's types (math.hpp) and back, bit for
// bit (both are column-major float; nothing is rounded), and GL's clip space to Vulkan's.
// Only usable where GLM is installed (Debian's libglm-dev): this header includes <glm/glm.hpp>
// and is never included by pipeline.hpp, so softraster itself does not depend on GLM.
//
// softraster's clip space is Vulkan's: x right, y DOWN, z in [0, w]. GLM's projections are GL's
// by default: y up, z in [-w, w]. Either
//   - #define GLM_FORCE_DEPTH_ZERO_TO_ONE before including GLM (z in [0, w]) and flip y with
//     flipClipY() (or negate projection[1][1]), or
//   - keep GL's matrices and multiply by vulkanFromGlClip() (y flipped, z halved and moved), which
//     costs a rounding per element when the product is formed.
// With y flipped, FrontFace::CounterClockwise means what it means in GL (counter-clockwise as
// seen in the picture), so GL code's winding carries over.
// Deliberately no double-precision types (softraster's are float) and no quaternions.
#pragma once

#include <softraster/math.hpp>

#if !__has_include(<glm/glm.hpp>)
#error "softraster/glm.hpp needs GLM (Debian: libglm-dev)"
#endif
#include <glm/glm.hpp>

namespace softraster {

inline Vec2 fromGlm(const glm::vec2& v) { return {v.x, v.y}; }
inline Vec3 fromGlm(const glm::vec3& v) { return {v.x, v.y, v.z}; }
inline Vec4 fromGlm(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }
// glm::mat4 m[c] is column c, as Mat4::columns[c] is.
inline Mat4 fromGlm(const glm::mat4& m) {
  Mat4 r;
  for (int c = 0; c < 4; ++c) r.columns[c] = fromGlm(m[c]);
  return r;
}

inline glm::vec2 toGlm(Vec2 v) { return {v.x, v.y}; }
inline glm::vec3 toGlm(Vec3 v) { return {v.x, v.y, v.z}; }
inline glm::vec4 toGlm(const Vec4& v) { return {v.x, v.y, v.z, v.w}; }
inline glm::mat4 toGlm(const Mat4& m) {
  glm::mat4 r(1.0f);
  for (int c = 0; c < 4; ++c) r[c] = toGlm(m.columns[c]);
  return r;
}

// `projection` with its clip y negated (row 1 of the matrix), exactly: a GL-style projection
// built with GLM_FORCE_DEPTH_ZERO_TO_ONE becomes Vulkan's.
inline glm::mat4 flipClipY(glm::mat4 projection) {
  for (int c = 0; c < 4; ++c) projection[c][1] = -projection[c][1];
  return projection;
}

// GL clip space (y up, z in [-w, w]) to Vulkan's (y down, z in [0, w]): y' = -y, z' = (z + w) / 2.
// vulkanFromGlClip() * glProjection is a Vulkan projection.
inline glm::mat4 vulkanFromGlClip() {
  glm::mat4 m(1.0f);
  m[1][1] = -1.0f;
  m[2][2] = 0.5f;
  m[3][2] = 0.5f;
  return m;
}

}  // namespace softraster
