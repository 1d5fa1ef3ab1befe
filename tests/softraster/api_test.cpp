// The public API as a library user meets it: Framebuffer::create's checks (errors returned, never
// printed), depth read back as floats, the pixel accessors and their sample order, a draw into a
// framebuffer with no pixels, and the threading promise (four threads, each with its own Context
// and Framebuffer, draw the same bits as one).
// Deliberately no pipeline arithmetic: the stage tests and the cross-check cover that.
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <bit>
#include <cmath>
#include <cstdint>
#include <thread>
#include <utility>
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

// A B8G8R8A8 target holds the R8G8B8A8 target's bytes with red and blue swapped, whatever the
// method, with blending (constants far apart in red and blue), a write mask naming red alone and
// a logic op, with one sample and four.
TEST(Context, BgraTargetIsTheRgbaTargetWithRedAndBlueSwapped) {
  softraster::PipelineState over;
  over.topology = softraster::Topology::TriangleStrip;
  over.rasterization.cullMode = softraster::CullMode::None;
  over.depth.testEnable = false;
  over.blend.enable = true;
  over.blend.srcColorBlendFactor = softraster::BlendFactor::ConstantColor;
  over.blend.dstColorBlendFactor = softraster::BlendFactor::OneMinusSrcColor;
  const float constants[4] = {0.9f, 0.4f, 0.1f, 0.6f};
  std::copy(std::begin(constants), std::end(constants), over.blend.blendConstants);
  softraster::PipelineState maskRed = over;
  maskRed.blend.enable = false;
  maskRed.blend.colorWriteMask = softraster::kColourR;
  softraster::PipelineState logic = over;
  logic.blend.logicOpEnable = true;
  logic.blend.logicOp = softraster::LogicOp::Xor;
  const std::vector<Gradient::Vertex> vertices = fan();
  for (const softraster::Method method : {softraster::Method::Exact, softraster::Method::ExactScalar}) {
    for (const std::uint32_t samples : {1u, 4u}) {
      for (const softraster::PipelineState& state : {over, maskRed, logic}) {
        softraster::ContextOptions options;
        options.method = method;
        options.threads = 1;
        const softraster::Context context(options);
        std::array<Framebuffer, 2> targets;
        for (int k = 0; k < 2; ++k) {
          auto target = Framebuffer::create(61, 47, DepthFormat::D32Sfloat, samples,
                                            k == 0 ? softraster::ColourFormat::R8G8B8A8Unorm
                                                   : softraster::ColourFormat::B8G8R8A8Unorm);
          ASSERT_TRUE(target);
          target->clear({0.8f, 0.3f, 0.15f, 0.5f}, 1.0f);
          ASSERT_TRUE(context.draw<Gradient>(state, Gradient::Uniforms{}, vertices, *target).ok());
          targets[static_cast<std::size_t>(k)] = std::move(*target);
        }
        std::vector<std::uint8_t> swapped = targets[0].colour();
        for (std::size_t i = 0; i < swapped.size(); i += 4) std::swap(swapped[i], swapped[i + 2]);
        EXPECT_EQ(targets[1].colour(), swapped) << "samples " << samples;
        EXPECT_NE(targets[0].colour(), swapped) << "red and blue differ somewhere";
        EXPECT_EQ(targets[1].colourAt(30, 20), targets[0].colourAt(30, 20));
      }
    }
  }
}

TEST(FramebufferCreate, BgraStoresBlueFirstAndResolvesToBgra) {
  auto framebuffer = Framebuffer::create(3, 2, DepthFormat::D32Sfloat, 4, softraster::ColourFormat::B8G8R8A8Unorm);
  ASSERT_TRUE(framebuffer);
  EXPECT_EQ(framebuffer->colourFormat(), softraster::ColourFormat::B8G8R8A8Unorm);
  framebuffer->clear({1.0f, 0.5f, 0.0f, 0.25f}, 1.0f);
  const std::vector<std::uint8_t>& bytes = framebuffer->colour();
  EXPECT_EQ((std::array<int, 4>{bytes[0], bytes[1], bytes[2], bytes[3]}), (std::array<int, 4>{0, 128, 255, 64}));
  EXPECT_EQ(framebuffer->colourAt(2, 1, 3), (std::array<std::uint8_t, 4>{255, 128, 0, 64}));
  framebuffer->colour()[4 * framebuffer->sampleIndex(1, 0, 2)] = 100;  // blue of one sample: 0 -> 100
  const Framebuffer resolved = framebuffer->resolve();
  EXPECT_EQ(resolved.colourFormat(), softraster::ColourFormat::B8G8R8A8Unorm);
  EXPECT_EQ(resolved.colourAt(1, 0), (std::array<std::uint8_t, 4>{255, 128, 25, 64}));  // blue 100 / 4
  EXPECT_EQ(resolved.colourAt(0, 0), (std::array<std::uint8_t, 4>{255, 128, 0, 64}));
  EXPECT_EQ(Framebuffer::create(4, 4, DepthFormat::D32Sfloat, 1, static_cast<softraster::ColourFormat>(9)).error(),
            "unknown colour format");
}

// An sRGB target's clear encodes red, green and blue as lavapipe's clear does (its own table:
// 0.5 -> 188, where a fragment store gives 187), alpha as UNORM; the resolve averages linear values.
TEST(FramebufferCreate, SrgbClearAndResolve) {
  auto framebuffer = Framebuffer::create(2, 1, DepthFormat::D32Sfloat, 4, softraster::ColourFormat::B8G8R8A8Srgb);
  ASSERT_TRUE(framebuffer);
  framebuffer->clear({0.5f, 0.2f, 1.0f, 0.5f}, 1.0f);
  EXPECT_EQ(framebuffer->colourAt(1, 0, 2), (std::array<std::uint8_t, 4>{188, 124, 255, 128}));
  EXPECT_EQ(framebuffer->colour()[2], 188) << "BGRA: red in byte 2";
  // Samples of pixel 0: red 0, 0, 188, 188. Averaged as linear values that is about 137 (the
  // transfer function in double; lavapipe's approximations may round the other way), where an
  // average of the bytes would give 94.
  for (std::uint32_t s = 0; s < 2; ++s) framebuffer->colour()[4 * framebuffer->sampleIndex(0, 0, s) + 2] = 0;
  const Framebuffer resolved = framebuffer->resolve();
  const double linear = std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4) / 2.0;
  const double encoded = 255.0 * (1.055 * std::pow(linear, 1.0 / 2.4) - 0.055);
  EXPECT_NEAR(resolved.colourAt(0, 0)[0], encoded, 1.0);
  EXPECT_EQ(resolved.colourAt(1, 0), (std::array<std::uint8_t, 4>{188, 124, 255, 128})) << "four equal samples";
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
