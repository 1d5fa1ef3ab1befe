// The window a draw lands in: the viewport a state names (or the whole framebuffer), and the
// pixel rectangle a draw may touch, as lavapipe computes them.
// Deliberately absent: multiple viewports, viewport swizzles.
#pragma once

#include <softraster/state.hpp>

#include <algorithm>
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
// rectangle [(int)(x + 0.499), (int)(x + width - 0.501)] (lavapipe sets point_tri_clip, which
// scissors every primitive to the viewport).
inline PixelRect drawRegion(const Scissor& scissor, const Viewport& vp, std::uint32_t width, std::uint32_t height) {
  PixelRect region{0, 0, static_cast<int>(width) - 1, static_cast<int>(height) - 1};
  if (scissor.width != 0 && scissor.height != 0) {  // in 64 bits: x + width may not fit in an int
    const auto lastOf = [](std::int32_t start, std::uint32_t size, int last) {
      return static_cast<int>(std::min<std::int64_t>(std::int64_t{start} + size - 1, last));
    };
    region = intersect(region, {scissor.x, scissor.y, lastOf(scissor.x, scissor.width, region.x1),
                                lastOf(scissor.y, scissor.height, region.y1)});
  }
  const float top = std::fmin(vp.y, vp.y + vp.height), bottom = std::fmax(vp.y, vp.y + vp.height);
  return intersect(region, {static_cast<int>(vp.x + 0.499f), static_cast<int>(top + 0.499f),
                            static_cast<int>(vp.x + vp.width - 0.501f), static_cast<int>(bottom - 0.501f)});
}

}  // namespace softraster::detail
