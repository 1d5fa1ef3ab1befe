// The public API as a library user meets it: Framebuffer::create's checks (errors returned, never
// printed), depth read back as floats, the pixel accessors and their sample order, a draw into a
// framebuffer with no pixels, and the threading promise (four threads, each with its own Context
// and Framebuffer, draw the same bits as one).
// Deliberately no pipeline arithmetic: the stage tests and the cross-check cover that.
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <span>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
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

// The UNORM8 4x resolve (two pixels at a time with AVX2, one with SSE2, the tail one by one) gives
// every pixel the formula's bytes: sample bytes times float(1/255) summed in sample order, times
// 0.25, stored as a fragment stores UNORM8. Random samples over an odd width and height, so every
// path and the tail are taken; the extremes (0 and 255) in the first pixels.
TEST(FramebufferCreate, Unorm8ResolveOfRandomSamplesIsTheFormulaAtEveryPixel) {
  auto framebuffer = Framebuffer::create(37, 23, DepthFormat::D32Sfloat, 4);
  ASSERT_TRUE(framebuffer);
  std::vector<std::uint8_t>& samples = framebuffer->colour();
  std::uint32_t state = 12345;
  for (std::uint8_t& b : samples) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(state >> 24);
  }
  for (std::size_t i = 0; i < 64; ++i) samples[i] = (i % 3 == 0) ? 255 : (i % 3 == 1 ? 0 : samples[i]);
  const Framebuffer resolved = framebuffer->resolve();
  const float toFloat = static_cast<float>(1.0 / 255.0);
  for (std::size_t p = 0; p < 37u * 23u; ++p) {
    for (std::size_t c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (std::size_t s = 0; s < 4; ++s) sum = sum + static_cast<float>(samples[(p * 4 + s) * 4 + c]) * toFloat;
      ASSERT_EQ(resolved.colour()[p * 4 + c], softraster::detail::unorm8FromFloat(sum * 0.25f)) << "pixel " << p << " channel " << c;
    }
  }
}

