// Vertex processing: runs the shader's vertex function once per vertex, computes the clip mask
// (which frustum planes the vertex is outside of) and the window position, as lavapipe's draw
// module does in its JIT code: 1/w is a real division and x_win = fmuladd(x * (1/w), scale, trans).
// Deliberately no vertex cache: every vertex of the draw is shaded exactly once, up front.
#pragma once

#include <softraster/detail/fused_multiply_add.hpp>
#include <softraster/math.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <array>
#include <cstdint>

namespace softraster::detail {

// A vertex after the vertex shader. `window` holds window x, y, z and, in w, 1/w_clip.
template <int NumVaryings>
struct ShadedVertex {
  Vec4 clip;
  Vec4 window;
  std::uint32_t clipMask = 0;
  float pointSize = 1.0f;  // gl_PointSize, used by points only
  bool edgeFlag = true;    // false for vertices clipping creates where an edge leaves the frustum
  std::array<float, NumVaryings> varyings{};
};

// Clip-mask bits, in lavapipe's plane order (also the order clipping visits the planes).
enum ClipPlaneBit : std::uint32_t {
  kOutsideRight = 1u << 0,   // x > w
  kOutsideLeft = 1u << 1,    // x < -w
  kOutsideBottom = 1u << 2,  // y > w
  kOutsideTop = 1u << 3,     // y < -w
  kOutsideNear = 1u << 4,    // z < 0
  kOutsideFar = 1u << 5,     // z > w
};

// The comparisons are unordered, as in lavapipe: a NaN takes a vertex outside every plane whose
// test it takes part in. Without depth clipping (depth clamp on) the z planes are not tested.
inline std::uint32_t computeClipMask(Vec4 c, bool clipDepth = true) {
  std::uint32_t mask = 0;
  if (!(c.x <= c.w)) mask |= kOutsideRight;
  if (!(0.0f <= c.x + c.w)) mask |= kOutsideLeft;
  if (!(c.y <= c.w)) mask |= kOutsideBottom;
  if (!(0.0f <= c.y + c.w)) mask |= kOutsideTop;
  if (clipDepth && !(0.0f <= c.z)) mask |= kOutsideNear;
  if (clipDepth && !(c.z <= c.w)) mask |= kOutsideFar;
  return mask;
}

// Vulkan viewport as lavapipe stores it: scale and translate per axis (z in [0, 1] clip space).
struct ViewportTransform {
  std::array<float, 3> scale{};
  std::array<float, 3> translate{};
};

inline ViewportTransform makeViewportTransform(const Viewport& vp) {
  ViewportTransform t;
  const float halfWidth = 0.5f * vp.width;
  const float halfHeight = 0.5f * vp.height;
  t.scale = {halfWidth, halfHeight,
             static_cast<float>(static_cast<double>(vp.maxDepth) - static_cast<double>(vp.minDepth))};
  t.translate = {halfWidth + vp.x, halfHeight + vp.y, vp.minDepth};
  return t;
}

// Window position of a shaded vertex, computed the way lavapipe's vertex JIT code does.
template <bool Fused>
inline Vec4 windowPosition(Vec4 clip, const ViewportTransform& vp) {
  const float oneOverW = 1.0f / clip.w;
  return {fmuladd<Fused>(clip.x * oneOverW, vp.scale[0], vp.translate[0]),
          fmuladd<Fused>(clip.y * oneOverW, vp.scale[1], vp.translate[1]),
          fmuladd<Fused>(clip.z * oneOverW, vp.scale[2], vp.translate[2]), oneOverW};
}

template <class Shader, bool Fused>
inline ShadedVertex<Shader::kVaryings> shadeVertex(const typename Shader::Uniforms& uniforms,
                                                   const typename Shader::Vertex& vertex,
                                                   const ViewportTransform& vp, bool clipDepth) {
  ShadedVertex<Shader::kVaryings> out;
  out.clip = Shader::vertex(uniforms, vertex, out.varyings.data());
  out.clipMask = computeClipMask(out.clip, clipDepth);
  out.window = windowPosition<Fused>(out.clip, vp);
  out.pointSize = pointSizeOf<Shader>(uniforms, vertex);
  return out;
}

}  // namespace softraster::detail
