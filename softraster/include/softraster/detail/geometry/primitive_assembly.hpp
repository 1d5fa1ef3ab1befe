// Primitive assembly: turns a topology and its vertex indices into triangles in lavapipe's order
// (Mesa's draw_decompose_tmp.h) and vertex batches.
//   - Order, provoking vertex first (Vulkan's default): list (3k, 3k+1, 3k+2); strip
//     (k, k+1, k+2), or (k, k+2, k+1) for odd k; fan (k+1, k+2, 0).
//     Provoking vertex last (VK_EXT_provoking_vertex): strip (k, k+1, k+2), or (k+1, k, k+2) for
//     odd k; fan (0, k+1, k+2); lists unchanged. The provoking vertex is then the third.
//   - Adjacency topologies without a geometry shader: the adjacent vertices are skipped. Triangle
//     list with adjacency (6k, 6k+2, 6k+4); triangle strip with adjacency, triangle k on vertices
//     2k, 2k+2, 2k+4, for odd k (2k, 2k+4, 2k+2) first / (2k+2, 2k, 2k+4) last; line list with
//     adjacency (4k+1, 4k+2); line strip with adjacency (k, k+1) for k in [1, n-3].
//   - Batches: Mesa's vsplit front end cuts a draw into segments of at most 1024 vertices
//     (lavapipe gives no index bounds): 341 triangles for lists, 1022 for strips and fans, 170
//     for lists with adjacency, 510 for strips with adjacency.
//     A batch with any vertex outside the frustum goes through Mesa's draw pipeline, whose cull
//     stage tests a float determinant before the fixed-point setup does its own.
//   - Primitive restart (draw_pt.c's prim_restart_loop): the index 0xFFFFFFFF ends a run; each
//     run is assembled and batched as a draw of its own (restartRuns).
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
  return t == Topology::TriangleList || t == Topology::TriangleStrip || t == Topology::TriangleFan ||
         t == Topology::TriangleListWithAdjacency || t == Topology::TriangleStripWithAdjacency;
}

inline bool isLineTopology(Topology t) {
  return t == Topology::LineList || t == Topology::LineStrip || t == Topology::LineListWithAdjacency ||
         t == Topology::LineStripWithAdjacency;
}

// The topologies primitive restart applies to without primitiveTopologyListRestart.
inline bool isStripOrFanTopology(Topology t) {
  return t == Topology::LineStrip || t == Topology::TriangleStrip || t == Topology::TriangleFan ||
         t == Topology::LineStripWithAdjacency || t == Topology::TriangleStripWithAdjacency;
}

// Calls run(span) for each run of indices between restart indices (the whole span when restart
// is off), skipping empty runs, as Mesa's prim_restart_loop draws them.
template <class Run>
inline void forEachRestartRun(std::span<const std::uint32_t> indices, bool restart, Run&& run) {
  if (!restart) {
    run(indices);
    return;
  }
  std::size_t start = 0;
  for (std::size_t i = 0; i <= indices.size(); ++i) {
    if (i == indices.size() || indices[i] == kPrimitiveRestartIndex) {
      if (i > start) run(indices.subspan(start, i - start));
      start = i + 1;
    }
  }
}

using LineIndices = std::array<std::uint32_t, 2>;

// The lines of a draw into `lines` (emptied first; its capacity is reused).
inline void assembleLines(Topology topology, std::span<const std::uint32_t> indices, std::vector<LineIndices>& lines) {
  lines.clear();
  const std::size_t n = indices.size();
  if (topology == Topology::LineList) {
    for (std::size_t k = 0; k + 1 < n; k += 2) lines.push_back({indices[k], indices[k + 1]});
  } else if (topology == Topology::LineStrip) {
    for (std::size_t k = 0; k + 1 < n; ++k) lines.push_back({indices[k], indices[k + 1]});
  } else if (topology == Topology::LineListWithAdjacency) {
    for (std::size_t k = 0; k + 3 < n; k += 4) lines.push_back({indices[k + 1], indices[k + 2]});
  } else if (topology == Topology::LineStripWithAdjacency) {
    for (std::size_t k = 1; k + 2 < n; ++k) lines.push_back({indices[k], indices[k + 1]});
  }
}

