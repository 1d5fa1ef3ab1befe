// Line and point setup, as lavapipe's lp_setup_line.c and lp_setup_point.c do it (plain C, no
// FMA). Both turn the primitive into a quad of edge functions that the rasterizer walks like a
// triangle, plus plane equations for depth, 1/w and the varyings.
//   - Snapping here is Mesa's util_iround(256 * v) on x86-64: round half away from zero through
//     a float add of 0.5, not the round-half-even of triangles.
//   - Rectangular lines: the snapped endpoints offset by +/-(iround(256 * -dy * s),
//     iround(256 * dx * s)), s = (width / 2) / sqrt(dx^2 + dy^2).
//   - Bresenham lines: GL's diamond-exit rule with a major-axis quad of iround(width) pixels.
//   - Points: a square of max(1, iround(256 * size)/256) pixels; attributes constant. With 4x
//     MSAA (lp_setup_point.c, setup->multisample) the centre is snapped without the half-pixel
//     offset, as triangles are, and the square is cut to the draw region exactly (its planes
//     are clamped to the region's pixel edges: no partial column or row, unlike triangles).
//   - Lines with 4x MSAA (lp_setup_line.c with setup->multisample): the quad is snapped without
//     the half-pixel offset, but the attribute planes keep it (lavapipe's line coefficients use
//     pixel_offset 0.5 while its MSAA fragment code adds 0.5 again: attributes and depth sit half
//     a pixel right of and below where a single-sample line has them); the bounding box stays
//     (min + 255) >> 8, which is not conservative for samples left of or above the first pixel
//     centre, so which of those samples are drawn depends on lavapipe's binning into 64x64
//     tiles (msaaLineWalk). Deviations::Spec evaluates the attributes at the fragment centre and
//     walks every pixel a sample of the quad can be in.
// Deliberately absent: smooth and stippled lines, point sprites.
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/rasterizer.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <initializer_list>

namespace softraster::detail {

// Mesa's util_iround on x86-64; out of range (undefined in C) gives cvttss2si's INT32_MIN.
inline std::int32_t iroundHalfAway(float f) {
  const float g = f >= 0.0f ? f + 0.5f : f - 0.5f;
  if (!(g > -2147483648.0f && g < 2147483648.0f)) return INT32_MIN;
  return static_cast<std::int32_t>(g);
}

inline std::int32_t snapLineCoordinate(float v) { return iroundHalfAway(kSubpixelScale * v); }

// A convex quad in 1/256 px, counter-clockwise, as four edge functions.
struct QuadEdges {
  EdgeFunction edges[4];
  PixelRect bounds;  // lavapipe's: the pixel centres (1/256 px, no offset) the quad may cover
  PixelRect sampleBounds;  // every pixel a 4x sample inside the quad may be in (conservative)
};

// Written into q in place: a QuadEdges built in a temporary and copied (std::optional's
// constructor copies) is read back with 16-byte loads over its 4- and 8-byte stores, a stalled
// store forward per load (a fifth of a wireframe's line setup).
// The short loops in this file are unrolled with #pragma GCC unroll: GCC 12 at -O2 keeps them as
// loops, and a line's setup spent a quarter of its instructions on their control and on a switch
// over the shader's constant interpolation it could not fold.
inline void quadEdges(const std::array<std::int32_t, 4>& x, const std::array<std::int32_t, 4>& y, QuadEdges& q) {
#pragma GCC unroll 4
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const std::int64_t dcdx = std::int64_t{y[i]} - y[j];
    const std::int64_t dcdy = std::int64_t{x[i]} - x[j];
    std::int64_t c = dcdx * x[i] - dcdy * y[i];
    if (dcdx < 0 || (dcdx == 0 && dcdy > 0)) c += 1;  // same fill rule as triangles
    q.edges[i] = {c, dcdx << kSubpixelBits, dcdy << kSubpixelBits};
  }
  const auto [minX, maxX] = std::minmax({x[0], x[1], x[2], x[3]});
  const auto [minY, maxY] = std::minmax({y[0], y[1], y[2], y[3]});
  q.bounds = {(minX + 255) >> kSubpixelBits, (minY + 255) >> kSubpixelBits, ((maxX + 255) >> kSubpixelBits) - 1,
              ((maxY + 255) >> kSubpixelBits) - 1};
  q.sampleBounds = {minX >> kSubpixelBits, minY >> kSubpixelBits, (maxX - 1) >> kSubpixelBits, (maxY - 1) >> kSubpixelBits};
}

