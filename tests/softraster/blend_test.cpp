// Blending on RGBA8: the 8-bit multiply is exact, the scalar stage's arithmetic on known values,
// every logic op on known bytes, and the fast path's SIMD blend is the scalar one byte for byte
// for every factor, op, logic op and mask.
#include <softraster/detail/fast/batch.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/state.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>

namespace {

using softraster::BlendFactor;
using softraster::BlendOp;
using softraster::BlendState;
using softraster::detail::ColourBlend;

constexpr int kFactors = static_cast<int>(BlendFactor::SrcAlphaSaturate) + 1;
constexpr int kOps = static_cast<int>(BlendOp::Max) + 1;

// The scalar stage's output for source bytes s over destination bytes d.
std::array<std::uint8_t, 4> scalarBlend(const std::array<std::uint8_t, 4>& s, std::array<std::uint8_t, 4> d,
                                        const ColourBlend& blend) {
  const softraster::Vec4 c{s[0] / 255.0f, s[1] / 255.0f, s[2] / 255.0f, s[3] / 255.0f};
  softraster::detail::blendColour(d.data(), c, blend);
  return d;
}

BlendState blendOf(BlendFactor sc, BlendFactor dc, BlendOp oc, BlendFactor sa, BlendFactor da, BlendOp oa) {
  BlendState b;
  b.enable = true;
  b.srcColorBlendFactor = sc;
  b.dstColorBlendFactor = dc;
  b.colorBlendOp = oc;
  b.srcAlphaBlendFactor = sa;
  b.dstAlphaBlendFactor = da;
  b.alphaBlendOp = oa;
  b.blendConstants[0] = 0.3f;
  b.blendConstants[1] = 0.55f;
  b.blendConstants[2] = 0.8f;
  b.blendConstants[3] = 0.45f;
  return b;
}

}  // namespace

// lp_build_mul_norm's comment calls the rounded geometric series exact; it is not quite: 24
// ordered pairs of bytes, each with x * f = 128 (mod 255) (x * f / 255 = k + 0.502), give k
// (152 * 229 = 136.502 -> 136); lavapipe's own output has them (scene blend_products).
TEST(Blend, Unorm8MultiplyIsTheRoundedProductBut24Pairs) {
  int oneLess = 0;
  for (int x = 0; x < 256; ++x) {
    for (int f = 0; f < 256; ++f) {
      const int rounded = (2 * x * f + 255) / 510;  // x * f / 255 rounded (never a tie: 255 is odd)
      const int product = softraster::detail::mulUnorm8(x, f);
      if (product != rounded) {
        ASSERT_EQ(product, rounded - 1) << x << " * " << f;
        ASSERT_EQ(x * f % 255, 128) << x << " * " << f;
        ++oneLess;
      }
    }
  }
  EXPECT_EQ(oneLess, 24);
  EXPECT_EQ(softraster::detail::mulUnorm8(152, 229), 136);
}

TEST(Blend, ScalarArithmeticOnKnownValues) {
  const std::array<std::uint8_t, 4> s = {200, 100, 50, 64}, d = {10, 120, 240, 180};
  // SRC_ALPHA / ONE_MINUS_SRC_ALPHA: 200*64/255 = 50.2 -> 50, 10*191/255 = 7.49 -> 7.
  ColourBlend over = softraster::detail::colourBlend(
      blendOf(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendOp::Add, BlendFactor::SrcAlpha,
              BlendFactor::OneMinusSrcAlpha, BlendOp::Add));
  EXPECT_EQ(scalarBlend(s, d, over)[0], 50 + 7);
  // SRC_ALPHA_SATURATE: colour factor min(64, 255 - 180) = 64, alpha factor 255.
  ColourBlend saturate = softraster::detail::colourBlend(blendOf(BlendFactor::SrcAlphaSaturate, BlendFactor::Zero,
                                                                 BlendOp::Add, BlendFactor::SrcAlphaSaturate,
                                                                 BlendFactor::Zero, BlendOp::Add));
  EXPECT_EQ(scalarBlend(s, d, saturate), (std::array<std::uint8_t, 4>{50, 25, 13, 64}));
  // MIN and MAX ignore the factors; SUBTRACT saturates at 0; REVERSE_SUBTRACT is d - s.
  ColourBlend minMax = softraster::detail::colourBlend(
      blendOf(BlendFactor::Zero, BlendFactor::Zero, BlendOp::Min, BlendFactor::Zero, BlendFactor::Zero, BlendOp::Max));
  EXPECT_EQ(scalarBlend(s, d, minMax), (std::array<std::uint8_t, 4>{10, 100, 50, 180}));
  ColourBlend subtract = softraster::detail::colourBlend(
      blendOf(BlendFactor::One, BlendFactor::One, BlendOp::Subtract, BlendFactor::One, BlendFactor::One,
              BlendOp::ReverseSubtract));
  EXPECT_EQ(scalarBlend(s, d, subtract), (std::array<std::uint8_t, 4>{190, 0, 0, 116}));
  // The constant colour is rounded to bytes first: 0.3 * 255 = 76.5 -> 76 (half to even).
  ColourBlend constant = softraster::detail::colourBlend(blendOf(BlendFactor::ConstantColor, BlendFactor::Zero,
                                                                 BlendOp::Add, BlendFactor::One, BlendFactor::Zero,
                                                                 BlendOp::Add));
  EXPECT_EQ(constant.constants[0], 76);
  EXPECT_EQ(scalarBlend(s, d, constant)[0], softraster::detail::mulUnorm8(200, 76));
  // The write mask keeps the destination's bytes, with blending off too.
  BlendState masked;
  masked.colorWriteMask = softraster::kColourG | softraster::kColourA;
  EXPECT_EQ(scalarBlend(s, d, softraster::detail::colourBlend(masked)), (std::array<std::uint8_t, 4>{10, 100, 240, 64}));
}

