// Triangle setup, as lavapipe's lp_setup_tri.c and lp_state_setup.c do it:
//   - snapping: X = round_half_even((x_win - 0.5) * 256) with the subtraction in float
//     (cvtps2dq: out-of-range and NaN give INT32_MIN);
//   - the sign of the 64-bit fixed-point area decides facing, culling and, when negative,
//     the vertex order (v0, v2, v1) used from here on (provoking vertex first), or (v1, v0, v2)
//     with provoking vertex last (the provoking vertex stays third);
//   - three 64-bit edge functions with the top-left rule (window y points down); a single-sample
//     triangle whose bounding box holds no pixel centre is dropped before them;
//   - float plane equations a(px, py) = a0 + dadx*px + dady*py for depth, 1/w and varyings,
//     from the unsnapped window positions, in lavapipe's operation order, no FMA.
//   - the depth bias of lp_do_offset_tri: max(|dz/dx|, |dz/dy|) * slope plus the constant factor
//     scaled by 2/(2^n - 1) for UNORM depth (a GL factor of 2 lavapipe keeps) or by
//     2^(exponent(max |z|) - 23) for float depth, then clamped.
//   - with 4x MSAA the pixel offset is 0 (snapping and plane origin at the pixel corner) and
//     coverage is tested at the Vulkan standard sample positions.
// Deliberately absent: the bottom-left fill rule.
#pragma once

#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/formats.hpp>
#include <softraster/state.hpp>

#include <bit>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace softraster::detail {

inline constexpr int kSubpixelBits = 8;
inline constexpr float kSubpixelScale = 256.0f;
inline constexpr float kPixelCentreOffset = 0.5f;  // lavapipe forces half-pixel centres (single-sample)

