// Context::draw refuses states outside softraster's device limits (limits.hpp, lavapipe's), and
// drawIndexed an index past the last vertex (named wherever it lies), with an error instead of
// drawing them, and states at the edge of what 32-bit integers hold draw
// without overflow (run under UBSan in the sanitizer build).
#include <softraster/limits.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

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

// Draws a triangle over most of a 16x16 framebuffer (as a line list: one horizontal line across
// its middle); returns the status and counts the white pixels.
softraster::Status drawWith(softraster::PipelineState state, int* whitePixels = nullptr) {
  state.rasterization.cullMode = softraster::CullMode::None;
  softraster::Framebuffer framebuffer = softraster::Framebuffer::create(16, 16).value();
  framebuffer.clear({0, 0, 0, 1}, 1.0f);
  const std::vector<White::Vertex> vertices{{{-1.0f, 0.0f, 0.5f}}, {{1.0f, 0.0f, 0.5f}}, {{-1.0f, 1.0f, 0.5f}}};
  const softraster::Context context;
  const softraster::Status status =
      context.draw<White>(state, White::Uniforms{}, std::span<const White::Vertex>(vertices), framebuffer);
  if (whitePixels) {
    *whitePixels = 0;
    for (std::size_t i = 0; i < framebuffer.colour().size(); i += 4) *whitePixels += framebuffer.colour()[i] == 255;
  }
  return status;
}

softraster::PipelineState lines(float width) {
  softraster::PipelineState state;
  state.topology = softraster::Topology::LineList;
  state.rasterization.lineWidth = width;
  return state;
}

void expectRefused(const softraster::PipelineState& state, const std::string& message) {
  const softraster::Status status = drawWith(state);
  ASSERT_FALSE(status.ok()) << "drawn: " << message;
  EXPECT_NE(status.message().find(message), std::string::npos) << status.message();
}

}  // namespace

TEST(DrawState, LineWidthOutsideLineWidthRangeIsAnError) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  for (float width : {0.5f, 255.5f, 1e9f, kInf, -kInf, std::numeric_limits<float>::quiet_NaN()}) {
    expectRefused(lines(width), "outside lineWidthRange [1, 255]");
  }
  for (auto rasterization : {softraster::LineRasterization::Rectangular, softraster::LineRasterization::Bresenham}) {
    softraster::PipelineState widest = lines(softraster::DeviceLimits::kMaxLineWidth);
    widest.rasterization.lineRasterization = rasterization;
    int white = 0;
    ASSERT_TRUE(drawWith(widest, &white).ok());
    EXPECT_GE(white, 16 * 15) << "a 255-pixel line across the middle covers every row";
  }
}

TEST(DrawState, ViewportOutsideTheDeviceLimitsIsAnError) {
  softraster::PipelineState state;
  state.viewport = {0, 0, 20000, 16, 0, 1};
  expectRefused(state, "maxViewportDimensions");
  state.viewport = {32760, 0, 16, 16, 0, 1};
  expectRefused(state, "viewportBoundsRange");
  state.viewport = {std::numeric_limits<float>::quiet_NaN(), 0, 16, 16, 0, 1};
  expectRefused(state, "finite");
  state.viewport = {0, 0, -16, 16, 0, 1};
  expectRefused(state, "positive");
  state.viewport = {0, 0, 16, 16, 0, 2};
  expectRefused(state, "minDepth and maxDepth");
}

TEST(DrawState, ScissorAtTheEdgeOfInt32) {
  softraster::PipelineState state;
  state.scissor = {std::numeric_limits<std::int32_t>::max(), 0, 100, 16};
  expectRefused(state, "must fit in a 32-bit signed integer");
  state.scissor = {-1, 0, 4, 4};
  expectRefused(state, "must not be negative");
  // The largest scissor that fits: far right of the framebuffer, so nothing is drawn.
  state.scissor = {std::numeric_limits<std::int32_t>::max() - 100, std::numeric_limits<std::int32_t>::max() - 100, 100, 100};
  int white = -1;
  ASSERT_TRUE(drawWith(state, &white).ok());
  EXPECT_EQ(white, 0);
  // A scissor wider than the framebuffer starting inside it clips to the framebuffer.
  state.scissor = {8, 0, std::numeric_limits<std::int32_t>::max() - 8, 16};
  ASSERT_TRUE(drawWith(state, &white).ok());
  int all = 0;
  ASSERT_TRUE(drawWith(softraster::PipelineState{}, &all).ok());
  EXPECT_GT(white, 0);
  EXPECT_LT(white, all);
}

