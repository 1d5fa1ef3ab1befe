// Primitive assembly: splits an indexed triangle list into the vertex batches lavapipe's draw
// module uses (vsplit segments of 1023 indices, no index bounds from the Vulkan driver), and says
// whether a batch needed clipping. That matters beyond clipping itself: every triangle of a
// batch with any vertex outside the frustum goes through Mesa's draw pipeline, whose cull stage
// tests a float determinant before the fixed-point setup does its own.
// Deliberately only triangle lists; strips, fans, lines and points come with their scenes.
#pragma once

#include <softraster/detail/vertex_processing.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace softraster::detail {

inline constexpr std::size_t kBatchIndices = 1023;  // 1024-entry segment trimmed to whole triangles

template <int N>
inline bool batchNeedsClipping(std::span<const std::uint32_t> batch, const std::vector<ShadedVertex<N>>& vertices) {
  std::uint32_t mask = 0;
  for (std::uint32_t index : batch) mask |= vertices[index].clipMask;
  return mask != 0;
}

}  // namespace softraster::detail
