// Polygon modes LINE and POINT: Mesa's "unfilled" stage (draw_pipe_unfilled.c), which turns one
// clipped and culled triangle into its edges as lines or its vertices as points.
//   - An edge or vertex is drawn when the triangle header's edge flag for it is set and its first
//     vertex's own edge flag is set: edges that clipping created along a frustum plane are not.
//   - A clipped polygon is emitted as a fan from its vertex 0 (emit_poly): the first triangle
//     carries the polygon's first edge, every triangle its middle edge, the last one the closing
//     edge.
//   - Flat varyings of all three vertices are the provoking vertex's.
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
template <int N>
unsigned fanTriangleEdgeFlags(const ClippedPolygon<N>& polygon, int i) {
  unsigned edges = (i == 2 && polygon.edges[0]) ? 1u : 0u;
  if (polygon.edges[static_cast<std::size_t>(i - 1)]) edges |= 2u;
  if (i == polygon.count - 1 && polygon.edges[static_cast<std::size_t>(i)]) edges |= 4u;
  return edges;
}

// Draws triangle (a, b, c) in polygon mode `mode` (Line or Point) with `edges` its header's edge
// flags: line(v, w) for each edge drawn, point(v) for each vertex drawn, in Mesa's order.
template <int N, class DrawLine, class DrawPoint>
void drawUnfilledTriangle(PolygonMode mode, const ShadedVertex<N>& a, const ShadedVertex<N>& b,
                          const ShadedVertex<N>& c, unsigned edges, const InterpolationSet<N>& interpolation,
                          DrawLine&& line, DrawPoint&& point) {
  ShadedVertex<N> v[3] = {a, b, c};
  for (int i = 0; i < N; ++i) {
    if (interpolation[static_cast<std::size_t>(i)] == Interpolation::Flat) v[1].varyings[i] = v[2].varyings[i] = a.varyings[i];
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