// Issue 13's primitive state: a negative viewport height flips y (the triangle drawn in the lower
// half lands in the upper half), primitive restart skips its index in the bounds check and is
// refused for list topologies, the stipple factor's range (and stippled polygon modes drawn) and the
// unknown enumerators.
TEST(DrawState, NegativeViewportHeightFlipsY) {
  const auto whiteRows = [](const softraster::PipelineState& state) {
    softraster::Framebuffer framebuffer = softraster::Framebuffer::create(16, 16).value();
    framebuffer.clear({0, 0, 0, 1}, 1.0f);
    const std::vector<White::Vertex> vertices{{{-1.0f, 0.0f, 0.5f}}, {{1.0f, 0.0f, 0.5f}}, {{-1.0f, 1.0f, 0.5f}}};
    softraster::PipelineState s = state;
    s.rasterization.cullMode = softraster::CullMode::None;
    EXPECT_TRUE(softraster::Context().draw<White>(s, {}, std::span<const White::Vertex>(vertices), framebuffer).ok());
    std::vector<int> rows(16, 0);
    for (std::size_t i = 0; i < framebuffer.colour().size(); i += 4) rows[i / 4 / 16] += framebuffer.colour()[i] == 255;
    return rows;
  };
  softraster::PipelineState flipped;
  flipped.viewport = {0, 16, 16, -16, 0, 1};
  const std::vector<int> up = whiteRows(softraster::PipelineState{}), down = whiteRows(flipped);
  for (int y = 0; y < 16; ++y) EXPECT_EQ(down[static_cast<std::size_t>(y)], up[static_cast<std::size_t>(15 - y)]) << y;
  EXPECT_GT(up[12], 0);
  EXPECT_EQ(up[3], 0);
  flipped.viewport = {0, 0, 16, -40000, 0, 1};
  expectRefused(flipped, "maxViewportDimensions");
  flipped.viewport = {0, -32760, 16, -16, 0, 1};
  expectRefused(flipped, "viewportBoundsRange");
}

TEST(DrawState, PrimitiveRestartIndexIsNoVertex) {
  softraster::Framebuffer framebuffer = softraster::Framebuffer::create(16, 16).value();
  const std::vector<White::Vertex> vertices{{{-1.0f, 0.0f, 0.5f}}, {{1.0f, 0.0f, 0.5f}}, {{-1.0f, 1.0f, 0.5f}},
                                            {{1.0f, 1.0f, 0.5f}}};
  const std::vector<std::uint32_t> indices{0, 1, 2, softraster::kPrimitiveRestartIndex, 1, 2, 3};
  softraster::PipelineState state;
  state.topology = softraster::Topology::TriangleStrip;
  state.rasterization.cullMode = softraster::CullMode::None;
  const softraster::Context context;
  const auto drawIndexed = [&](const softraster::PipelineState& s) {
    return context.drawIndexed<White>(s, {}, std::span<const White::Vertex>(vertices), indices, framebuffer);
  };
  EXPECT_FALSE(drawIndexed(state).ok()) << "without restart 0xFFFFFFFF is an index past the last vertex";
  state.primitiveRestartEnable = true;
  EXPECT_TRUE(drawIndexed(state).ok());
  state.topology = softraster::Topology::TriangleList;
  const softraster::Status list = drawIndexed(state);
  ASSERT_FALSE(list.ok());
  EXPECT_NE(list.message().find("topology-06252"), std::string::npos) << list.message();
}