// Context::resolveInto shares the rows among the context's threads: the same bytes as
// Framebuffer::resolve for every attachment's format, depth and stencil, on a height that is not
// a multiple of the rows per task, into a fresh target and into one reused.
TEST(FramebufferCreate, ContextResolveOnThreadsIsTheFramebuffersResolve) {
  const std::array formats{softraster::ColourFormat::R8G8B8A8Unorm, softraster::ColourFormat::R8G8B8A8Srgb,
                           softraster::ColourFormat::A2B10G10R10Unorm,
                           softraster::ColourFormat::R16G16B16A16Sfloat, softraster::ColourFormat::R32G32B32A32Sfloat};
  auto framebuffer = Framebuffer::create(45, 77, DepthFormat::D24UnormS8Uint, 4, formats);
  ASSERT_TRUE(framebuffer);
  std::uint32_t state = 99;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return state;
  };
  for (std::uint32_t a = 0; a < framebuffer->colourAttachments(); ++a) {
    std::vector<std::uint8_t>& bytes = framebuffer->colour(a);
    const bool isFloat = softraster::isFloat(framebuffer->colourFormat(a));
    for (std::size_t i = 0; i < bytes.size(); ++i) {
      // float formats: exponents kept small (no NaN or infinity), so the sums stay finite
      bytes[i] = static_cast<std::uint8_t>(next() >> 24) & (isFloat && i % 2 == 1 ? 0x3bu : 0xffu);
    }
  }
  for (std::uint32_t& d : framebuffer->depthStorage()) d = next() & 0xffffffu;
  for (std::uint8_t& s : framebuffer->stencilStorage()) s = static_cast<std::uint8_t>(next() >> 24);
  const Framebuffer expected = framebuffer->resolve();
  softraster::ContextOptions options;
  options.threads = 3;
  const softraster::Context context(options);
  Framebuffer out;
  for (int round = 0; round < 2; ++round) {  // allocated, then reused
    context.resolveInto(*framebuffer, out);
    ASSERT_EQ(out.samples(), 1u);
    for (std::uint32_t a = 0; a < expected.colourAttachments(); ++a) EXPECT_EQ(out.colour(a), expected.colour(a)) << "attachment " << a;
    EXPECT_EQ(out.depthStorage(), expected.depthStorage());
    EXPECT_EQ(out.stencilStorage(), expected.stencilStorage());
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

// An A2B10G10R10 target: one word per sample, red in the low bits. The clear rounds as Mesa's
// format packer does (0.9995 * 1023 = 1022.49 -> 1022; alpha 0.5 * 3 -> 2, half to even); colourAt
// is a byte view; the resolve averages v * float(1/1023) and stores as a fragment does (the
// 16-bit route: round to UNORM16, then >> 6).
TEST(FramebufferCreate, TenBitClearViewAndResolve) {
  auto framebuffer = Framebuffer::create(2, 1, DepthFormat::D32Sfloat, 4, softraster::ColourFormat::A2B10G10R10Unorm);
  ASSERT_TRUE(framebuffer);
  framebuffer->clear({0.9995f, 0.25f, 0.6f, 0.5f}, 1.0f);
  std::uint32_t word;
  std::memcpy(&word, framebuffer->colour().data() + 4 * framebuffer->sampleIndex(1, 0, 3), 4);
  EXPECT_EQ(word, softraster::packTenBit(1022, 256, 614, 2));
  EXPECT_EQ(word,
            softraster::colourClearValue(softraster::ColourFormat::A2B10G10R10Unorm, {0.9995f, 0.25f, 0.6f, 0.5f})[0]);
  EXPECT_EQ(framebuffer->colourAt(1, 0, 3), (std::array<std::uint8_t, 4>{255, 64, 153, 170}));
  // Pixel 0's red: 1022, 1022, 0, 1023 -> the mean of v * float(1/1023) is 0.74951, UNORM16 49119,
  // >> 6 = 767.
  const std::size_t first = framebuffer->sampleIndex(0, 0, 0);
  const std::uint32_t reds[4] = {1022, 1022, 0, 1023};
  for (std::uint32_t s = 0; s < 4; ++s) {
    const std::uint32_t w = (word & ~1023u) | reds[s];
    std::memcpy(framebuffer->colour().data() + 4 * (first + s), &w, 4);
  }
  const Framebuffer resolved = framebuffer->resolve();
  std::uint32_t resolvedWord, sameWord;
  std::memcpy(&resolvedWord, resolved.colour().data(), 4);
  std::memcpy(&sameWord, resolved.colour().data() + 4, 4);
  const float toFloat = static_cast<float>(1.0 / 1023.0);
  const float mean = (1022.0f * toFloat + 1022.0f * toFloat + 0.0f + 1023.0f * toFloat) * 0.25f;
  EXPECT_EQ(softraster::tenBitChannel(resolvedWord, 0),
            static_cast<std::uint32_t>(softraster::detail::unorm16FromFloat(mean)) >> 6);
  EXPECT_EQ(softraster::tenBitChannel(resolvedWord, 1), 256u) << "four equal samples keep their value";
  EXPECT_EQ(softraster::tenBitChannel(resolvedWord, 3), 2u);
  EXPECT_EQ(softraster::tenBitChannel(resolvedWord, 0), 767u);
  // A pixel of four equal samples keeps its word (v / 1023 goes back to v on the 16-bit route).
  EXPECT_EQ(sameWord, word);
}

// The 10-bit format's conversions: the 16-bit UNORM of a float (clamped, NaN to 0), widening and
// narrowing that invert each other for every 10-bit and 2-bit value, and a plain store that
// truncates (0.9995 stores as 1023 where round(0.9995 * 1023) = 1022).
TEST(FramebufferCreate, TenBitConversionsInvertEachOther) {
  using namespace softraster::detail;
  EXPECT_EQ(unorm16FromFloat(0.0f), 0);
  EXPECT_EQ(unorm16FromFloat(1.0f), 65535);
  EXPECT_EQ(unorm16FromFloat(-2.0f), 0);
  EXPECT_EQ(unorm16FromFloat(7.0f), 65535);
  EXPECT_EQ(unorm16FromFloat(std::nanf("")), 0);
  EXPECT_EQ(unorm16FromFloat(0.5f), 32768) << "32767.5, half to even";
  for (std::uint32_t v = 0; v < 1024; ++v) ASSERT_EQ(narrowToTenBit(widenTenBit(v)), v) << v;
  for (std::uint32_t a = 0; a < 4; ++a) ASSERT_EQ(narrowToTwoBit(widenTwoBit(a)), a) << a;
  EXPECT_EQ(widenTwoBit(3), 65535);
  std::uint8_t pixel[4] = {0, 0, 0, 0};
  blendColour(pixel, {0.9995f, 0.0f, 1.0f, 0.4f},
              colourBlend(softraster::BlendState{}, softraster::ColourFormat::A2B10G10R10Unorm));
  std::uint32_t word;
  std::memcpy(&word, pixel, 4);
  EXPECT_EQ(word, softraster::packTenBit(1023, 0, 1023, 1));
}

// Halves as lavapipe converts them: widened exactly, narrowed toward zero (held at 65504 where
// nearest would round up or overflow, infinities kept, NaN quieted, denormals truncated).
TEST(FramebufferCreate, HalfConversionsRoundTowardZero) {
  using softraster::detail::floatFromHalf;
  using softraster::detail::halfFromFloatTowardZero;
  for (std::uint32_t h = 0; h < 0x10000; ++h) {
    const auto half = static_cast<std::uint16_t>(h);
    if ((h & 0x7c00u) == 0x7c00u && (h & 0x3ffu) != 0) continue;  // NaN: checked below
    ASSERT_EQ(halfFromFloatTowardZero(floatFromHalf(half)), half) << h;
  }
  EXPECT_EQ(halfFromFloatTowardZero(0.3f), 0x34cc) << "nearest would be 0x34cd";
  EXPECT_EQ(halfFromFloatTowardZero(-0.3f), 0xb4cc);
  EXPECT_EQ(halfFromFloatTowardZero(65519.0f), 0x7bff);
  EXPECT_EQ(halfFromFloatTowardZero(1e30f), 0x7bff);
  EXPECT_EQ(halfFromFloatTowardZero(-1e30f), 0xfbff);
  EXPECT_EQ(halfFromFloatTowardZero(std::numeric_limits<float>::infinity()), 0x7c00);
  EXPECT_EQ(halfFromFloatTowardZero(std::bit_cast<float>(0xffc00000u)), 0xfe00) << "the default NaN";
  EXPECT_EQ(halfFromFloatTowardZero(std::bit_cast<float>(0x7f800001u)), 0x7e00) << "a signalling NaN, quieted";
  EXPECT_EQ(halfFromFloatTowardZero(0x1p-24f * 2.9f), 0x0002) << "a denormal, truncated";
  EXPECT_EQ(halfFromFloatTowardZero(0x1p-25f), 0x0000);
  EXPECT_EQ(halfFromFloatTowardZero(-0x1p-30f), 0x8000);
  EXPECT_EQ(floatFromHalf(0x0001), 0x1p-24f);
  EXPECT_EQ(floatFromHalf(0x7bff), 65504.0f);
}

// Float targets: clear values as the format stores them (halves toward zero, floats as given),
// unclamped stores, and the resolve's mean.
TEST(FramebufferCreate, FloatTargetsClearStoreAndResolve) {
  auto half = Framebuffer::create(2, 1, DepthFormat::D32Sfloat, 4, softraster::ColourFormat::R16G16B16A16Sfloat);
  ASSERT_TRUE(half);
  ASSERT_EQ(half->colour().size(), std::size_t{2} * 4 * 8);
  half->clear({100000.0f, -2.5f, 0.3f, 3.0f}, 1.0f);
  std::uint16_t halves[4];
  std::memcpy(halves, half->colour().data() + 8 * half->sampleIndex(1, 0, 3), sizeof halves);
  EXPECT_EQ((std::array<int, 4>{halves[0], halves[1], halves[2], halves[3]}),
            (std::array<int, 4>{0x7bff, 0xc100, 0x34cc, 0x4200}));
  EXPECT_EQ(half->colourAt(1, 0, 3), (std::array<std::uint8_t, 4>{255, 0, 76, 255})) << "the byte view clamps";
  // Sample 2 of pixel 0 gets 7 in red: the mean of 65504, 65504, 7, 65504 is 49129.75, toward zero 49120.
  softraster::detail::blendColour(half->colour().data() + 8 * half->sampleIndex(0, 0, 2), {7.0f, -2.5f, 0.3f, 3.0f},
                                  softraster::detail::colourBlend(softraster::BlendState{}, half->colourFormat()));
  const Framebuffer resolved = half->resolve();
  std::memcpy(halves, resolved.colour().data(), sizeof halves);
  EXPECT_EQ(softraster::detail::floatFromHalf(halves[0]), 49120.0f);
  EXPECT_EQ(halves[1], 0xc100);
  auto f32 = Framebuffer::create(1, 1, DepthFormat::D32Sfloat, 1, softraster::ColourFormat::R32G32B32A32Sfloat);
  ASSERT_TRUE(f32);
  f32->clear({100000.0f, -2.5f, 0.3f, 3.0f}, 1.0f);
  float values[4];
  std::memcpy(values, f32->colour().data(), sizeof values);
  EXPECT_EQ((std::array<float, 4>{values[0], values[1], values[2], values[3]}),
            (std::array<float, 4>{100000.0f, -2.5f, 0.3f, 3.0f}));
}

// A shader with two colour outputs: Gradient's colour, and its complement.
struct TwoOutputs {
  using Vertex = Gradient::Vertex;
  using Uniforms = Gradient::Uniforms;
  static constexpr int kVaryings = 4;
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& v, float* out) { return Gradient::vertex(u, v, out); }
  template <class F>
  static softraster::ColourOutputs<F, 2> fragment(const Uniforms& u, const F* in) {
    const softraster::Vec4T<F> c = Gradient::fragment(u, in);
    return {{c, {F(1.0f) - c.x, F(1.0f) - c.y, F(1.0f) - c.z, c.w}}};
  }
};
static_assert(softraster::ShaderInterface<TwoOutputs>);
static_assert(softraster::colourOutputsOf<TwoOutputs>() == 2);
static_assert(!softraster::ShadesBatches<TwoOutputs>, "several outputs are shaded on the scalar path");

