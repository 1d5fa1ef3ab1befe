// The public API as a library user meets it: Framebuffer::create's checks (errors returned, never
// printed), depth read back as floats, the pixel accessors and their sample order, a draw into a
// framebuffer with no pixels, and the threading promise (four threads, each with its own Context
// and Framebuffer, draw the same bits as one).
// Deliberately no pipeline arithmetic: the stage tests and the cross-check cover that.
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <thread>
#include <vector>

namespace {

using softraster::DepthFormat;
using softraster::Framebuffer;

TEST(FramebufferCreate, RejectsBadSampleCountsSizesAndFormats) {
  const auto two = Framebuffer::create(8, 8, DepthFormat::D32Sfloat, 2);
  ASSERT_FALSE(two);
  EXPECT_EQ(two.error(), "framebuffer samples 2: must be 1 or 4");
  const auto empty = Framebuffer::create(0, 8);
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.error(), "framebuffer size 0x8: width and height must be 1..16384");
  EXPECT_FALSE(Framebuffer::create(16385, 1));
  EXPECT_FALSE(Framebuffer::create(4, 4, static_cast<DepthFormat>(7)));
  const auto four = Framebuffer::create(3, 2, DepthFormat::D16Unorm, 4);
  ASSERT_TRUE(four);
  EXPECT_EQ(four->samples(), 4u);
  EXPECT_EQ(four->colour().size(), 3u * 2 * 4 * 4);
  EXPECT_EQ(four->depthStorage().size(), 3u * 2 * 4);
}

TEST(FramebufferRead, DepthAsFloatsForEveryFormat) {
  for (const DepthFormat format : {DepthFormat::D16Unorm, DepthFormat::X8D24UnormPack32, DepthFormat::D32Sfloat}) {
    auto framebuffer = Framebuffer::create(4, 3, format, 4);
    ASSERT_TRUE(framebuffer);
    framebuffer->clear({0, 0, 0, 1}, 0.5f);
    const std::vector<float> depth = framebuffer->depthValues();
    ASSERT_EQ(depth.size(), 4u * 3 * 4);
    for (std::size_t i = 0; i < depth.size(); ++i) EXPECT_EQ(depth[i], framebuffer->depth(i));
    EXPECT_NEAR(depth[0], 0.5f, 1e-4f);
    std::vector<float> reused(1);
    framebuffer->depthValuesInto(reused);
    EXPECT_EQ(reused, depth);
  }
}

TEST(FramebufferRead, PixelAccessorsFollowTheStorageOrder) {
  auto framebuffer = Framebuffer::create(5, 4, DepthFormat::D32Sfloat, 4);
  ASSERT_TRUE(framebuffer);
  framebuffer->clear({0, 0, 0, 0}, 1.0f);
  // Sample 2 of pixel (3, 1): row 1, column 3, samples of a pixel adjacent.
  const std::size_t index = framebuffer->sampleIndex(3, 1, 2);
  EXPECT_EQ(index, (1u * 5 + 3) * 4 + 2);
  framebuffer->colour()[4 * index + 0] = 200;
  framebuffer->colour()[4 * index + 3] = 7;
  framebuffer->depthStorage()[index] = std::bit_cast<std::uint32_t>(0.25f);
  const std::array<std::uint8_t, 4> rgba = framebuffer->colourAt(3, 1, 2);
  EXPECT_EQ(rgba[0], 200);
  EXPECT_EQ(rgba[3], 7);
  EXPECT_EQ(framebuffer->depthAt(3, 1, 2), 0.25f);
  EXPECT_EQ(framebuffer->depthAt(3, 1, 1), 1.0f);
}

// A shader over both float types, so a draw can take the fast path.
struct Gradient {
  struct Vertex {
    softraster::Vec3 position;
    softraster::Vec4 colour;
  };
  struct Uniforms {
    float scale = 1.0f;
  };
  static constexpr int kVaryings = 4;
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& v, float* out) {
    for (int i = 0; i < 4; ++i) out[i] = v.colour[i] * u.scale;
    return {v.position.x, v.position.y, v.position.z, 1.0f};
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F* in) {
    return {in[0] * in[1] + in[2], in[1], in[2] * in[3], F(1.0f)};
  }
};
static_assert(softraster::ShaderInterface<Gradient>);
static_assert(softraster::ShadesBatches<Gradient>);

std::vector<Gradient::Vertex> fan() {
  std::vector<Gradient::Vertex> v;
  for (int i = 0; i < 60; ++i) {
    const float x = -0.9f + 0.03f * static_cast<float>(i), y = (i % 2 ? 0.8f : -0.7f);
    v.push_back({{x, y, 0.1f + 0.01f * static_cast<float>(i)}, {0.1f * static_cast<float>(i % 10), 0.3f, 0.7f, 0.9f}});
  }
  return v;
}

Framebuffer drawFan(unsigned threads) {
  softraster::ContextOptions options;
  options.threads = threads;
  const softraster::Context context(options);
  auto framebuffer = Framebuffer::create(61, 47, DepthFormat::X8D24UnormPack32, 4);
  framebuffer->clear({0, 0, 0, 1}, 1.0f);
  softraster::PipelineState state;
  state.topology = softraster::Topology::TriangleStrip;
  state.rasterization.cullMode = softraster::CullMode::None;
  const std::vector<Gradient::Vertex> vertices = fan();
  EXPECT_TRUE(context.draw<Gradient>(state, Gradient::Uniforms{}, vertices, *framebuffer).ok());
  return std::move(*framebuffer);
}

TEST(Context, FourThreadsWithTheirOwnContextsDrawTheSameBits) {
  const Framebuffer reference = drawFan(1);
  std::vector<Framebuffer> results(4);
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < 4; ++t) threads.emplace_back([&results, t] { results[t] = drawFan(1 + t % 2); });
  for (std::thread& t : threads) t.join();
  for (const Framebuffer& r : results) {
    EXPECT_EQ(r.colour(), reference.colour());
    EXPECT_EQ(r.depthStorage(), reference.depthStorage());
  }
}

TEST(Context, RefusesAFramebufferWithoutPixels) {
  const softraster::Context context;
  Framebuffer none;
  const std::vector<Gradient::Vertex> vertices = fan();
  const softraster::Status status = context.draw<Gradient>(softraster::PipelineState{}, Gradient::Uniforms{}, vertices, none);
  ASSERT_FALSE(status);
  EXPECT_EQ(status.message(), "framebuffer has no pixels (make it with Framebuffer::create)");
}

}  // namespace
