// FloatBatch's lane-wise primitives (simd.hpp: sqrt, fma, floor) give each lane exactly the bits
// of their float counterparts (std::sqrt, std::fma, std::floor), over random bit patterns (NaN,
// infinities, denormals, negatives) and the edge cases, compiled both ways a batch runs: flattened
// into an AVX2 + FMA function, as the fast path does, and as baseline x86-64 code (SSE halves), as
// the scalar path's quad shading and the sanitizer build run it. FloatBatchPair's operations give
// each half the bits of the same operation on a FloatBatch, and FloatBatch16's (the fast path's
// AVX-512 block pairs, where the CPU has it) each lane the float operation's bits.
#include <softraster/detail/fast/batch.hpp>
#include <softraster/simd.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace {

using softraster::FloatBatch;
using softraster::FloatBatchPair;
using softraster::kBatchLanes;

bool sameBits(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;  // which NaN comes out is not part of the contract
  return std::memcmp(&a, &b, sizeof a) == 0;
}

std::vector<float> inputs() {
  std::vector<float> values = {0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 1.5f, -1.5f, 2.5f, -2.5f, 0.99999994f,
                               -0.99999994f, 8388607.5f, -8388607.5f, 8388608.0f, -8388608.0f, 16777217.0f,
                               1e30f, -1e30f, std::numeric_limits<float>::denorm_min(),
                               -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                               std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
                               std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::quiet_NaN(), -126.99999f, 127.99999f, 128.0f};
  std::mt19937 random(7);
  for (int i = 0; i < 200000; ++i) {
    const std::uint32_t bits = random();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    values.push_back(f);
    values.push_back(static_cast<float>(static_cast<std::int32_t>(random() % 2000001) - 1000000) / 1024.0f);
  }
  while (values.size() % (3 * kBatchLanes) != 0) values.push_back(1.0f);
  return values;
}

// Lanes that differ from the float functions, for the batches made of `values`, three at a time.
template <class Context>
int mismatches(const std::vector<float>& values, Context) {
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); i += 3 * kBatchLanes) {
    const float* a = values.data() + i;
    const float* b = a + kBatchLanes;
    const float* c = b + kBatchLanes;
    const FloatBatch x = FloatBatch::load(a), y = FloatBatch::load(b), z = FloatBatch::load(c);
    const FloatBatch root = sqrt(x), fused = fma(x, y, z), down = floor(x);
    for (int k = 0; k < kBatchLanes; ++k) {
      wrong += !sameBits(root[k], std::sqrt(a[k]));
      wrong += !sameBits(fused[k], std::fma(a[k], b[k], c[k]));
      wrong += !sameBits(down[k], std::floor(a[k]));
    }
  }
  return wrong;
}

struct Avx2 {};
struct Baseline {};

[[gnu::target("avx2,fma"), gnu::flatten, gnu::noinline]] int avx2Mismatches(const std::vector<float>& values) {
  return mismatches(values, Avx2{});
}
[[gnu::flatten, gnu::noinline]] int baselineMismatches(const std::vector<float>& values) {
  return mismatches(values, Baseline{});
}

TEST(FloatBatchPrimitives, BaselineCodeGivesTheFloatFunctionsBits) { EXPECT_EQ(baselineMismatches(inputs()), 0); }

TEST(FloatBatchPrimitives, Avx2CodeGivesTheFloatFunctionsBits) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "no AVX2 + FMA";
  EXPECT_EQ(avx2Mismatches(inputs()), 0);
}

// Halves of BatchPair<Half> results (FloatBatchPair, FloatBatch16Pair) that differ from the Half
// operation on that half, for the pairs of three batches (the low half from x, y, z, the high half
// from the same three in another order, so the halves differ) and a splat of s.
template <class Half>
int pairHalvesMismatches(const Half& x, const Half& y, const Half& z, float s) {
  using Pair = softraster::BatchPair<Half>;
  int wrong = 0;
  const auto check = [&](const Pair& pair, const Half& low, const Half& high) {
    for (int k = 0; k < Half::kLanes; ++k) wrong += !sameBits(pair.low[k], low[k]) + !sameBits(pair.high[k], high[k]);
  };
  const Pair a(x, z), b(y, x), c(z, y);
  check(a + b, x + y, z + x);
  check(a - b, x - y, z - x);
  check(a * b, x * y, z * x);
  check(a / b, x / y, z / x);
  check(-a, -x, -z);
  check(sseMin(a, b), sseMin(x, y), sseMin(z, x));
  check(sseMax(a, b), sseMax(x, y), sseMax(z, x));
  check(sqrt(a), sqrt(x), sqrt(z));
  check(fma(a, b, c), fma(x, y, z), fma(z, x, y));
  check(floor(a), floor(x), floor(z));
  Pair d = a;
  d += b;
  d *= c;
  d -= a;
  d /= b;
  check(d, ((x + y) * z - x) / y, ((z + x) * y - z) / x);
  check(Pair(s), Half(s), Half(s));
  return wrong;
}

