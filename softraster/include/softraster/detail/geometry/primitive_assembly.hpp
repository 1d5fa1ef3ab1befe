// Primitive assembly: turns a topology and its vertex indices into triangles in lavapipe's order
// and vertex batches.
//   - Order (provoking vertex first, Vulkan's default): list (3k, 3k+1, 3k+2); strip
//     (k, k+1, k+2), or (k, k+2, k+1) for odd k; fan (k+1, k+2, 0).
//   - Batches: Mesa's vsplit front end cuts a draw into segments of at most 1024 vertices
//     (lavapipe gives no index bounds): 341 triangles for lists, 1022 for strips and fans.
//     A batch with any vertex outside the frustum goes through Mesa's draw pipeline, whose cull
//     stage tests a float determinant before the fixed-point setup does its own.
// Lines: list (2k, 2k+1), strip (k, k+1); points: one per index. They have no cull stage, so
// their batches do not change the result.
#pragma once

#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/state.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace softraster::detail {

using TriangleIndices = std::array<std::uint32_t, 3>;

inline bool isTriangleTopology(Topology t) {
  return t == Topology::TriangleList || t == Topology::TriangleStrip || t == Topology::TriangleFan;
}

inline bool isLineTopology(Topology t) { return t == Topology::LineList || t == Topology::LineStrip; }

using LineIndices = std::array<std::uint32_t, 2>;

// The lines of a draw into `lines` (emptied first; its capacity is reused).
inline void assembleLines(Topology topology, std::span<const std::uint32_t> indices, std::vector<LineIndices>& lines) {
  lines.clear();
  if (topology == Topology::LineList) {
    for (std::size_t k = 0; k + 1 < indices.size(); k += 2) lines.push_back({indices[k], indices[k + 1]});
  } else if (topology == Topology::LineStrip) {
    for (std::size_t k = 0; k + 1 < indices.size(); ++k) lines.push_back({indices[k], indices[k + 1]});
  }
}

inline std::vector<LineIndices> assembleLines(Topology topology, std::span<const std::uint32_t> indices) {
  std::vector<LineIndices> lines;
  assembleLines(topology, indices, lines);
  return lines;
}

inline std::size_t trianglesPerBatch(Topology t) { return t == Topology::TriangleList ? 341 : 1022; }

// The triangles of a draw, as vertex numbers (`indices`: an indexed draw's, or 0..count-1), into
// `triangles` (emptied first; its capacity is reused).
inline void assembleTriangles(Topology topology, std::span<const std::uint32_t> indices,
                              std::vector<TriangleIndices>& triangles) {
  triangles.clear();
  const std::size_t n = indices.size();
  if (n < 3) return;
  triangles.reserve(topology == Topology::TriangleList ? n / 3 : n - 2);
  switch (topology) {
    case Topology::TriangleList:
      for (std::size_t k = 0; k + 2 < n; k += 3) triangles.push_back({indices[k], indices[k + 1], indices[k + 2]});
      break;
    case Topology::TriangleStrip:
      for (std::size_t k = 0; k + 2 < n; ++k) {
        if (k % 2 == 0) {
          triangles.push_back({indices[k], indices[k + 1], indices[k + 2]});
        } else {
          triangles.push_back({indices[k], indices[k + 2], indices[k + 1]});
        }
      }
      break;
    case Topology::TriangleFan:
      for (std::size_t k = 0; k + 2 < n; ++k) triangles.push_back({indices[k + 1], indices[k + 2], indices[0]});
      break;
    default:
      break;
  }
}

inline std::vector<TriangleIndices> assembleTriangles(Topology topology, std::span<const std::uint32_t> indices) {
  std::vector<TriangleIndices> triangles;
  assembleTriangles(topology, indices, triangles);
  return triangles;
}

template <int N>
inline bool batchNeedsClipping(std::span<const TriangleIndices> batch, const std::vector<ShadedVertex<N>>& vertices) {
  std::uint32_t mask = 0;
  for (const TriangleIndices& t : batch) mask |= vertices[t[0]].clipMask | vertices[t[1]].clipMask | vertices[t[2]].clipMask;
  return mask != 0;
}

}  // namespace softraster::detail
