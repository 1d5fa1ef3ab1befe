// Rasterization (coverage): walks the pixels of a primitive's bounding box clipped to the draw
// region and calls `covered(px, py)` for each pixel centre strictly inside all its edge
// functions (3 for triangles, 4 for line and point quads; the +1 of the fill rule is already
// folded into the constants). Edge values
// step incrementally in 64-bit integers, so the result is exact for any triangle setup accepted.
// Deliberately a plain scanline walk of the box: the tiled/SIMD fast path comes later and must
// produce the same set of pixels.
#pragma once

#include <softraster/detail/exact/triangle_setup.hpp>

#include <algorithm>
#include <cstdint>

namespace softraster::detail {

// Calls visit(px, py, values) for every pixel of bounds ∩ region with the N edge values at the
// pixel, stepped incrementally.
template <int N, class Visit>
inline void rasterizeEdgesAt(const EdgeFunction (&edges)[N], const PixelRect& bounds, const PixelRect& region,
                             Visit&& visit) {
  const PixelRect box = intersect(bounds, region);
  if (box.empty()) return;
  std::int64_t row[N];
  for (int i = 0; i < N; ++i) row[i] = edges[i].c + edges[i].dcdy * box.y0 - edges[i].dcdx * box.x0;
  for (int py = box.y0; py <= box.y1; ++py) {
    std::int64_t c[N];
    for (int i = 0; i < N; ++i) c[i] = row[i];
    for (int px = box.x0; px <= box.x1; ++px) {
      visit(px, py, c);
      for (int i = 0; i < N; ++i) c[i] -= edges[i].dcdx;
    }
    for (int i = 0; i < N; ++i) row[i] += edges[i].dcdy;
  }
}

// Calls covered(px, py) for each pixel of bounds ∩ region inside all N edge functions.
template <int N, class Covered>
inline void rasterizeEdges(const EdgeFunction (&edges)[N], const PixelRect& bounds, const PixelRect& region,
                           Covered&& covered) {
  rasterizeEdgesAt(edges, bounds, region, [&](int px, int py, const std::int64_t (&value)[N]) {
    bool inside = true;
    for (int i = 0; i < N; ++i) inside &= value[i] > 0;
    if (inside) covered(px, py);
  });
}

// 4x MSAA: calls covered(px, py, mask) for each pixel of bounds ∩ region with at least one
// sample inside all N edge functions; bit s of mask is sample s (kFixedSamplePositions4x). The
// edge value at a sample is the value at the pixel corner plus sy*DX - sx*DY, as lp_rast does.
template <int N, class Covered>
inline void rasterizeEdgesSampled(const EdgeFunction (&edges)[N], const PixelRect& bounds, const PixelRect& region,
                                  Covered&& covered) {
  std::int64_t sampleOffset[N][4];
  for (int i = 0; i < N; ++i) {
    for (int s = 0; s < 4; ++s) {
      sampleOffset[i][s] = (kFixedSamplePositions4x[s][1] * edges[i].dcdy - kFixedSamplePositions4x[s][0] * edges[i].dcdx) >>
                           kSubpixelBits;
    }
  }
  rasterizeEdgesAt(edges, bounds, region, [&](int px, int py, const std::int64_t (&value)[N]) {
    unsigned mask = 0;
    for (int s = 0; s < 4; ++s) {
      bool inside = true;
      for (int i = 0; i < N; ++i) inside &= value[i] + sampleOffset[i][s] > 0;
      mask |= inside ? 1u << s : 0u;
    }
    if (mask != 0) covered(px, py, mask);
  });
}

template <class Covered>
inline void rasterizeTriangle(const TriangleEdges& tri, const PixelRect& region, Covered&& covered) {
  rasterizeEdges(tri.edges, tri.bounds, region, covered);
}

}  // namespace softraster::detail