// Snapped line coordinates beyond this (1/256 px; 2^20 pixels) are not drawn: clipping keeps real
// lines inside the viewport bounds (2^15 pixels), and a coordinate that snapped to INT32_MIN (too
// large, or NaN) would overflow the quad's arithmetic. lavapipe's result there is undefined too.
inline constexpr std::int32_t kMaxLineCoordinate = 1 << 28;

inline bool lineCoordinatesInRange(std::initializer_list<std::int32_t> values) {
  bool inRange = true;  // one branch for all of them
#pragma GCC unroll 8
  for (const std::int32_t v : values) inRange &= v >= -kMaxLineCoordinate && v <= kMaxLineCoordinate;
  return inRange;
}

// A line's quad and the (possibly adjusted) deltas its attribute planes use.
struct LineSetup {
  QuadEdges quad;
  float dx, dy, oneOverArea;
};

// pixelOffset: subtracted before snapping, kPixelCentreOffset with one sample, 0 with 4x MSAA.
// The two line setups fill `line` in place (no copy, no zeroing: see quadEdges) and return
// whether the line is drawn: false for a line of no length or one beyond kMaxLineCoordinate.
inline bool setupRectangularLine(Vec4 v1, Vec4 v2, float width, LineSetup& line,
                                 float pixelOffset = kPixelCentreOffset) {
  const float dx = v1.x - v2.x, dy = v1.y - v2.y;
  const float area = dx * dx + dy * dy;
  if (area == 0) return false;
  const float scale = (width * 0.5f) / std::sqrt(area);
  const std::int32_t tx = snapLineCoordinate(-dy * scale);
  const std::int32_t ty = snapLineCoordinate(dx * scale);
  const std::int32_t x1 = snapLineCoordinate(v1.x - pixelOffset), y1 = snapLineCoordinate(v1.y - pixelOffset);
  const std::int32_t x2 = snapLineCoordinate(v2.x - pixelOffset), y2 = snapLineCoordinate(v2.y - pixelOffset);
  if (!lineCoordinatesInRange({tx, ty, x1, y1, x2, y2})) return false;
  quadEdges({x1 - tx, x2 - tx, x2 + tx, x1 + tx}, {y1 - ty, y2 - ty, y2 + ty, y1 + ty}, line.quad);
  line.dx = dx;
  line.dy = dy;
  line.oneOverArea = 1.0f / area;
  return true;
}

