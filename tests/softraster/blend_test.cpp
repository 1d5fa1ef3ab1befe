// Blending on RGBA8: the 8-bit multiply is exact, the scalar stage's arithmetic on known values,
// every logic op on known bytes, and the fast path's SIMD blend is the scalar one byte for byte
// for every factor, op, logic op and mask; so is its packing of float colours into RGBA8 (and
// BGRA8) for every class of float, NaN and infinities included.
#include <softraster/detail/fast/batch.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/state.hpp>

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

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

// The fast path's packing of eight lanes of channels (channels[c][lane]).
[[SOFTRASTER_FAST_TARGET]] void fastPack(const float (&channels)[4][8], bool swapRedBlue, std::uint32_t* out) {
  namespace fast = softraster::detail::fast;
  softraster::Vec4T<softraster::FloatBatch> c;
  c.x = softraster::FloatBatch::load(channels[0]);
  c.y = softraster::FloatBatch::load(channels[1]);
  c.z = softraster::FloatBatch::load(channels[2]);
  c.w = softraster::FloatBatch::load(channels[3]);
  fast::storeBlock(out, 4, 0xffu, fast::packColour(c, swapRedBlue));
}

}  // namespace

// packColour leaves the clamp below 0 to saturating packs: NaN, -inf, -0, negatives tiny and huge,
// the rounding ties around every byte, values just over 1, +inf and random bit patterns of every
// exponent must all give unorm8FromFloat's byte, in RGBA8 and BGRA8 order.
TEST(Blend, FastPathPacksColoursAsTheScalarConversion) {
  if (!softraster::detail::fast::cpuRunsFastPath()) GTEST_SKIP() << "no AVX2 and FMA";
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(),
                               kInf, -kInf, 0.0f, -0.0f, 1.0f, -1.0f, std::nextafter(1.0f, 2.0f), 2.0f, 1e30f, -1e30f,
                               std::numeric_limits<float>::denorm_min(), -std::numeric_limits<float>::denorm_min(),
                               -0.5f / 255.0f, std::nextafter(-0.5f / 255.0f, 0.0f), std::nextafter(-0.5f / 255.0f, -1.0f),
                               -1.5f / 255.0f, 4294967296.0f, -2147483648.0f};
  for (int k = 0; k <= 255; ++k) {  // each byte's tie and its neighbours
    const float tie = (static_cast<float>(k) + 0.5f) / 255.0f;
    values.insert(values.end(), {tie, std::nextafter(tie, 0.0f), std::nextafter(tie, 1.0f), static_cast<float>(k) / 255.0f});
  }
  std::mt19937 random(17);
  for (int i = 0; i < 20000; ++i) values.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(random())));
  for (int i = 0; i < 20000; ++i) values.push_back(std::uniform_real_distribution<float>(-0.1f, 1.1f)(random));
  float channels[4][8];
  std::uint32_t out[8];
  for (std::size_t first = 0; first < values.size(); first += 8) {
    for (int c = 0; c < 4; ++c) {
      for (int lane = 0; lane < 8; ++lane) {  // each channel sees every value, in a different lane
        channels[c][lane] = values[(first + static_cast<std::size_t>(lane) + 97 * static_cast<std::size_t>(c)) % values.size()];
      }
    }
    for (const bool swap : {false, true}) {
      fastPack(channels, swap, out);
      for (int lane = 0; lane < 8; ++lane) {
        for (int c = 0; c < 4; ++c) {
          const int stored = swap && c != 1 && c != 3 ? 2 - c : c;  // BGRA8 swaps red and blue
          ASSERT_EQ(static_cast<std::uint8_t>(out[lane] >> (8 * stored)), softraster::detail::unorm8FromFloat(channels[c][lane]))
              << "value " << channels[c][lane] << " (bits 0x" << std::hex << std::bit_cast<std::uint32_t>(channels[c][lane])
              << std::dec << ") lane " << lane << " channel " << c << (swap ? " swapped" : "");
        }
      }
    }
  }
}

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