[[gnu::target("avx2,fma"), gnu::flatten, gnu::noinline]] int pairMismatches(const std::vector<float>& values) {
  int wrong = 0;
  for (std::size_t i = 0; i < values.size(); i += 3 * kBatchLanes) {
    const FloatBatch x = FloatBatch::load(values.data() + i), y = FloatBatch::load(values.data() + i + kBatchLanes),
                     z = FloatBatch::load(values.data() + i + 2 * kBatchLanes);
    wrong += pairHalvesMismatches(x, y, z, values[i]);
  }
  return wrong;
}

TEST(FloatBatchPair, EachHalfIsTheBatchOperation) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "no AVX2 + FMA";
  EXPECT_EQ(pairMismatches(inputs()), 0);
}

// Lanes of FloatBatch16 results (the fast path's AVX-512 block pairs) that differ from the float
// operation, for 16-lane batches made of `values`, three at a time, and halves of FloatBatch16Pair
// results that differ from the FloatBatch16 operation; compiled as the fast path's wide functions
// are (AVX-512, flattened).
[[SOFTRASTER_WIDE_TARGET, gnu::flatten, gnu::noinline]] int wideMismatches(const std::vector<float>& values) {
  using softraster::FloatBatch16;
  constexpr int kLanes = 2 * kBatchLanes;
  int wrong = 0;
  std::vector<float> padded = values;
  while (padded.size() % (3 * kLanes) != 0) padded.push_back(1.0f);
  for (std::size_t i = 0; i < padded.size(); i += 3 * kLanes) {
    const float* a = padded.data() + i;
    const float* b = a + kLanes;
    const float* c = b + kLanes;
    const FloatBatch16 x = FloatBatch16::load(a), y = FloatBatch16::load(b), z = FloatBatch16::load(c);
    const FloatBatch16 root = sqrt(x), fused = fma(x, y, z), down = floor(x), sum = x + y, difference = x - y, product = x * y,
                       quotient = x / y, negated = -x, smaller = sseMin(x, y), larger = sseMax(x, y);
    for (int k = 0; k < kLanes; ++k) {
      wrong += !sameBits(root[k], std::sqrt(a[k]));
      wrong += !sameBits(fused[k], std::fma(a[k], b[k], c[k]));
      wrong += !sameBits(down[k], std::floor(a[k]));
      wrong += !sameBits(sum[k], a[k] + b[k]) + !sameBits(difference[k], a[k] - b[k]) + !sameBits(product[k], a[k] * b[k]);
      wrong += !sameBits(quotient[k], a[k] / b[k]) + !sameBits(negated[k], -a[k]);
      wrong += !sameBits(smaller[k], softraster::sseMin(a[k], b[k])) + !sameBits(larger[k], softraster::sseMax(a[k], b[k]));
    }
    // FloatBatch16Pair (two pairs of blocks): each half the FloatBatch16 operation on it.
    wrong += pairHalvesMismatches(x, y, z, a[0]);
  }
  return wrong;
}

TEST(FloatBatch16, EachLaneIsTheFloatOperation) {
  if (!softraster::detail::fast::cpuShadesWidePairs()) GTEST_SKIP() << "no AVX-512 F, VL, BW and DQ";
  EXPECT_EQ(wideMismatches(inputs()), 0);
}

TEST(FloatBatchPrimitives, FloorKeepsTheSignOfZero) {
  const FloatBatch f = floor(FloatBatch(-0.0f)), g = floor(FloatBatch(0.25f)), h = floor(FloatBatch(-0.25f));
  EXPECT_TRUE(std::signbit(f[0]));
  EXPECT_FALSE(std::signbit(g[0]));
  EXPECT_EQ(h[0], -1.0f);
}

}  // namespace
