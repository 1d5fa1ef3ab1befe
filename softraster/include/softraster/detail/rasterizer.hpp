// Rasterization (coverage): walks the pixels of a primitive's bounding box clipped to the draw
// region and calls `covered(px, py)` for each pixel centre strictly inside all its edge
// functions (3 for triangles, 4 for line and point quads; the +1 of the fill rule is already
// folded into the constants). Edge values
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

// Calls covered(px, py) for each pixel of bounds ∩ region inside all N edge functions.
template <int N, class Covered>
inline void rasterizeEdges(const EdgeFunction (&edges)[N], const PixelRect& bounds, const PixelRect& region,
                           Covered&& covered) {
  const PixelRect box = intersect(bounds, region);
  if (box.empty()) return;
  std::int64_t row[N];
  for (int i = 0; i < N; ++i) row[i] = edges[i].c + edges[i].dcdy * box.y0 - edges[i].dcdx * box.x0;
  for (int py = box.y0; py <= box.y1; ++py) {
    std::int64_t c[N];
    for (int i = 0; i < N; ++i) c[i] = row[i];
    for (int px = box.x0; px <= box.x1; ++px) {
      bool inside = true;
      for (int i = 0; i < N; ++i) inside &= c[i] > 0;
      if (inside) covered(px, py);
      for (int i = 0; i < N; ++i) c[i] -= edges[i].dcdx;
    }
    for (int i = 0; i < N; ++i) row[i] += edges[i].dcdy;
  }
}

template <class Covered>
inline void rasterizeTriangle(const TriangleEdges& tri, const PixelRect& region, Covered&& covered) {
  rasterizeEdges(tri.edges, tri.bounds, region, covered);
}

}  // namespace softraster::detail