// GL's diamond-exit line (VK_EXT_line_rasterization BRESENHAM), following lp_setup_line.c.
// pixelOffset as for setupRectangularLine (polygon mode line with 4x MSAA snaps without it).
inline bool setupBresenhamLine(Vec4 v1, Vec4 v2, float lineWidth, LineSetup& line, float pixelOffset = kPixelCentreOffset) {
  const auto positive = [](float x) { return x >= 0; };  // Mesa's sign()
  const auto fracf = [](float f) { return f - std::floor(f); };
  float dx = v1.x - v2.x, dy = v1.y - v2.y;
  const float area = dx * dx + dy * dy;
  if (area == 0) return false;
  line.dx = dx;
  line.dy = dy;
  line.oneOverArea = 1.0f / area;
  const std::int32_t fixedWidth = iroundHalfAway(std::max(1.0f, lineWidth)) * 256;
  float xOffset = 0, yOffset = 0, xOffsetEnd = 0, yOffsetEnd = 0;
  float x1diff = v1.x - std::floor(v1.x) - 0.5f, y1diff = v1.y - std::floor(v1.y) - 0.5f;
  float x2diff = v2.x - std::floor(v2.x) - 0.5f, y2diff = v2.y - std::floor(v2.y) - 0.5f;
  std::array<std::int32_t, 4> x, y;

  if (std::fabs(dx) >= std::fabs(dy)) {  // x-major
    const float dydx = dy / dx;
    if (y2diff == -0.5f && dy < 0) y2diff = 0.5f;
    bool drawStart, drawEnd;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) {
      drawStart = true;
    } else if (positive(x1diff) == positive(-dx)) {
      drawStart = false;
    } else if (positive(-y1diff) != positive(dy)) {
      drawStart = true;
    } else {
      const float yIntersect = fracf(v1.y) + x1diff * dydx;
      drawStart = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) {
      drawEnd = false;
    } else if (positive(x2diff) != positive(-dx)) {
      drawEnd = false;
    } else if (positive(-y2diff) == positive(dy)) {
      drawEnd = true;
    } else {
      const float yIntersect = fracf(v2.y) + x2diff * dydx;
      drawEnd = yIntersect < 1.0f && yIntersect > 0.0f;
    }
    const bool willDrawStart = positive(-x1diff) != positive(dx);
    const bool willDrawEnd = positive(x2diff) == positive(-dx) || x2diff == 0;
    line.dx *= 1 + dydx * dydx;  // the attribute planes use the wide-line formula
    line.dy = 0;
    if (dx < 0) {
      std::swap(v1, v2);
      dx = -dx;
      dy = -dy;
      if (willDrawStart != drawStart) xOffsetEnd = -x1diff - 0.5f, yOffsetEnd = xOffsetEnd * dydx;
      if (willDrawEnd != drawEnd) xOffset = -x2diff - 0.5f, yOffset = xOffset * dydx;
    } else {
      if (willDrawStart != drawStart) xOffset = -x1diff + 0.5f, yOffset = xOffset * dydx;
      if (willDrawEnd != drawEnd) xOffsetEnd = -x2diff + 0.5f, yOffsetEnd = xOffsetEnd * dydx;
    }
    const std::int32_t ax = snapLineCoordinate(v1.x + xOffset - pixelOffset);
    const std::int32_t bx = snapLineCoordinate(v2.x + xOffsetEnd - pixelOffset);
    const std::int32_t ay = snapLineCoordinate(v1.y + yOffset - pixelOffset);
    const std::int32_t by = snapLineCoordinate(v2.y + yOffsetEnd - pixelOffset);
    if (!lineCoordinatesInRange({ax, bx, ay, by, fixedWidth})) return false;
    x = {ax, bx, bx, ax};
    y = {ay - fixedWidth / 2, by - fixedWidth / 2, by + fixedWidth / 2, ay + fixedWidth / 2};
  } else {  // y-major
    const float dxdy = dx / dy;
    if (x2diff == -0.5f && dx < 0) x2diff = 0.5f;
    bool drawStart, drawEnd;
    if (std::fabs(x1diff) + std::fabs(y1diff) < 0.5f) {
      drawStart = true;
    } else if (positive(-y1diff) == positive(dy)) {
      drawStart = false;
    } else if (positive(x1diff) != positive(-dx)) {
      drawStart = true;
    } else {
      const float xIntersect = fracf(v1.x) + y1diff * dxdy;
      drawStart = xIntersect < 1.0f && xIntersect > 0.0f;
    }
    if (std::fabs(x2diff) + std::fabs(y2diff) < 0.5f) {
      drawEnd = false;
    } else if (positive(-y2diff) != positive(dy)) {
      drawEnd = false;
    } else if (positive(x2diff) == positive(-dx)) {
      drawEnd = true;
    } else {
      const float xIntersect = fracf(v2.x) + y2diff * dxdy;
      drawEnd = xIntersect < 1.0f && xIntersect >= 0.0f;
    }
    const bool willDrawStart = positive(y1diff) == positive(dy);
    const bool willDrawEnd = positive(-y2diff) == positive(dy) || y2diff == 0;
    line.dx = 0;
    line.dy *= 1 + dxdy * dxdy;
    if (dy > 0) {
      std::swap(v1, v2);
      dx = -dx;
      dy = -dy;
      if (willDrawStart != drawStart) yOffsetEnd = -y1diff + 0.5f, xOffsetEnd = yOffsetEnd * dxdy;
      if (willDrawEnd != drawEnd) yOffset = -y2diff + 0.5f, xOffset = yOffset * dxdy;
    } else {
      if (willDrawStart != drawStart) yOffset = -y1diff - 0.5f, xOffset = yOffset * dxdy;
      if (willDrawEnd != drawEnd) yOffsetEnd = -y2diff - 0.5f, xOffsetEnd = yOffsetEnd * dxdy;
    }
    const std::int32_t ax = snapLineCoordinate(v1.x + xOffset - pixelOffset);
    const std::int32_t bx = snapLineCoordinate(v2.x + xOffsetEnd - pixelOffset);
    const std::int32_t ay = snapLineCoordinate(v1.y + yOffset - pixelOffset);
    const std::int32_t by = snapLineCoordinate(v2.y + yOffsetEnd - pixelOffset);
    if (!lineCoordinatesInRange({ax, bx, ay, by, fixedWidth})) return false;
    x = {ax - fixedWidth / 2, bx - fixedWidth / 2, bx + fixedWidth / 2, ax + fixedWidth / 2};
    y = {ay, by, by, ay};
  }
  quadEdges(x, y, line.quad);
  return true;
}

