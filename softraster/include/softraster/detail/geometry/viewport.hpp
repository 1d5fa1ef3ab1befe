// The window a draw lands in: the viewport a state names (or the whole framebuffer), and the
// pixel rectangle a draw may touch, as lavapipe computes them.
// With 4x MSAA, also the extra samples lavapipe's scissor planes let through (MsaaRegionEdges).
// Deliberately absent: multiple viewports, viewport swizzles.
#pragma once

#include <softraster/options.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace softraster::detail {

struct PixelRect {  // inclusive bounds
  int x0, y0, x1, y1;
  bool empty() const { return x0 > x1 || y0 > y1; }
};

inline PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

// The viewport the state names, or the whole framebuffer (width x height) when its size is 0.
inline Viewport resolveViewport(const Viewport& vp, std::uint32_t width, std::uint32_t height) {
  if (vp.width != 0 && vp.height != 0) return vp;
  Viewport full = vp;
  full.x = 0;
  full.y = 0;
  full.width = static_cast<float>(width);
  full.height = static_cast<float>(height);
  return full;
}

// Pixels a draw may touch (lavapipe's draw region): framebuffer ∩ scissor ∩ the viewport
// rectangle [(int)(x0 + 0.499), (int)(2*sx + x0 - 0.501)] (lavapipe sets point_tri_clip, which
// scissors every primitive to the viewport), computed as lp_setup.c does from the viewport's
// scale s and translate t: x0 = tx - sx, y0 = ty - |sy| (a negative height flips y, so the
// rectangle spans y + height .. y).
inline PixelRect drawRegion(const Scissor& scissor, const Viewport& vp, std::uint32_t width, std::uint32_t height) {
  PixelRect region{0, 0, static_cast<int>(width) - 1, static_cast<int>(height) - 1};
  if (scissor.width != 0 && scissor.height != 0) {  // in 64 bits: x + width may not fit in an int
    const auto lastOf = [](std::int32_t start, std::uint32_t size, int last) {
      return static_cast<int>(std::min<std::int64_t>(std::int64_t{start} + size - 1, last));
    };
    region = intersect(region, {scissor.x, scissor.y, lastOf(scissor.x, scissor.width, region.x1),
                                lastOf(scissor.y, scissor.height, region.y1)});
  }
  const float halfWidth = 0.5f * vp.width, halfHeight = std::fabs(0.5f * vp.height);
  const float x0 = (halfWidth + vp.x) - halfWidth;
  const float y0 = (0.5f * vp.height + vp.y) - halfHeight;
  return intersect(region, {static_cast<int>(x0 + 0.499f), static_cast<int>(y0 + 0.499f),
                            static_cast<int>(halfWidth * 2.0f + x0 - 0.501f),
                            static_cast<int>(halfHeight * 2.0f + y0 - 0.501f)});
}

// 4x MSAA: lavapipe bounds a triangle that crosses the draw region's edges by four scissor
// planes (lp_setup_add_scissor_planes), and with multisampling their constants carry +127/256:
// the left and top planes then lie 127/256 px outside the region. So in the column left of the
// region only the samples with an x offset above 127/256 pass (samples 1 and 3), in the row above
// only those with a y offset above it (2 and 3), in their corner sample 3; the right and bottom
// planes cut exactly. Lavapipe rasterizes only the 64x64 tiles the region touches, so a column or
// row on the other side of a tile boundary (x0 or y0 a multiple of 64) is never visited, and a
// triangle whose bounds miss the region itself is culled before the planes are made. As the draw
// region includes the viewport rectangle, this covers scissors and viewports alike. The Vulkan
// spec scissors whole fragments (a lavapipe deviation for the scissor; for a viewport the extra
// samples are inside the clipped primitive, as the spec has it). With Deviations::Spec the
// scissor is tested per fragment: no partial column or row where the scissor makes that edge.
struct MsaaRegionEdges {
  static constexpr int kLavapipeTileSize = 64;
  static constexpr unsigned kRightHalfSamples = 0b1010;   // x offsets 0.875 and 0.625
  static constexpr unsigned kBottomHalfSamples = 0b1100;  // y offsets 0.625 and 0.875

  PixelRect drawRegion{0, 0, -1, -1};  // the region itself: a triangle missing it is culled
  PixelRect rasterRegion{0, 0, -1, -1};  // the region with the partial column and row
  int partialColumn = INT_MIN, partialRow = INT_MIN;

  // Which of the region's left and top planes a primitive carries: triangles and points always
  // (their bounding boxes are conservative, so one reaching the column or row has the plane);
  // a line only when its bounding box starts left of or above the region (msaaLineWalk).
  static constexpr unsigned kLeftPlane = 1, kTopPlane = 2, kBothPlanes = kLeftPlane | kTopPlane;

  // The samples (bit s: sample s) of pixel (px, py) the planes let through.
  unsigned allowedSamples(int px, int py, unsigned planes = kBothPlanes) const {
    unsigned allowed = 0xfu;
    if (px == partialColumn && (planes & kLeftPlane)) allowed &= kRightHalfSamples;
    if (py == partialRow && (planes & kTopPlane)) allowed &= kBottomHalfSamples;
    return allowed;
  }
};

// `scissor` and `deviations`: with Deviations::Spec, a left or top edge the scissor makes (the
// scissor set and not reaching past it) gets no partial column or row.
inline MsaaRegionEdges msaaRegionEdges(const PixelRect& region, const Scissor& scissor = {},
                                       Deviations deviations = Deviations::Driver) {
  MsaaRegionEdges e;
  e.drawRegion = e.rasterRegion = region;
  if (region.empty()) return e;
  const bool specScissor = deviations == Deviations::Spec && scissor.width != 0 && scissor.height != 0;
  const bool scissorLeft = specScissor && scissor.x >= region.x0;
  const bool scissorTop = specScissor && scissor.y >= region.y0;
  if (region.x0 % MsaaRegionEdges::kLavapipeTileSize != 0 && !scissorLeft) e.partialColumn = --e.rasterRegion.x0;
  if (region.y0 % MsaaRegionEdges::kLavapipeTileSize != 0 && !scissorTop) e.partialRow = --e.rasterRegion.y0;
  return e;
}

}  // namespace softraster::detail
