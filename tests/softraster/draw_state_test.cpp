// Context::draw refuses states outside softraster's device limits (limits.hpp, lavapipe's) with
// an error instead of drawing them, and states at the edge of what 32-bit integers hold draw
// without overflow (run under UBSan in the sanitizer build).
#include <softraster/limits.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
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
