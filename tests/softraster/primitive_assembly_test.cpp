// Primitive assembly and the index check of an indexed draw, below the draw loop:
//   - a draw's triangles assembled range by range (as each front-end worker assembles its own,
//     exact/draw.hpp) are the whole draw's, and those follow Mesa's order as primitive_assembly.hpp
//     writes it down, for every triangle topology, both provoking vertex modes and every length;
//   - largestIndex (the AVX2 pass and its tail) is the plain maximum for every length, for values
//     past 2^31 (an unsigned maximum), with and without primitive restart;
//   - Context::drawIndexed names the offending index wherever it lies (in a vector, in the tail).
#include <softraster/detail/geometry/largest_index.hpp>
#include <softraster/detail/geometry/primitive_assembly.hpp>
#include <softraster/pipeline.hpp>

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

struct White {
  struct Vertex {
    softraster::Vec3 position;
  };
  struct Uniforms {};
  static constexpr int kVaryings = 0;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex& v, float*) {
    return {v.position.x, v.position.y, v.position.z, 1.0f};
  }
  static softraster::Vec4 fragment(const Uniforms&, const float*) { return {1, 1, 1, 1}; }
};

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
        std::vector<TriangleIndices> whole;
        softraster::detail::assembleTriangles(topology, indices, whole, last);
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

TEST(LargestIndex, DrawIndexedNamesTheOffendingIndexWhereverItLies) {
  softraster::Framebuffer framebuffer = softraster::Framebuffer::create(8, 8).value();
  const std::vector<White::Vertex> vertices{{{-1, -1, 0.5f}}, {{1, -1, 0.5f}}, {{-1, 1, 0.5f}}};
  const softraster::Context context;
  // 3 * 11 = 33 indices: 32 in AVX2 vectors and one in the tail.
  for (const std::size_t at : {std::size_t{0}, std::size_t{9}, std::size_t{31}, std::size_t{32}}) {
    std::vector<std::uint32_t> indices(33);
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i % 3);
    indices[at] = 3;
    const softraster::Status status = context.drawIndexed<White>(
        softraster::PipelineState{}, {}, std::span<const White::Vertex>(vertices), indices, framebuffer);
    ASSERT_FALSE(status.ok()) << "index " << at;
    EXPECT_NE(status.message().find("index " + std::to_string(at) + " (3) is past the last vertex (3 vertices)"),
              std::string::npos)
        << status.message();
  }
}