// Every VkLogicOp on s = 0xCA (1100 1010) over d = 0xA6 (1010 0110), worked out by hand; a write
// mask keeps the destination's other bytes, and blendEnable beside a logic op is ignored.
TEST(Blend, LogicOpsOnKnownBytes) {
  using softraster::LogicOp;
  const std::array<std::uint8_t, 16> expected = {0x00, 0x82, 0x48, 0xCA, 0x24, 0xA6, 0x6C, 0xEE,
                                                 0x11, 0x93, 0x59, 0xDB, 0x35, 0xB7, 0x7D, 0xFF};
  for (int op = 0; op < 16; ++op) {
    for (bool enable : {false, true}) {
      BlendState b = blendOf(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendOp::Add, BlendFactor::One,
                             BlendFactor::One, BlendOp::Add);
      b.enable = enable;
      b.logicOpEnable = true;
      b.logicOp = LogicOp(op);
      const auto out = scalarBlend({0xCA, 0xCA, 0xCA, 0xCA}, {0xA6, 0xA6, 0xA6, 0xA6}, softraster::detail::colourBlend(b));
      for (int c = 0; c < 4; ++c) EXPECT_EQ(out[static_cast<std::size_t>(c)], expected[static_cast<std::size_t>(op)]) << "op " << op;
      b.colorWriteMask = softraster::kColourR | softraster::kColourB;
      const auto masked = scalarBlend({0xCA, 0xCA, 0xCA, 0xCA}, {0xA6, 0xA6, 0xA6, 0xA6}, softraster::detail::colourBlend(b));
      EXPECT_EQ(masked, (std::array<std::uint8_t, 4>{expected[static_cast<std::size_t>(op)], 0xA6,
                                                     expected[static_cast<std::size_t>(op)], 0xA6}))
          << "op " << op;
    }
  }
}

#if SOFTRASTER_HAS_FAST_PATH

namespace {

// The fast path's blend of eight packed pixels.
[[SOFTRASTER_FAST_TARGET]] void fastBlend(const std::uint32_t* source, const std::uint32_t* destination,
                                          const ColourBlend& blend, std::uint32_t* out) {
  namespace fast = softraster::detail::fast;
  const fast::Words s = fast::loadBlock(source, 4, 0xffu), d = fast::loadBlock(destination, 4, 0xffu);
  fast::storeBlock(out, 4, 0xffu, fast::blendColour(s, d, blend));
}

}  // namespace

TEST(Blend, FastPathIsTheScalarBlendForEveryFactorOpAndMask) {
  if (!softraster::detail::fast::cpuRunsFastPath()) GTEST_SKIP() << "no AVX2 and FMA";
  std::mt19937 random(9);
  std::uint32_t source[8], destination[8], out[8];
  const auto check = [&](const BlendState& state) {
    const ColourBlend blend = softraster::detail::colourBlend(state);
    for (auto& v : source) v = random();
    for (auto& v : destination) v = random();
    source[0] = 0xffffffffu;  // and the extremes
    destination[1] = 0;
    fastBlend(source, destination, blend, out);
    for (int lane = 0; lane < 8; ++lane) {
      std::array<std::uint8_t, 4> s, d;
      for (int c = 0; c < 4; ++c) {
        s[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(source[lane] >> (8 * c));
        d[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(destination[lane] >> (8 * c));
      }
      const auto expected = scalarBlend(s, d, blend);
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(static_cast<std::uint8_t>(out[lane] >> (8 * c)), expected[static_cast<std::size_t>(c)])
            << "lane " << lane << " channel " << c << " factors " << int(state.srcColorBlendFactor) << "/"
            << int(state.dstColorBlendFactor) << " " << int(state.srcAlphaBlendFactor) << "/"
            << int(state.dstAlphaBlendFactor) << " ops " << int(state.colorBlendOp) << "/" << int(state.alphaBlendOp)
            << " mask " << int(state.colorWriteMask) << " enable " << state.enable;
      }
    }
  };
  for (int sc = 0; sc < kFactors; ++sc) {
    for (int dc = 0; dc < kFactors; ++dc) {
      for (int op = 0; op < kOps; ++op) {
        // Alpha factors and op differ from the colour ones.
        check(blendOf(BlendFactor(sc), BlendFactor(dc), BlendOp(op), BlendFactor((sc + 5) % kFactors),
                      BlendFactor((dc + 11) % kFactors), BlendOp((op + 2) % kOps)));
        check(blendOf(BlendFactor(sc), BlendFactor(dc), BlendOp(op), BlendFactor(sc), BlendFactor(dc), BlendOp(op)));
      }
    }
  }
  for (int mask = 0; mask < 16; ++mask) {
    for (bool enable : {false, true}) {
      BlendState b = blendOf(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendOp::Add, BlendFactor::One,
                             BlendFactor::OneMinusSrcAlpha, BlendOp::Add);
      b.enable = enable;
      b.colorWriteMask = static_cast<std::uint8_t>(mask);
      check(b);
      for (int op = 0; op < 16; ++op) {  // a logic op instead of blending, whatever enable says
        b.logicOpEnable = true;
        b.logicOp = softraster::LogicOp(op);
        check(b);
        b.logicOpEnable = false;
      }
    }
  }
}

#endif