// Attribute planes of a line from its first vertex v1 (lp_setup_line.c linear_coef):
// dadx = (da * dx) / area, a0 = a1 - (dadx * (x1 - 0.5) + dady * (y1 - 0.5)). Flat varyings are
// v1's, or v2's with provokingLast. planeOrigin: the 0.5 subtracted from x1 and y1 (lavapipe's
// pixel_offset, with 4x MSAA too; 0 puts the planes' origin at the window's, as triangles' MSAA
// planes have it).
template <int N>
inline TriangleInterpolants<N> setupLineInterpolants(const ShadedVertex<N>& v1, const ShadedVertex<N>& v2,
                                                     const LineSetup& line, const InterpolationSet<N>& interpolation,
                                                     bool provokingLast = false, float planeOrigin = kPixelCentreOffset) {
  const float x1 = v1.window.x - planeOrigin, y1 = v1.window.y - planeOrigin;
  const auto linear = [&](float a1, float a2) {
    const float da21 = a1 - a2;
    PlaneEquation p;
    p.dadx = da21 * line.dx * line.oneOverArea;
    p.dady = da21 * line.dy * line.oneOverArea;
    p.a0 = a1 - (p.dadx * x1 + p.dady * y1);
    return p;
  };
  TriangleInterpolants<N> t;
  t.depth = linear(v1.window.z, v2.window.z);
  t.oneOverW = linear(v1.window.w, v2.window.w);
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) {
    switch (interpolation[static_cast<std::size_t>(i)]) {
      case Interpolation::Perspective:
        t.varyings[i] = linear(v1.varyings[i] * v1.window.w, v2.varyings[i] * v2.window.w);
        break;
      case Interpolation::NoPerspective: t.varyings[i] = linear(v1.varyings[i], v2.varyings[i]); break;
      case Interpolation::Flat: t.varyings[i] = {(provokingLast ? v2 : v1).varyings[i], 0.0f, 0.0f}; break;
    }
  }
  return t;
}

