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

// The most triangles a batch holds, of any topology.
inline constexpr std::size_t kMaxTrianglesPerBatch = 1022;

inline std::size_t trianglesPerBatch(Topology t) {
  switch (t) {
    case Topology::TriangleList: return 341;
    case Topology::TriangleListWithAdjacency: return 170;
    case Topology::TriangleStripWithAdjacency: return 510;
    default: return kMaxTrianglesPerBatch;
  }
}

// How many triangles `n` indices of a triangle topology make (0 for any other topology).
inline std::size_t triangleCount(Topology topology, std::size_t n) {
  switch (topology) {
    case Topology::TriangleList: return n / 3;
    case Topology::TriangleStrip:
    case Topology::TriangleFan: return n < 3 ? 0 : n - 2;
    case Topology::TriangleListWithAdjacency: return n / 6;
    case Topology::TriangleStripWithAdjacency: return n < 6 ? 0 : (n - 6) / 2 + 1;
    default: return 0;
  }
}

// Triangles [first, first + count) of a draw (count no more than triangleCount leaves), as vertex
// numbers (`indices`: an indexed draw's, or 0..count-1), into out[0, count), in Mesa's order for
// the provoking vertex mode (provokingLast: VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT). Triangle k
// depends on k alone, so a draw's ranges are assembled apart, each by the worker that draws it.
inline void assembleTriangleRange(Topology topology, std::span<const std::uint32_t> indices, std::size_t first,
                                  std::size_t count, TriangleIndices* out, bool provokingLast = false) {
  const auto at = [&](std::size_t k) { return indices[k]; };
  const std::size_t end = first + count;
  switch (topology) {
    case Topology::TriangleList:
      for (std::size_t t = first; t < end; ++t) *out++ = {at(3 * t), at(3 * t + 1), at(3 * t + 2)};
      break;
    case Topology::TriangleStrip:
      for (std::size_t k = first; k < end; ++k) {
        if (k % 2 == 0) {
          *out++ = {at(k), at(k + 1), at(k + 2)};
        } else if (provokingLast) {
          *out++ = {at(k + 1), at(k), at(k + 2)};
        } else {
          *out++ = {at(k), at(k + 2), at(k + 1)};
        }
      }
      break;
    case Topology::TriangleFan:
      for (std::size_t k = first; k < end; ++k) {
        if (provokingLast) {
          *out++ = {at(0), at(k + 1), at(k + 2)};
        } else {
          *out++ = {at(k + 1), at(k + 2), at(0)};
        }
      }
      break;
    case Topology::TriangleListWithAdjacency:
      for (std::size_t t = first; t < end; ++t) *out++ = {at(6 * t), at(6 * t + 2), at(6 * t + 4)};
      break;
    case Topology::TriangleStripWithAdjacency:
      for (std::size_t t = first; t < end; ++t) {  // triangle t on vertices 2t, 2t+2, 2t+4
        const std::size_t k = 2 * t;
        if (t % 2 == 0) {
          *out++ = {at(k), at(k + 2), at(k + 4)};
        } else if (provokingLast) {
          *out++ = {at(k + 2), at(k), at(k + 4)};
        } else {
          *out++ = {at(k), at(k + 4), at(k + 2)};
        }
      }
      break;
    default:
      break;
  }
}

// The adjacency topologies' batches also fetch, and clip-test, the adjacent vertices of their
// triangles [first, first + count): is any of those outside the frustum?
// `vertices`: the shaded vertices, or anything else with their clipMask (exact/draw.hpp's compact
// copy of each vertex's snapped position and clip mask).
template <class Vertex>
inline bool adjacencyNeedsClipping(Topology topology, std::span<const std::uint32_t> indices, std::size_t first,
                                   std::size_t count, const std::vector<Vertex>& vertices) {
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

template <class Vertex>
inline bool batchNeedsClipping(std::span<const TriangleIndices> batch, const std::vector<Vertex>& vertices) {
  std::uint32_t mask = 0;
  for (const TriangleIndices& t : batch) mask |= vertices[t[0]].clipMask | vertices[t[1]].clipMask | vertices[t[2]].clipMask;
  return mask != 0;
}

}  // namespace softraster::detail
