// Rasterization (coverage): walks the pixels of a triangle's bounding box clipped to the draw
// region and calls `covered(px, py)` for each pixel centre strictly inside all three edge
// functions (the +1 of the top-left rule is already folded into the constants). Edge values
// step incrementally in 64-bit integers, so the result is exact for any triangle setup accepted.
// Deliberately a plain scanline walk of the box: the tiled/SIMD fast path comes later and must
// produce the same set of pixels.
#pragma once

#include <softraster/detail/triangle_setup.hpp>

#include <algorithm>
#include <cstdint>

namespace softraster::detail {

inline PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
}

template <class Covered>
inline void rasterizeTriangle(const TriangleEdges& tri, const PixelRect& region, Covered&& covered) {
  const PixelRect box = intersect(tri.bounds, region);
  if (box.empty()) return;
  const EdgeFunction& e0 = tri.edges[0];
  const EdgeFunction& e1 = tri.edges[1];
  const EdgeFunction& e2 = tri.edges[2];
  std::int64_t row0 = e0.c + e0.dcdy * box.y0 - e0.dcdx * box.x0;
  std::int64_t row1 = e1.c + e1.dcdy * box.y0 - e1.dcdx * box.x0;
  std::int64_t row2 = e2.c + e2.dcdy * box.y0 - e2.dcdx * box.x0;
  for (int py = box.y0; py <= box.y1; ++py) {
    std::int64_t c0 = row0, c1 = row1, c2 = row2;
    for (int px = box.x0; px <= box.x1; ++px) {
      if ((c0 > 0) & (c1 > 0) & (c2 > 0)) covered(px, py);
      c0 -= e0.dcdx;
      c1 -= e1.dcdx;
      c2 -= e2.dcdx;
    }
    row0 += e0.dcdy;
    row1 += e1.dcdy;
    row2 += e2.dcdy;
  }
}

}  // namespace softraster::detail