TEST(DrawState, DrawIndexedNamesTheOffendingIndexWhereverItLies) {
  softraster::Framebuffer framebuffer = softraster::Framebuffer::create(8, 8).value();
  const std::vector<White::Vertex> vertices{{{-1, -1, 0.5f}}, {{1, -1, 0.5f}}, {{-1, 1, 0.5f}}};
  const softraster::Context context;
  // 3 * 11 = 33 indices: 32 in largestIndex's AVX2 vectors and one in its tail.
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

TEST(DrawState, LineStippleAndTopologyRefusals) {
  softraster::PipelineState state = lines(1.0f);
  state.rasterization.lineStipple = {true, 0x00FF, 0};
  expectRefused(state, "stippledLineEnable-02767");
  state.rasterization.lineStipple.factor = 257;
  expectRefused(state, "outside [1, 256]");
  state.rasterization.lineStipple.factor = 256;
  int white = 0;
  ASSERT_TRUE(drawWith(state, &white).ok());
  EXPECT_GT(white, 0) << "bit 0 of the pattern is on for the first 256 steps";
  // Polygon mode line is stippled too (Mesa's stipple stage follows the unfilled stage): runs of
  // 2 steps on, 2 off keep some of the outline's pixels; point mode ignores the stipple.
  state.topology = softraster::Topology::TriangleList;
  state.rasterization.lineStipple = {true, 0x3333, 1};
  int outline = 0, stippled = 0, points = 0, stippledPoints = 0;
  state.rasterization.polygonMode = softraster::PolygonMode::Line;
  ASSERT_TRUE(drawWith(state, &stippled).ok());
  state.rasterization.lineStipple.enable = false;
  ASSERT_TRUE(drawWith(state, &outline).ok());
  EXPECT_GT(stippled, outline / 4);
  EXPECT_LT(stippled, outline * 3 / 4);
  state.rasterization.polygonMode = softraster::PolygonMode::Point;
  ASSERT_TRUE(drawWith(state, &points).ok());
  state.rasterization.lineStipple.enable = true;
  ASSERT_TRUE(drawWith(state, &stippledPoints).ok());
  EXPECT_GT(points, 0);
  EXPECT_EQ(stippledPoints, points);
  softraster::PipelineState unknown;
  unknown.topology = static_cast<softraster::Topology>(10);  // VK_PRIMITIVE_TOPOLOGY_PATCH_LIST
  expectRefused(unknown, "unknown topology");
}

// The multisample state through the public API: a sample mask keeping no sample draws nothing;
// with one sample lavapipe ignores bit 0 (Deviations::Driver draws a mask of 0xfffffffe) where
// the spec does not (Deviations::Spec draws nothing); minSampleShading outside [0, 1] is refused
// only with sample shading on (Vulkan ignores the value otherwise).
TEST(DrawState, SampleMaskAndSampleShadingRules) {
  const auto whiteWith = [](std::uint32_t mask, softraster::Deviations deviations) {
    softraster::PipelineState state;
    state.rasterization.cullMode = softraster::CullMode::None;
    state.multisample.sampleMask = mask;
    softraster::Framebuffer framebuffer = softraster::Framebuffer::create(16, 16).value();
    framebuffer.clear({0, 0, 0, 1}, 1.0f);
    const std::vector<White::Vertex> vertices{{{-1.0f, -1.0f, 0.5f}}, {{1.0f, -1.0f, 0.5f}}, {{-1.0f, 1.0f, 0.5f}}};
    softraster::ContextOptions options;
    options.deviations = deviations;
    const softraster::Context context(options);
    EXPECT_TRUE(context.draw<White>(state, White::Uniforms{}, std::span<const White::Vertex>(vertices), framebuffer).ok());
    int white = 0;
    for (std::size_t i = 0; i < framebuffer.colour().size(); i += 4) white += framebuffer.colour()[i] == 255;
    return white;
  };
  const int all = whiteWith(0xFFFFFFFFu, softraster::Deviations::Driver);
  EXPECT_GT(all, 100);
  EXPECT_EQ(whiteWith(0xFFFFFFFEu, softraster::Deviations::Driver), all);
  EXPECT_EQ(whiteWith(0xFFFFFFFEu, softraster::Deviations::Spec), 0);
  EXPECT_EQ(whiteWith(0x1u, softraster::Deviations::Spec), all);
  EXPECT_EQ(whiteWith(0u, softraster::Deviations::Driver), 0);

  softraster::PipelineState state;
  state.multisample.minSampleShading = 2.0f;  // ignored: sample shading is off
  EXPECT_TRUE(drawWith(state).ok());
  state.multisample.sampleShadingEnable = true;
  expectRefused(state, "minSampleShading-00786");
  state.multisample.minSampleShading = std::numeric_limits<float>::quiet_NaN();
  expectRefused(state, "minSampleShading must be in [0, 1]");
}

// 4x MSAA lines are drawn (rectangular, Bresenham, polygon mode line); a sample mask leaves
// Bresenham lines whole (lavapipe draws them with multisampling off, so only a mask of 0 drops
// them) and narrows rectangular ones; alpha to coverage, alpha to one and sample shading with
// Bresenham lines are refused (Vulkan forbids them); the course's 1/z buffer with 4 samples is
// refused.
TEST(DrawState, MsaaLineRules) {
  const auto drawMsaa = [](softraster::PipelineState state, softraster::DepthMode depthMode = softraster::DepthMode::Vulkan) {
    softraster::Framebuffer framebuffer =
        softraster::Framebuffer::create(16, 16, softraster::DepthFormat::D32Sfloat, 4).value();
    framebuffer.clear({0, 0, 0, 1}, 1.0f);
    const std::vector<White::Vertex> vertices{{{-1.0f, 0.0f, 0.5f}}, {{1.0f, 0.1f, 0.5f}}, {{-1.0f, 1.0f, 0.5f}}};
    softraster::ContextOptions options;
    options.depthMode = depthMode;
    const softraster::Context context(options);
    std::size_t white = 0;
    const softraster::Status status =
        context.draw<White>(state, White::Uniforms{}, std::span<const White::Vertex>(vertices), framebuffer);
    for (std::size_t i = 0; i < framebuffer.colour().size(); i += 4) white += framebuffer.colour()[i] == 255;
    return std::pair{status, white};
  };
  for (auto rasterization : {softraster::LineRasterization::Rectangular, softraster::LineRasterization::Bresenham}) {
    softraster::PipelineState state = lines(2.0f);
    state.rasterization.lineRasterization = rasterization;
    const auto [status, white] = drawMsaa(state);
    EXPECT_TRUE(status.ok()) << status.message();
    EXPECT_GE(white, 4u * 16u) << "a 2-pixel line across 16 columns covers at least 64 samples";
    softraster::PipelineState polygonMode;
    polygonMode.rasterization.cullMode = softraster::CullMode::None;
    polygonMode.rasterization.polygonMode = softraster::PolygonMode::Line;
    polygonMode.rasterization.lineRasterization = rasterization;
    EXPECT_TRUE(drawMsaa(polygonMode).first.ok());
  }
  softraster::PipelineState masked = lines(1.0f);
  masked.rasterization.lineRasterization = softraster::LineRasterization::Bresenham;
  const std::size_t unmasked = drawMsaa(masked).second;
  ASSERT_GT(unmasked, 0u);
  masked.multisample.sampleMask = 0x1;  // lavapipe draws Bresenham lines with multisampling off: no mask applies
  EXPECT_EQ(drawMsaa(masked).second, unmasked);
  masked.multisample.sampleMask = 0x10;  // no sample of the four, yet not 0: still drawn whole
  EXPECT_EQ(drawMsaa(masked).second, unmasked);
  masked.multisample.sampleMask = 0;  // a mask of 0 discards the draw
  EXPECT_EQ(drawMsaa(masked).second, 0u);
  masked.multisample.sampleMask = 0x7;
  masked.rasterization.lineRasterization = softraster::LineRasterization::Rectangular;
  const auto [rectangularStatus, rectangularMasked] = drawMsaa(masked);  // multisampled: the mask applies
  EXPECT_TRUE(rectangularStatus.ok());
  masked.multisample.sampleMask = 0xf;
  EXPECT_LT(rectangularMasked, drawMsaa(masked).second);
  // Alpha to coverage, alpha to one and sample shading are invalid with Bresenham lines in Vulkan
  // (VUID-...-02766), whatever the topology or sample count: refused, not drawn by guesswork.
  for (int which = 0; which < 3; ++which) {
    softraster::PipelineState bresenham = lines(1.0f);
    bresenham.rasterization.lineRasterization = softraster::LineRasterization::Bresenham;
    bresenham.multisample.alphaToCoverageEnable = which == 0;
    bresenham.multisample.alphaToOneEnable = which == 1;
    bresenham.multisample.sampleShadingEnable = which == 2;
    const softraster::Status refused = drawMsaa(bresenham).first;
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.message().find("lineRasterizationMode-02766"), std::string::npos) << refused.message();
    bresenham.rasterization.lineRasterization = softraster::LineRasterization::Rectangular;
    EXPECT_TRUE(drawMsaa(bresenham).first.ok());
  }
  softraster::PipelineState unknownMode = lines(1.0f);
  unknownMode.rasterization.lineRasterization = static_cast<softraster::LineRasterization>(7);
  EXPECT_EQ(drawMsaa(unknownMode).first.message(), "unknown line rasterization mode");
  const softraster::Status inverseZ = drawMsaa(lines(1.0f), softraster::DepthMode::InverseZ).first;
  ASSERT_FALSE(inverseZ.ok());
  EXPECT_NE(inverseZ.message().find("the 1/z depth buffer takes one sample per pixel"), std::string::npos)
      << inverseZ.message();
}
