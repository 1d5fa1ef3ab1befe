// Polygon modes LINE and POINT: Mesa's "unfilled" stage (draw_pipe_unfilled.c), which turns one
// clipped and culled triangle into its edges as lines or its vertices as points.
//   - An edge or vertex is drawn when the triangle header's edge flag for it is set and its first
//     vertex's own edge flag is set: edges that clipping created along a frustum plane are not.
//   - A clipped polygon is emitted as a fan from its vertex 0 (emit_poly): the first triangle
//     carries the polygon's first edge, every triangle its middle edge, the last one the closing
//     edge.
//   - Flat varyings of all three vertices are the provoking vertex's (the first, or the third
//     with provoking vertex last, where emit_poly's fan is (i-1, i, 0) and its edge flags rotate).
// Deliberately absent: drawing the lines and points; the caller hands in how (exact/draw.hpp).
#pragma once

#include <softraster/detail/geometry/clipping.hpp>
#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <cstddef>

namespace softraster::detail {

// Edge flags (bit i: the edge from vertex i to vertex i+1) of fan triangle (0, i-1, i) of a
// clipped polygon, i in [2, count).
// With provokingLast the triangle is (i-1, i, 0): the same edges, named from its own vertex 0.
template <int N>
unsigned fanTriangleEdgeFlags(const ClippedPolygon<N>& polygon, int i, bool provokingLast = false) {
  const bool first = i == 2 && polygon.edges[0];
  const bool middle = polygon.edges[static_cast<std::size_t>(i - 1)];
  const bool last = i == polygon.count - 1 && polygon.edges[static_cast<std::size_t>(i)];
  if (provokingLast) return (middle ? 1u : 0u) | (last ? 2u : 0u) | (first ? 4u : 0u);
  return (first ? 1u : 0u) | (middle ? 2u : 0u) | (last ? 4u : 0u);
}

// Draws triangle (a, b, c) in polygon mode `mode` (Line or Point) with `edges` its header's edge
// flags: line(v, w) for each edge drawn, point(v) for each vertex drawn, in Mesa's order.
template <int N, class DrawLine, class DrawPoint>
void drawUnfilledTriangle(PolygonMode mode, const ShadedVertex<N>& a, const ShadedVertex<N>& b,
                          const ShadedVertex<N>& c, unsigned edges, const InterpolationSet<N>& interpolation,
                          DrawLine&& line, DrawPoint&& point, bool provokingLast = false) {
  ShadedVertex<N> v[3] = {a, b, c};
  const ShadedVertex<N>& provoking = provokingLast ? c : a;
  for (int i = 0; i < N; ++i) {
    if (interpolation[static_cast<std::size_t>(i)] == Interpolation::Flat) {
      for (ShadedVertex<N>& w : v) w.varyings[i] = provoking.varyings[i];
    }
  }
  if (mode == PolygonMode::Line) {
    if ((edges & 4u) && v[2].edgeFlag) line(v[2], v[0]);
    if ((edges & 1u) && v[0].edgeFlag) line(v[0], v[1]);
    if ((edges & 2u) && v[1].edgeFlag) line(v[1], v[2]);
  } else {
    for (int i = 0; i < 3; ++i) {
      if ((edges & (1u << i)) && v[i].edgeFlag) point(v[i]);
    }
  }
}

}  // namespace softraster::detail
