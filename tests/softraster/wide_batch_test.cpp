// The fast path's 16-lane operations (fast/wide_batch.hpp, the runs of whole blocks drawn with
// AVX-512) against its 8-lane ones (fast/batch.hpp), lane by lane, over every class of float:
// plane evaluation, the depth clamp and conversion for each depth format, the depth test for
// each compare op, and colour packing (RGBA8 and BGRA8). Each 16-lane result must be, lane for
// lane, the bits the 8-lane form gives for the same inputs; the scenes then check the whole
// path against the scalar one (tests/crosscheck/fast_path_test.cpp).
#include <softraster/detail/fast/batch.hpp>
#include <softraster/detail/fast/wide_batch.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/state.hpp>

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#if SOFTRASTER_HAS_FAST_PATH && defined(SOFTRASTER_WIDE_TARGET)

namespace {

namespace fast = softraster::detail::fast;
using softraster::CompareOp;
using softraster::DepthFormat;
using softraster::detail::DepthRange;

constexpr int kLanes = 16;

// Floats of every class: NaNs, infinities, zeros, denormals, the ends of [0, 1] and their
// neighbours, then random bit patterns and random values in and around [0, 1].
std::vector<float> inputs() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  std::vector<float> v = {std::numeric_limits<float>::quiet_NaN(), -std::numeric_limits<float>::quiet_NaN(), kInf, -kInf,
                          0.0f, -0.0f, 1.0f, -1.0f, std::nextafter(1.0f, 2.0f), std::nextafter(1.0f, 0.0f),
                          std::nextafter(0.0f, 1.0f), std::nextafter(0.0f, -1.0f), std::numeric_limits<float>::min(),
                          2.0f, 0.5f, 1e30f, -1e30f, 4294967296.0f, -2147483648.0f, 16777215.0f, 65535.0f};
  for (int k = 0; k <= 255; ++k) {  // each byte's rounding tie and its neighbours
    const float tie = (static_cast<float>(k) + 0.5f) / 255.0f;
    v.insert(v.end(), {tie, std::nextafter(tie, 0.0f), std::nextafter(tie, 1.0f), static_cast<float>(k) / 255.0f});
  }
  std::mt19937 random(29);
  for (int i = 0; i < 30000; ++i) v.push_back(std::bit_cast<float>(static_cast<std::uint32_t>(random())));
  for (int i = 0; i < 30000; ++i) v.push_back(std::uniform_real_distribution<float>(-0.1f, 1.1f)(random));
  return v;
}

// The helpers that take or return a vector are compiled for AVX-512 like their callers: in the
// sanitizer build nothing is inlined, and a vector crossing between code with and without the
// target is passed in a register on one side and in memory on the other.

// 16 of `values` from `first` on (wrapping), one value per lane.
template <class V>
[[SOFTRASTER_WIDE_TARGET]] V lanesOf(const std::vector<float>& values, std::size_t first) {
  float lanes[kLanes];
  for (int l = 0; l < kLanes; ++l) lanes[l] = values[(first + static_cast<std::size_t>(l)) % values.size()];
  V v;
  static_assert(sizeof v == sizeof lanes);
  std::memcpy(&v, lanes, sizeof v);
  return v;
}

// Half h (lanes 8h to 8h + 7) of 16 lanes, as an 8-lane vector.
template <class Half, class Wide>
[[SOFTRASTER_WIDE_TARGET]] Half half(const Wide& w, int h) {
  Half out;
  std::memcpy(&out, reinterpret_cast<const char*>(&w) + h * sizeof out, sizeof out);
  return out;
}

template <class A, class B>
[[SOFTRASTER_WIDE_TARGET]] bool sameBytes(const A& a, const B& b) {
  static_assert(sizeof a == sizeof b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Lanes where the 16-lane plane evaluation, depth clamp and conversion to Format's storage differ
// from the 8-lane ones, for planes and pixel coordinates made of `values`, over depth ranges
// with ends in [0, 1].
template <DepthFormat Format>
[[SOFTRASTER_WIDE_TARGET, gnu::noinline]] int depthMismatches(const std::vector<float>& values) {
  const DepthRange ranges[] = {{0.0f, 1.0f}, {0.25f, 0.75f}, {0.0f, 0.0f}, {1.0f, 1.0f}, {0.5f, 0.5f}};
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); i += 5) {
    const DepthRange& range = ranges[i % std::size(ranges)];
    const fast::WideFloats a0 = lanesOf<fast::WideFloats>(values, i), dadx = lanesOf<fast::WideFloats>(values, i + 7);
    const fast::WideFloats dady = lanesOf<fast::WideFloats>(values, i + 13), offset = lanesOf<fast::WideFloats>(values, i + 3);
    // Pixel coordinates as the walk makes them: whole numbers, with a random value now and then.
    fast::WideFloats px = static_cast<float>(i % 4096) + fast::kWideLaneX, py = static_cast<float>(i % 2048) + fast::kWideLaneY;
    if (i % 3 == 0) px = lanesOf<fast::WideFloats>(values, i + 11);
    const fast::WidePlane wide{a0, dadx, dady};
    const fast::WideFloats z = fast::evaluateWide(wide, px, py) + offset;
    const fast::WideWords stored = fast::depthToStorageWide<Format>(fast::clampDepthWide(z, range));
    for (int h = 0; h < 2; ++h) {
      const fast::BatchPlane narrow{half<fast::Floats>(a0, h), half<fast::Floats>(dadx, h), half<fast::Floats>(dady, h)};
      const fast::Floats zNarrow = fast::evaluatePlane(narrow, half<fast::Floats>(px, h), half<fast::Floats>(py, h)) + half<fast::Floats>(offset, h);
      wrong += !sameBytes(half<fast::Floats>(z, h), zNarrow);
      wrong += !sameBytes(half<fast::Words>(stored, h), fast::depthToStorage<Format>(fast::clampDepth(zNarrow, range)));
    }
  }
  return wrong;
}