inline std::vector<LineIndices> assembleLines(Topology topology, std::span<const std::uint32_t> indices) {
  std::vector<LineIndices> lines;
  assembleLines(topology, indices, lines);
  return lines;
}

inline std::size_t trianglesPerBatch(Topology t) {
  switch (t) {
    case Topology::TriangleList: return 341;
    case Topology::TriangleListWithAdjacency: return 170;
    case Topology::TriangleStripWithAdjacency: return 510;
    default: return 1022;
  }
}

// The triangles of a draw, as vertex numbers (`indices`: an indexed draw's, or 0..count-1), into
// `triangles` (emptied first; its capacity is reused), in Mesa's order for the provoking vertex
// mode (provokingLast: VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT).
inline void assembleTriangles(Topology topology, std::span<const std::uint32_t> indices,
                              std::vector<TriangleIndices>& triangles, bool provokingLast = false) {
  triangles.clear();
  const std::size_t n = indices.size();
  if (n < 3) return;
  triangles.reserve(topology == Topology::TriangleList ? n / 3 : n - 2);
  const auto at = [&](std::size_t k) { return indices[k]; };
  switch (topology) {
    case Topology::TriangleList:
      for (std::size_t k = 0; k + 2 < n; k += 3) triangles.push_back({at(k), at(k + 1), at(k + 2)});
      break;
    case Topology::TriangleStrip:
      for (std::size_t k = 0; k + 2 < n; ++k) {
        if (k % 2 == 0) {
          triangles.push_back({at(k), at(k + 1), at(k + 2)});
        } else if (provokingLast) {
          triangles.push_back({at(k + 1), at(k), at(k + 2)});
        } else {
          triangles.push_back({at(k), at(k + 2), at(k + 1)});
        }
      }
      break;
    case Topology::TriangleFan:
      for (std::size_t k = 0; k + 2 < n; ++k) {
        if (provokingLast) {
          triangles.push_back({at(0), at(k + 1), at(k + 2)});
        } else {
          triangles.push_back({at(k + 1), at(k + 2), at(0)});
        }
      }
      break;
    case Topology::TriangleListWithAdjacency:
      for (std::size_t k = 0; k + 5 < n; k += 6) triangles.push_back({at(k), at(k + 2), at(k + 4)});
      break;
    case Topology::TriangleStripWithAdjacency:
      for (std::size_t k = 0; k + 5 < n; k += 2) {  // triangle k/2 on vertices k, k+2, k+4
        if ((k & 2) == 0) {
          triangles.push_back({at(k), at(k + 2), at(k + 4)});
        } else if (provokingLast) {
          triangles.push_back({at(k + 2), at(k), at(k + 4)});
        } else {
          triangles.push_back({at(k), at(k + 4), at(k + 2)});
        }
      }
      break;
    default:
      break;
  }
}

inline std::vector<TriangleIndices> assembleTriangles(Topology topology, std::span<const std::uint32_t> indices,
                                                      bool provokingLast = false) {
  std::vector<TriangleIndices> triangles;
  assembleTriangles(topology, indices, triangles, provokingLast);
  return triangles;
}

// The adjacency topologies' batches also fetch, and clip-test, the adjacent vertices of their
// triangles [first, first + count): is any of those outside the frustum?
template <int N>
inline bool adjacencyNeedsClipping(Topology topology, std::span<const std::uint32_t> indices, std::size_t first,
                                   std::size_t count, const std::vector<ShadedVertex<N>>& vertices) {
  std::size_t begin = 0, end = 0;
  if (topology == Topology::TriangleListWithAdjacency) {
    begin = 6 * first;
    end = 6 * (first + count);
  } else if (topology == Topology::TriangleStripWithAdjacency && count > 0) {
    begin = 2 * first;
    end = 2 * (first + count - 1) + 6;
  }
  std::uint32_t mask = 0;
  for (std::size_t i = begin; i < end && i < indices.size(); ++i) mask |= vertices[indices[i]].clipMask;
  return mask != 0;
}

template <int N>
inline bool batchNeedsClipping(std::span<const TriangleIndices> batch, const std::vector<ShadedVertex<N>>& vertices) {
  std::uint32_t mask = 0;
  for (const TriangleIndices& t : batch) mask |= vertices[t[0]].clipMask | vertices[t[1]].clipMask | vertices[t[2]].clipMask;
  return mask != 0;
}

}  // namespace softraster::detail