// The Vulkan standard 4x sample positions, in pixels and in 1/256 px (lp_sample_pos_4x).
inline constexpr float kSamplePositions4x[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
inline constexpr std::int64_t kFixedSamplePositions4x[4][2] = {{96, 32}, {224, 96}, {32, 160}, {160, 224}};

// One window coordinate to 24.8 fixed point, as SSE's cvtps2dq does it in round-to-nearest-even.
inline std::int32_t snapToSubpixel(float windowCoordinate, float pixelOffset = kPixelCentreOffset) {
  const float scaled = (windowCoordinate - pixelOffset) * kSubpixelScale;
  if (!(scaled >= -2147483648.0f && scaled < 2147483648.0f)) return INT32_MIN;
  return static_cast<std::int32_t>(std::nearbyint(scaled));
}

struct FixedTriangle {
  std::int32_t x[3];
  std::int32_t y[3];
};

// One vertex's window x and y snapped (the draw loop snaps each vertex once and builds the
// triangles of its straight path from them: the same bits as snapTriangle).
struct FixedPoint {
  std::int32_t x;
  std::int32_t y;
};

inline FixedPoint snapVertex(Vec4 w, float pixelOffset = kPixelCentreOffset) {
  return {snapToSubpixel(w.x, pixelOffset), snapToSubpixel(w.y, pixelOffset)};
}

inline FixedTriangle fixedTriangle(FixedPoint a, FixedPoint b, FixedPoint c) { return {{a.x, b.x, c.x}, {a.y, b.y, c.y}}; }

inline FixedTriangle snapTriangle(Vec4 w0, Vec4 w1, Vec4 w2, float pixelOffset = kPixelCentreOffset) {
  return {{snapToSubpixel(w0.x, pixelOffset), snapToSubpixel(w1.x, pixelOffset), snapToSubpixel(w2.x, pixelOffset)},
          {snapToSubpixel(w0.y, pixelOffset), snapToSubpixel(w1.y, pixelOffset), snapToSubpixel(w2.y, pixelOffset)}};
}

// Sign of (X0-X1)*(Y2-Y0) - (X2-X0)*(Y0-Y1), with lavapipe's 32-bit differences and
// wrapping 64-bit arithmetic. Positive is counter-clockwise in Vulkan's sense.
inline int fixedAreaSign(const FixedTriangle& t) {
  const auto dx01 = static_cast<std::int32_t>(static_cast<std::uint32_t>(t.x[0]) - static_cast<std::uint32_t>(t.x[1]));
  const auto dy01 = static_cast<std::int32_t>(static_cast<std::uint32_t>(t.y[0]) - static_cast<std::uint32_t>(t.y[1]));
  const auto dx20 = static_cast<std::int32_t>(static_cast<std::uint32_t>(t.x[2]) - static_cast<std::uint32_t>(t.x[0]));
  const auto dy20 = static_cast<std::int32_t>(static_cast<std::uint32_t>(t.y[2]) - static_cast<std::uint32_t>(t.y[0]));
  const std::uint64_t area = static_cast<std::uint64_t>(std::int64_t{dx01} * dy20) -
                             static_cast<std::uint64_t>(std::int64_t{dx20} * dy01);
  return area == 0 ? 0 : (area >> 63) ? -1 : 1;
}

// Which fixed-point windings survive culling (lp_setup_choose_triangle).
struct WindingFilter {
  bool drawCounterClockwise;
  bool drawClockwise;
};

inline WindingFilter windingFilter(const RasterizationState& rs) {
  const bool ccwIsFront = rs.frontFace == FrontFace::CounterClockwise;
  switch (rs.cullMode) {
    case CullMode::None: return {true, true};
    case CullMode::Back: return {ccwIsFront, !ccwIsFront};
    case CullMode::Front: return {!ccwIsFront, ccwIsFront};
    case CullMode::FrontAndBack: return {false, false};
  }
  return {false, false};
}

// Whether no pixel centre lies in the triangle's bounding box, single-sample (centres at
// multiples of 256 once the half-pixel offset is snapped in): then it covers no pixel and needs
// no setup. A centre left of or above the box is outside an edge (the edge values are integers
// and the fill rule's +1 only takes in centres on an edge); setupEdges' bounds keep the pixels
// whose centre is at the box's left or top or inside it, and stop before its right and bottom.
inline bool missesEveryPixelCentre(const FixedTriangle& t) {
  const std::int64_t minX = std::min({t.x[0], t.x[1], t.x[2]}), maxX = std::max({t.x[0], t.x[1], t.x[2]});
  const std::int64_t minY = std::min({t.y[0], t.y[1], t.y[2]}), maxY = std::max({t.y[0], t.y[1], t.y[2]});
  return ((minX + 255) >> kSubpixelBits) > ((maxX - 1) >> kSubpixelBits) ||
         ((minY + 255) >> kSubpixelBits) > ((maxY - 1) >> kSubpixelBits);
}

// Edge function i (vertex i to i+1) in units of 1/256 px, evaluated at pixel (px, py) as
// c + dcdy*py - dcdx*px; the pixel centre is inside the edge when the value is > 0.
struct EdgeFunction {
  std::int64_t c;
  std::int64_t dcdx;  // DY << 8
  std::int64_t dcdy;  // DX << 8
};

struct TriangleEdges {
  EdgeFunction edges[3];
  PixelRect bounds;  // pixels whose centres may be covered
};

// Edge functions of a counter-clockwise (positive-area) fixed-point triangle.
inline TriangleEdges setupEdges(const FixedTriangle& t) {
  TriangleEdges e;
  // Edge i runs from vertex i to vertex j, written out for the three (a loop with (i + 1) % 3
  // stayed a loop at -O2, a tenth of the front end of a million small triangles).
  const auto edge = [&t](int i, int j) -> EdgeFunction {
    const std::int64_t dy = std::int64_t{t.y[i]} - t.y[j];
    const std::int64_t dx = std::int64_t{t.x[i]} - t.x[j];
    std::int64_t c = dy * t.x[i] - dx * t.y[i];
    if (dy < 0 || (dy == 0 && dx > 0)) c += 1;  // top-left rule: left and top edges own their pixels
    return {c, dy << kSubpixelBits, dx << kSubpixelBits};
  };
  e.edges[0] = edge(0, 1);
  e.edges[1] = edge(1, 2);
  e.edges[2] = edge(2, 0);
  const int minX = std::min({t.x[0], t.x[1], t.x[2]});
  const int maxX = std::max({t.x[0], t.x[1], t.x[2]});
  const int minY = std::min({t.y[0], t.y[1], t.y[2]});
  const int maxY = std::max({t.y[0], t.y[1], t.y[2]});
  e.bounds = {minX >> kSubpixelBits, minY >> kSubpixelBits, (maxX - 1) >> kSubpixelBits, (maxY - 1) >> kSubpixelBits};
  return e;
}

// a(px, py) = a0 + dadx*px + dady*py at the centre of pixel (px, py).
struct PlaneEquation {
  float a0 = 0, dadx = 0, dady = 0;
};

// The shared part of the plane setup of one triangle (init_args in lp_state_setup.c).
class PlaneSetup {
 public:
  // pixelOffset: 0.5 puts a0 at the centre of pixel (0, 0) (single-sample), 0 at its corner (MSAA).
  PlaneSetup(Vec4 w0, Vec4 w1, Vec4 w2, float pixelOffset = kPixelCentreOffset) {
    const float dx01 = w0.x - w1.x, dy01 = w0.y - w1.y;
    const float dx20 = w2.x - w0.x, dy20 = w2.y - w0.y;
    const float e = dx01 * dy20;
    const float f = dy01 * dx20;
    const float ooa = 1.0f / (e - f);
    dx01_ = dx01, dy01_ = dy01, dx20_ = dx20, dy20_ = dy20, ooa_ = ooa;
    dx20_ooa_ = dx20 * ooa;
    dy20_ooa_ = dy20 * ooa;
    dx01_ooa_ = dx01 * ooa;
    dy01_ooa_ = dy01 * ooa;
    x0Centre_ = w0.x - pixelOffset;
    y0Centre_ = w0.y - pixelOffset;
  }

  // calc_coef4 in lp_state_setup.c.
  PlaneEquation plane(float a0, float a1, float a2) const {
    const float da01 = a0 - a1;
    const float da20 = a2 - a0;
    PlaneEquation p;
    p.dadx = da01 * dy20_ooa_ - da20 * dy01_ooa_;
    p.dady = da20 * dx01_ooa_ - da01 * dx20_ooa_;
    p.a0 = a0 - (p.dadx * x0Centre_ + p.dady * y0Centre_);
    return p;
  }

  // The depth offset lp_do_offset_tri adds to every fragment's depth; z0..z2 are the window
  // depths of the (reordered) vertices.
  float depthBias(float z0, float z1, float z2, const DepthBias& bias, DepthFormat format) const {
    if (!bias.enable || (bias.slopeFactor == 0.0f && bias.constantFactor == 0.0f)) return 0.0f;
    const float dz01 = z0 - z1, dz20 = z2 - z0;
    const float dzdx = std::fabs((dz20 * dy01_ - dy20_ * dz01) * ooa_);
    const float dzdy = std::fabs((dx20_ * dz01 - dz20 * dx01_) * ooa_);
    const float steepest = !(dzdx <= dzdy) ? dzdx : dzdy;  // unordered greater-than select
    const float slope = steepest * bias.slopeFactor;
    float offset;
    if (const int bits = unormDepthBits(format); bits != 0) {
      const double minimumResolvable = 1.0 / static_cast<double>((1ull << bits) - 1);
      offset = static_cast<float>(static_cast<double>(bias.constantFactor) * minimumResolvable * 2) + slope;
    } else {
      const auto sseMax = [](float a, float b) { return a > b ? a : b; };
      const float maxZ = sseMax(std::fabs(z2), sseMax(std::fabs(z0), std::fabs(z1)));
      const std::int32_t exponent =
          static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(maxZ) & 0x7f800000u) - (23 << 23);
      const float unit = std::bit_cast<float>(std::max(exponent, 0));  // 2^(e - 23), or 0
      offset = unit * bias.constantFactor + slope;
    }
    if (bias.clamp > 0) offset = bias.clamp < offset ? bias.clamp : offset;  // SSE min(clamp, offset)
    if (bias.clamp < 0) offset = bias.clamp > offset ? bias.clamp : offset;  // SSE max(clamp, offset)
    return offset;
  }

 private:
  float dx01_, dy01_, dx20_, dy20_, ooa_;
  float dx20_ooa_, dy20_ooa_, dx01_ooa_, dy01_ooa_;
  float x0Centre_, y0Centre_;
};

}  // namespace softraster::detail