// Lanes where the 16-lane depth test differs from the 8-lane one, for every op, over stored and
// incoming depths made of `values` (equal ones too).
template <DepthFormat Format>
[[SOFTRASTER_WIDE_TARGET, gnu::noinline]] int depthTestMismatches(const std::vector<float>& values) {
  const CompareOp ops[] = {CompareOp::Never, CompareOp::Less, CompareOp::Equal, CompareOp::LessOrEqual,
                           CompareOp::Greater, CompareOp::NotEqual, CompareOp::GreaterOrEqual, CompareOp::Always};
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); i += 7) {
    fast::WideWords incoming = reinterpret_cast<fast::WideWords>(lanesOf<fast::WideFloats>(values, i));
    fast::WideWords stored = reinterpret_cast<fast::WideWords>(lanesOf<fast::WideFloats>(values, i + (i % 2 == 0 ? 0 : 5)));
    if constexpr (Format != DepthFormat::D32Sfloat) {  // storage of a UNORM format: 16 or 24 bits
      const std::uint32_t bits = Format == DepthFormat::D16Unorm ? 0xffffu : 0xffffffu;
      incoming &= bits;
      stored &= bits;
    }
    for (const CompareOp op : ops) {
      const unsigned passes = fast::depthTestPassesWide<Format>(op, incoming, stored);
      for (int h = 0; h < 2; ++h) {
        const unsigned narrow = fast::maskBits(fast::depthTestPasses<Format>(op, half<fast::Words>(incoming, h), half<fast::Words>(stored, h)));
        wrong += std::popcount(((passes >> (8 * h)) & 0xffu) ^ narrow);
      }
    }
  }
  return wrong;
}

// Pixels whose 16-lane packed colour differs from the 8-lane packing of the same channels, in
// RGBA8 and BGRA8 order: the low 256 bits are lanes 0-7's pixels, the high 256 bits lanes 8-15's.
[[SOFTRASTER_WIDE_TARGET, gnu::noinline]] int packMismatches(const std::vector<float>& values) {
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); i += kLanes) {
    softraster::Vec4T<softraster::FloatBatch16> c;
    c.x = softraster::FloatBatch16(lanesOf<fast::WideFloats>(values, i));
    c.y = softraster::FloatBatch16(lanesOf<fast::WideFloats>(values, i + 97));
    c.z = softraster::FloatBatch16(lanesOf<fast::WideFloats>(values, i + 194));
    c.w = softraster::FloatBatch16(lanesOf<fast::WideFloats>(values, i + 291));
    for (const bool swap : {false, true}) {
      const __m512i packed = fast::packColourWide(c, swap);
      for (int h = 0; h < 2; ++h) {
        const softraster::Vec4T<softraster::FloatBatch> narrow{
            softraster::FloatBatch(half<fast::Floats>(c.x.native(), h)), softraster::FloatBatch(half<fast::Floats>(c.y.native(), h)),
            softraster::FloatBatch(half<fast::Floats>(c.z.native(), h)), softraster::FloatBatch(half<fast::Floats>(c.w.native(), h))};
        const fast::Words expected = fast::packColour(narrow, swap);
        const fast::Words got = half<fast::Words>(packed, h);
        for (int l = 0; l < 8; ++l) wrong += got[l] != expected[l];
      }
    }
  }
  return wrong;
}

bool cpuHasAvx512() { return fast::cpuShadesWidePairs(); }

}  // namespace

TEST(WideBatch, PlanesAndDepthStorageAreTheBatchOnes) {
  if (!cpuHasAvx512()) GTEST_SKIP() << "no AVX-512 F, VL, BW and DQ";
  const std::vector<float> values = inputs();
  EXPECT_EQ(depthMismatches<DepthFormat::D32Sfloat>(values), 0);
  EXPECT_EQ(depthMismatches<DepthFormat::X8D24UnormPack32>(values), 0);
  EXPECT_EQ(depthMismatches<DepthFormat::D16Unorm>(values), 0);
}

TEST(WideBatch, DepthTestsAreTheBatchOnesForEveryOp) {
  if (!cpuHasAvx512()) GTEST_SKIP() << "no AVX-512 F, VL, BW and DQ";
  const std::vector<float> values = inputs();
  EXPECT_EQ(depthTestMismatches<DepthFormat::D32Sfloat>(values), 0);
  EXPECT_EQ(depthTestMismatches<DepthFormat::X8D24UnormPack32>(values), 0);
  EXPECT_EQ(depthTestMismatches<DepthFormat::D16Unorm>(values), 0);
}

TEST(WideBatch, PackedColoursAreTheBatchOnes) {
  if (!cpuHasAvx512()) GTEST_SKIP() << "no AVX-512 F, VL, BW and DQ";
  EXPECT_EQ(packMismatches(inputs()), 0);
}

#else

TEST(WideBatch, PlanesAndDepthStorageAreTheBatchOnes) { GTEST_SKIP() << "no AVX-512 fast path in this build"; }

#endif
