// Depth bias for polygon modes LINE and POINT: Mesa's draw-module "offset" stage
// (draw_pipe_offset.c), which llvmpipe leaves the bias to whenever the draw pipeline draws
// unfilled polygons (lp_state_rasterizer.c). It runs after clipping and the float cull and
// before the unfilled stage, on the whole triangle: the offset comes from the triangle's own
// window-space slopes, is added to each vertex's window z (saturated to [0, 1]), and the lines
// or points the unfilled stage then makes carry that z. Operation order as in Mesa, in float:
//   e = v0 - v2, f = v1 - v2; det = ex*fy - ey*fx; a = ey*fz - ez*fy; b = ez*fx - ex*fz;
//   slope = max(|a * (1/det)|, |b * (1/det)|) * slopeFactor;
//   UNORM: constant = (float)(constantFactor * 1/(2^n - 1) * 2) (a GL factor 2, as for filled
//   triangles); D32_SFLOAT: constant = constantFactor * 2^(exponent(max |z|) - 23);
//   offset = constant + slope, clamped by the bias clamp (when not 0), then z = saturate(z + offset).
// Filled triangles take llvmpipe's own setup bias instead (exact/triangle_setup.hpp).
// Deliberately absent: drawing the lines and points (geometry/unfilled.hpp, exact/draw.hpp).
#pragma once

#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/formats.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace softraster::detail {

// Mesa's MAX2, MIN2 and SATURATE, with their comparisons' NaN behaviour.
inline float mesaMax2(float a, float b) { return a > b ? a : b; }
inline float mesaMin2(float a, float b) { return a < b ? a : b; }
inline float mesaSaturate(float x) { return x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f; }

// The offset Mesa's stage adds to the window z of triangle (w0, w1, w2) (window positions).
inline float unfilledDepthOffset(Vec4 w0, Vec4 w1, Vec4 w2, const DepthBias& bias, DepthFormat format) {
  const float ex = w0.x - w2.x, ey = w0.y - w2.y, ez = w0.z - w2.z;
  const float fx = w1.x - w2.x, fy = w1.y - w2.y, fz = w1.z - w2.z;
  const float det = ex * fy - ey * fx;
  const float invDet = 1.0f / det;
  const float a = ey * fz - ez * fy;
  const float b = ez * fx - ex * fz;
  const float dzdx = std::fabs(a * invDet);
  const float dzdy = std::fabs(b * invDet);
  const float slope = mesaMax2(dzdx, dzdy) * bias.slopeFactor;
  float offset;
  if (const int bits = unormDepthBits(format); bits != 0) {
    const double minimumResolvable = 1.0 / static_cast<double>((1ull << bits) - 1);
    offset = static_cast<float>(static_cast<double>(bias.constantFactor) * minimumResolvable * 2) + slope;
  } else {
    const float z0 = std::fabs(w0.z), z1 = std::fabs(w1.z), z2 = std::fabs(w2.z);
    const float maxZ = z0 > z1 ? mesaMax2(z0, z2) : mesaMax2(z1, z2);  // MAX3
    const std::int32_t exponent = static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(maxZ) & 0x7f800000u) - (23 << 23);
    offset = bias.constantFactor * std::bit_cast<float>(std::max(exponent, 0)) + slope;
  }
  if (bias.clamp != 0.0f) offset = bias.clamp < 0.0f ? mesaMax2(offset, bias.clamp) : mesaMin2(offset, bias.clamp);
  return offset;
}

// The triangle's vertices as the offset stage leaves them (copies; z = saturate(z + offset)).
template <int N>
inline void offsetUnfilledTriangle(ShadedVertex<N>& v0, ShadedVertex<N>& v1, ShadedVertex<N>& v2, const DepthBias& bias,
                                   DepthFormat format) {
  const float offset = unfilledDepthOffset(v0.window, v1.window, v2.window, bias, format);
  for (ShadedVertex<N>* v : {&v0, &v1, &v2}) v->window.z = mesaSaturate(v->window.z + offset);
}

}  // namespace softraster::detail
