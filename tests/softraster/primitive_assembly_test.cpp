// Primitive assembly and the index check of an indexed draw, below the draw loop:
//   - a draw's triangles assembled range by range (as each front-end worker assembles its own,
//     exact/draw.hpp) are the whole draw's, and those follow Mesa's order as primitive_assembly.hpp
//     writes it down, for every triangle topology, both provoking vertex modes and every length;
//   - largestIndex (the AVX2 pass and its tail) is the plain maximum for every length, for values
//     past 2^31 (an unsigned maximum), with and without primitive restart (draw_state_test.cpp
//     checks that Context::drawIndexed names the offending index wherever it lies).
#include <softraster/detail/geometry/largest_index.hpp>
#include <softraster/detail/geometry/primitive_assembly.hpp>
#include <softraster/state.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

using softraster::Topology;
using softraster::detail::TriangleIndices;

// Mesa's order, written out from the header's comment one triangle at a time, independently of
// primitive_assembly.hpp's loops.
std::vector<TriangleIndices> reference(Topology topology, const std::vector<std::uint32_t>& idx, bool last) {
  std::vector<TriangleIndices> out;
  const std::size_t n = idx.size();
  switch (topology) {
    case Topology::TriangleList:
      for (std::size_t k = 0; 3 * k + 3 <= n; ++k) out.push_back({idx[3 * k], idx[3 * k + 1], idx[3 * k + 2]});
      break;
    case Topology::TriangleStrip:
      for (std::size_t k = 0; k + 3 <= n; ++k) {
        if (k % 2 == 0) out.push_back({idx[k], idx[k + 1], idx[k + 2]});
        else if (last) out.push_back({idx[k + 1], idx[k], idx[k + 2]});
        else out.push_back({idx[k], idx[k + 2], idx[k + 1]});
      }
      break;
    case Topology::TriangleFan:
      for (std::size_t k = 0; k + 3 <= n; ++k) {
        if (last) out.push_back({idx[0], idx[k + 1], idx[k + 2]});
        else out.push_back({idx[k + 1], idx[k + 2], idx[0]});
      }
      break;
    case Topology::TriangleListWithAdjacency:
      for (std::size_t k = 0; 6 * k + 6 <= n; ++k) out.push_back({idx[6 * k], idx[6 * k + 2], idx[6 * k + 4]});
      break;
    case Topology::TriangleStripWithAdjacency:
      for (std::size_t k = 0; 2 * k + 6 <= n; ++k) {
        if (k % 2 == 0) out.push_back({idx[2 * k], idx[2 * k + 2], idx[2 * k + 4]});
        else if (last) out.push_back({idx[2 * k + 2], idx[2 * k], idx[2 * k + 4]});
        else out.push_back({idx[2 * k], idx[2 * k + 4], idx[2 * k + 2]});
      }
      break;
    default:
      break;
  }
  return out;
}

}  // namespace

TEST(PrimitiveAssembly, RangesAssembledApartAreTheDrawInMesasOrder) {
  const Topology topologies[] = {Topology::TriangleList, Topology::TriangleStrip, Topology::TriangleFan,
                                 Topology::TriangleListWithAdjacency, Topology::TriangleStripWithAdjacency};
  std::mt19937 random(7);
  for (const Topology topology : topologies) {
    for (const bool last : {false, true}) {
      for (std::size_t n = 0; n <= 40; ++n) {
        std::vector<std::uint32_t> indices(n);
        for (std::uint32_t& i : indices) i = random() % 1000;  // distinct enough to tell the order
        const std::vector<TriangleIndices> expected = reference(topology, indices, last);
        SCOPED_TRACE("topology " + std::to_string(static_cast<int>(topology)) + ", " + std::to_string(n) +
                     " indices, provoking " + (last ? "last" : "first"));
        ASSERT_EQ(softraster::detail::triangleCount(topology, n), expected.size());
        std::vector<TriangleIndices> whole(expected.size());
        softraster::detail::assembleTriangleRange(topology, indices, 0, whole.size(), whole.data(), last);
        EXPECT_EQ(whole, expected);
        // Every cut into two ranges, each assembled on its own.
        for (std::size_t cut = 0; cut <= expected.size(); ++cut) {
          std::vector<TriangleIndices> pieces(expected.size());
          softraster::detail::assembleTriangleRange(topology, indices, 0, cut, pieces.data(), last);
          softraster::detail::assembleTriangleRange(topology, indices, cut, expected.size() - cut,
                                                    pieces.data() + cut, last);
          EXPECT_EQ(pieces, expected) << "cut at triangle " << cut;
        }
      }
    }
  }
  EXPECT_EQ(softraster::detail::triangleCount(Topology::LineList, 30), 0u);
  EXPECT_EQ(softraster::detail::triangleCount(Topology::PointList, 30), 0u);
}

TEST(LargestIndex, IsThePlainMaximumForEveryLengthAndRestart) {
  std::mt19937 random(11);
  constexpr std::uint32_t kRestart = softraster::kPrimitiveRestartIndex;
  for (std::size_t n = 0; n <= 300; ++n) {
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<std::uint32_t> indices(n);
      for (std::uint32_t& i : indices) {
        const std::uint32_t r = random();
        i = r % 5 == 0 ? kRestart : (trial == 3 ? r : r % 5000);  // trial 3: values past 2^31 too
      }
      if (n > 0 && trial == 1) indices[random() % n] = 0xFFFFFFFEu;  // the largest non-restart value, anywhere
      for (const bool restart : {false, true}) {
        std::uint32_t expected = 0;
        for (const std::uint32_t i : indices) expected = std::max(expected, restart && i == kRestart ? 0u : i);
        EXPECT_EQ(softraster::detail::largestIndex(indices, restart), expected)
            << n << " indices, trial " << trial << ", restart " << restart;
      }
    }
  }
  // Only restart indices, or none at all: 0.
  EXPECT_EQ(softraster::detail::largestIndex(std::vector<std::uint32_t>(37, kRestart), true), 0u);
  EXPECT_EQ(softraster::detail::largestIndex(std::vector<std::uint32_t>(37, kRestart), false), kRestart);
  EXPECT_EQ(softraster::detail::largestIndex({}, true), 0u);
}