TEST(FramebufferCreate, SeveralColourAttachments) {
  using softraster::ColourFormat;
  EXPECT_EQ(Framebuffer::create(4, 4, DepthFormat::D32Sfloat, 1, std::span<const ColourFormat>{}).error(),
            "framebuffer colour attachments 0: must be 1..8");
  const std::vector<ColourFormat> nine(9, ColourFormat::R8G8B8A8Unorm);
  EXPECT_EQ(Framebuffer::create(4, 4, DepthFormat::D32Sfloat, 1, nine).error(),
            "framebuffer colour attachments 9: must be 1..8");
  const std::vector<ColourFormat> formats = {ColourFormat::R8G8B8A8Unorm, ColourFormat::R32G32B32A32Sfloat,
                                             ColourFormat::B8G8R8A8Unorm};
  auto fb = Framebuffer::create(3, 2, DepthFormat::D16Unorm, 4, formats);
  ASSERT_TRUE(fb) << fb.error();
  EXPECT_EQ(fb->colourAttachments(), 3u);
  EXPECT_EQ(fb->colourFormat(1), ColourFormat::R32G32B32A32Sfloat);
  EXPECT_EQ(fb->colour(1).size(), std::size_t{3} * 2 * 4 * 16);
  // Each attachment cleared to its own colour, converted by its own format; a missing one takes the last.
  const softraster::Vec4 clears[] = {{1, 0, 0, 1}, {-2.5f, 0.5f, 7, 1}};
  fb->clear(clears, 1.0f);
  EXPECT_EQ(fb->colourAt(2, 1, 3, 0), (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  float stored[4];
  std::memcpy(stored, fb->colour(1).data() + 16 * fb->sampleIndex(2, 1, 3), sizeof stored);
  EXPECT_EQ(stored[0], -2.5f);
  EXPECT_EQ(stored[2], 7.0f);
  EXPECT_EQ(fb->colourAt(0, 0, 0, 2), (std::array<std::uint8_t, 4>{0, 128, 255, 255}));  // -2.5 and 7 clamped
  const Framebuffer resolved = fb->resolve();
  EXPECT_EQ(resolved.colourAttachments(), 3u);
  EXPECT_EQ(resolved.samples(), 1u);
  std::memcpy(stored, resolved.colour(1).data(), sizeof stored);
  EXPECT_EQ(stored[1], 0.5f);
}

TEST(Context, WritesEachOutputToItsAttachment) {
  using softraster::ColourFormat;
  const softraster::Context context;
  const std::vector<ColourFormat> formats = {ColourFormat::R8G8B8A8Unorm, ColourFormat::R8G8B8A8Unorm};
  auto fb = Framebuffer::create(32, 32, DepthFormat::D32Sfloat, 1, formats);
  ASSERT_TRUE(fb);
  fb->clear({0, 0, 0, 0}, 1.0f);
  const std::vector<Gradient::Vertex> vertices = fan();
  softraster::PipelineState state;
  state.topology = softraster::Topology::TriangleStrip;
  state.rasterization.cullMode = softraster::CullMode::None;
  ASSERT_TRUE(context.draw<TwoOutputs>(state, TwoOutputs::Uniforms{}, vertices, *fb));
  std::size_t covered = 0;
  for (std::uint32_t y = 0; y < 32; ++y) {
    for (std::uint32_t x = 0; x < 32; ++x) {
      const auto a = fb->colourAt(x, y, 0, 0), b = fb->colourAt(x, y, 0, 1);
      if (a[3] == 0) continue;
      ++covered;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(int{a[static_cast<std::size_t>(c)]} + b[static_cast<std::size_t>(c)], 255, 1);
    }
  }
  EXPECT_GT(covered, 100u);
  // A one-output shader leaves attachment 1 undefined in Vulkan: refused, unless its writes are masked.
  const softraster::Status refused = context.draw<Gradient>(state, Gradient::Uniforms{}, vertices, *fb);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.message(), "colour attachment 1 has no fragment output (the shader writes 1), so Vulkan leaves its "
                               "colour undefined: give the shader an output for it or set its colorWriteMask to 0");
  state.moreBlend[0].colorWriteMask = 0;
  const std::vector<std::uint8_t> before = fb->colour(1);
  ASSERT_TRUE(context.draw<Gradient>(state, Gradient::Uniforms{}, vertices, *fb));
  EXPECT_EQ(fb->colour(1), before);
  state.moreBlend[0].colorBlendOp = static_cast<softraster::BlendOp>(9);
  EXPECT_EQ(context.draw<TwoOutputs>(state, TwoOutputs::Uniforms{}, vertices, *fb).message(),
            "unknown blend op (colour attachment 1)");
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
