// The largest index of an indexed draw, which validation compares with the vertex count before
// any work (pipeline.hpp): one pass over the indices, eight at a time with AVX2 where the CPU has
// it (src/largest_index.cpp). A million-triangle mesh has three million indices, and this pass
// runs on the calling thread before the draw is shared out, so its speed is the draw's.
// Deliberately only the largest value: which index is the offending one is found (by a plain
// search) only when validation fails.
#pragma once

#include <cstdint>
#include <span>

namespace softraster::detail {

// The largest of `indices` (0 when there are none); with `restart`, the primitive restart index
// 0xFFFFFFFF counts as 0.
std::uint32_t largestIndex(std::span<const std::uint32_t> indices, bool restart);

}  // namespace softraster::detail