// The pixels lavapipe's rasterizer walks for a 4x MSAA line (lp_setup_line.c, then
// lp_setup_bin_triangle), from the line's bounding box `box` (QuadEdges::bounds) and the draw
// region: a box inside one 64x64 tile is binned to that tile, a larger one to every tile the box
// cut to the region touches, and each binned tile is walked whole (the multisampled rasterizer
// has no 16x16 or 4x4 shortcut: lp_rast_triangle_ms_4_16 walks the tile). Inside the walk only
// the planes decide, so a sample left of or above the box is drawn iff its pixel is in a binned
// tile, that is unless the box starts on a tile's first column or row.
inline PixelRect msaaLineWalk(PixelRect box, const PixelRect& region) {
  constexpr int kTile = 64;
  box.x0 = std::max(box.x0, 0);  // bboxpos
  box.y0 = std::max(box.y0, 0);
  const unsigned crossed = static_cast<unsigned>((box.x0 ^ box.x1) | (box.y0 ^ box.y1));
  const PixelRect binned = std::bit_floor(crossed) < kTile ? box : intersect(box, region);
  return {binned.x0 / kTile * kTile, binned.y0 / kTile * kTile, binned.x1 / kTile * kTile + kTile - 1,
          binned.y1 / kTile * kTile + kTile - 1};
}

inline constexpr float kMaxPointSize = 255.0f;  // LP_MAX_POINT_WIDTH

// A point's square: covered iff x0 <= 256*px < x0 + width (likewise y), width >= 1 px.
// The corner and bounds are 64-bit: a point far outside the guard band snaps to INT32_MIN, and
// its corner would overflow an int (the bounds then lie outside any draw region).
// multisampleRegion: with 4x MSAA, the draw region the square is cut to (null: single sample,
// snapped with the half-pixel offset and left whole).
inline QuadEdges setupPoint(Vec4 window, float size, const PixelRect* multisampleRegion = nullptr) {
  if (size > kMaxPointSize) size = kMaxPointSize;
  const float offset = multisampleRegion != nullptr ? 0.0f : kPixelCentreOffset;
  const std::int32_t width = std::max<std::int32_t>(256, snapLineCoordinate(size));
  std::int64_t x0 = std::int64_t{snapLineCoordinate(window.x - offset)} - width / 2;
  std::int64_t y0 = std::int64_t{snapLineCoordinate(window.y - offset)} - width / 2;
  std::int64_t x1 = x0 + width, y1 = y0 + width;
  if (multisampleRegion != nullptr) {
    const PixelRect& r = *multisampleRegion;
    x0 = std::max<std::int64_t>(x0, std::int64_t{r.x0} << kSubpixelBits);
    y0 = std::max<std::int64_t>(y0, std::int64_t{r.y0} << kSubpixelBits);
    x1 = std::min<std::int64_t>(x1, (std::int64_t{r.x1} + 1) << kSubpixelBits);
    y1 = std::min<std::int64_t>(y1, (std::int64_t{r.y1} + 1) << kSubpixelBits);
  }
  QuadEdges q;
  q.edges[0] = {-x0 + 1, -256, 0};  // left, inclusive
  q.edges[1] = {x1, 256, 0};        // right, exclusive
  q.edges[2] = {-y0 + 1, 0, 256};   // top, inclusive
  q.edges[3] = {y1, 0, -256};       // bottom, exclusive
  const auto pixel = [](std::int64_t subpixels) { return static_cast<int>(subpixels >> kSubpixelBits); };
  q.bounds = {pixel(x0), pixel(y0), pixel(x1 + 255) - 1, pixel(y1 + 255) - 1};
  q.sampleBounds = q.bounds;
  return q;
}

// A point's attributes are constant: perspective ones pre-multiplied by 1/w (and divided by the
// constant interpolated 1/w per fragment), the others as they are.
template <int N>
inline TriangleInterpolants<N> setupPointInterpolants(const ShadedVertex<N>& v, const InterpolationSet<N>& interpolation) {
  TriangleInterpolants<N> t;
  t.depth = {v.window.z, 0.0f, 0.0f};
  t.oneOverW = {v.window.w, 0.0f, 0.0f};
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) {
    const bool perspective = interpolation[static_cast<std::size_t>(i)] == Interpolation::Perspective;
    t.varyings[i] = {perspective ? v.varyings[i] * v.window.w : v.varyings[i], 0.0f, 0.0f};
  }
  return t;
}

}  // namespace softraster::detail
