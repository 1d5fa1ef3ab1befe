// The GLSL built-in functions the shader twins call, computed as lavapipe computes them (Mesa
// 22.3.6: SPIR-V lowering in compiler/spirv/vtn_glsl450.c and nir_builtin_builder.h, code
// generation in gallium/auxiliary/gallivm/lp_bld_arit.c; docs/lavapipe-rules.md, "Shader
// arithmetic"), so a twin gives the GLSL's bits. Each is written over the twin's float type F
// (float; softraster::FloatBatch, one value per lane; or FloatBatchPair, two batches).
//   dot(a, b)         (a.x*b.x + a.y*b.y) + a.z*b.z, every step rounded
//   length(v)         sqrt(dot(v, v))
//   normalize(v)      v / length(v), a real division per component
//   reflect(i, n)     i - n * (dot(i, n) * 2)
//   cross(a, b)       a.yzx * b.zxy - a.zxy * b.yzx, each product rounded
//   maxConstant(x, c) max(x, c) with c a constant: SSE maxps(x, c) (a NaN x gives c)
//   selectLessEqual(a, b, x, y)  a <= b ? x : y, the compare ordered (false with a NaN)
//   pow(x, y)         exp2(log2_safe(x) * y), 0 where x == 0 or x is NaN; gallivm's polynomials
// Each has a float and a FloatBatch form; the batch form is vector code throughout (FloatBatch's
// sqrt, fma and floor, integer lanes for the exponent bits), step for step the float form, so
// every lane gets the float form's bits (tests/crosscheck/lighting_test.cpp checks it). The pair
// form is the batch form on each half (written over F, or pow and selectLessEqual's own, for
// FloatBatchPair and FloatBatch16Pair alike).
// FloatBatch16 (16 lanes, the fast path's AVX-512 block pairs) takes the F-generic ones as they
// are, and exp2, log2Safe and pow in AVX-512 code of their own: the batch forms' steps, with
// their comparisons, truncation and selects as AVX-512 intrinsics (GCC 12 scalarises those
// written over vector extensions outside AVX-512 code, simd.hpp). selectLessEqual has no 16-lane
// form: no shader that pairs blocks calls it.
// The polynomials use fmuladd as gallivm does on a CPU with FMA (every x86-64 CPU this project
// targets has it); a lavapipe on a CPU without FMA rounds them differently.
// Deliberately absent: denormal flushing (lavapipe's shaders run with DAZ/FTZ; the lit scenes
// never produce denormals), and every built-in no twin calls yet.
#pragma once

#include <softraster/simd.hpp>

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>

namespace shaders::glsl {

template <class F>
struct Vec3T {
  F x{}, y{}, z{};
};

template <class F>
Vec3T<F> operator+(const Vec3T<F>& a, const Vec3T<F>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class F>
Vec3T<F> operator-(const Vec3T<F>& a, const Vec3T<F>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class F>
Vec3T<F> operator-(const Vec3T<F>& a) {
  return {-a.x, -a.y, -a.z};
}
template <class F>
Vec3T<F> operator*(const Vec3T<F>& a, const Vec3T<F>& b) {
  return {a.x * b.x, a.y * b.y, a.z * b.z};
}
template <class F>
Vec3T<F> operator*(const Vec3T<F>& a, const F& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class F>
Vec3T<F> operator/(const Vec3T<F>& a, const F& s) {
  return {a.x / s, a.y / s, a.z / s};
}

// ---- a <= b ? x : y (an ordered compare: false where a or b is NaN) ----

inline float selectLessEqual(float a, float b, float x, float y) { return a <= b ? x : y; }
inline softraster::FloatBatch selectLessEqual(softraster::FloatBatch a, softraster::FloatBatch b,
                                              softraster::FloatBatch x, softraster::FloatBatch y) {
  return softraster::FloatBatch(a.native() <= b.native() ? x.native() : y.native());
}

// ---- sqrt: IEEE (llvm.sqrt) ----

// softraster::sqrt for a FloatBatch (simd.hpp), found by argument-dependent lookup.
inline float sqrt(float x) { return std::sqrt(x); }

// ---- Geometric functions ----

template <class F>
F dot(const Vec3T<F>& a, const Vec3T<F>& b) {
  return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

template <class F>
F length(const Vec3T<F>& v) {
  return sqrt(dot(v, v));
}

template <class F>
Vec3T<F> normalize(const Vec3T<F>& v) {
  return v / length(v);
}

// nir_cross3: ffma(a.yzx, b.zxy, -(a.zxy * b.yzx)), the ffma split (lower_ffma32) into a
// rounded product and an add.
template <class F>
Vec3T<F> cross(const Vec3T<F>& a, const Vec3T<F>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class F>
Vec3T<F> reflect(const Vec3T<F>& i, const Vec3T<F>& n) {
  return i - n * (dot(i, n) * F(2.0f));
}

// max(x, c) for a constant c, which NIR knows is a number: SSE maxps with x first, so a NaN x
// gives c, and max(-0, +0) gives +0.
template <class F>
F maxConstant(const F& x, float c) {
  using softraster::sseMax;  // the float overload; FloatBatch's is found by argument-dependent lookup
  return sseMax(x, F(c));
}

// ---- exp2, log2_safe and pow (lp_build_exp2, lp_build_log2_approx, lp_build_pow) ----

namespace detail {

// lp_build_polynomial: x2 = x*x; even and odd coefficients each walked from the highest index
// down, the first taken as it is, each later one fmuladd(x2, value, coeff); then
// fmuladd(odd, x, even). Coefficients are rounded to float. The table is a template argument so
// the walk is unrolled with every coefficient a constant: inlined into the fast path's pixel
// loop, a loop over a reference to the table stayed a run-time loop that read, converted and
// broadcast each double per block (the Blinn-Phong quad took 7% longer).
template <const auto& Coefficients, class F>
F polynomial(F x) {
  using std::fma;  // fma(float...) or FloatBatch's, found by argument-dependent lookup
  constexpr std::size_t kCount = std::size(Coefficients);
  static_assert(kCount >= 1);
  // Coefficients[i] as a float constant.
  const auto coefficient = []<std::size_t I>(std::integral_constant<std::size_t, I>) {
    constexpr float kValue = static_cast<float>(Coefficients[I]);
    return F(kValue);
  };
  // value, then value = fmuladd(x2, value, Coefficients[Top - 2k]) for k = 1, 2, ... (one per K).
  const auto walkDown = [&]<std::size_t Top, std::size_t... K>(F value, const F& x2, std::index_sequence<K...>) {
    ((value = fma(x2, value, coefficient(std::integral_constant<std::size_t, Top - 2 * (K + 1)>{}))), ...);
    return value;
  };
  const F x2 = x * x;
  constexpr std::size_t kTopEven = (kCount - 1) % 2 == 0 ? kCount - 1 : kCount - 2;
  const F even = walkDown.template operator()<kTopEven>(coefficient(std::integral_constant<std::size_t, kTopEven>{}), x2,
                                                        std::make_index_sequence<kTopEven / 2>{});
  if constexpr (kCount == 1) {
    return even;
  } else {
    constexpr std::size_t kTopOdd = (kCount - 1) % 2 == 1 ? kCount - 1 : kCount - 2;
    const F odd = walkDown.template operator()<kTopOdd>(coefficient(std::integral_constant<std::size_t, kTopOdd>{}), x2,
                                                        std::make_index_sequence<(kTopOdd - 1) / 2>{});
    return fma(odd, x, even);
  }
}

// lp_build_exp2_polynomial, EXP_POLY_DEGREE 5: 2^x on [0, 1).
inline constexpr double kExp2Polynomial[] = {1.000000000000000000000, 0.693153073200168932794,
                                             0.240153617044375388211, 0.0558263180532956664775,
                                             0.00898934009049466391101, 0.00187757667519147912699};
// lp_build_log2_polynomial, LOG_POLY_DEGREE 4.
inline constexpr double kLog2Polynomial[] = {2.88539009343309178325, 0.961791550404184197881,
                                             0.577440339438736392009, 0.403343858251329912514,
                                             0.406718052498846252698};

// cvttps2dq: truncation, 0x80000000 for NaN and out-of-range values.
inline std::int32_t truncateToInt(float x) {
  if (!(x > -2147483904.0f && x < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(x);
}

// The batch's lanes as integers: the int32 lanes, and their bits unsigned (which wrap).
using IntLanes = softraster::FloatBatch::NativeMask;
using BitLanes = std::uint32_t __attribute__((vector_size(32)));
// Always inlined, as FloatBatch's own Native functions: a 32-byte vector passed by value is in a
// ymm register for AVX code and in memory for baseline code, so a call between the two must not
// exist (simd.hpp).

[[gnu::always_inline]] inline BitLanes bitsOf(softraster::FloatBatch x) { return reinterpret_cast<BitLanes>(x.native()); }
[[gnu::always_inline]] inline softraster::FloatBatch fromBits(BitLanes bits) {
  return softraster::FloatBatch(reinterpret_cast<softraster::FloatBatch::Native>(bits));
}
// Per lane: `mask` (-1 or 0 per lane) ? a : b.
[[gnu::always_inline]] inline softraster::FloatBatch select(IntLanes mask, softraster::FloatBatch a, softraster::FloatBatch b) {
  return softraster::FloatBatch(mask ? a.native() : b.native());
}

// truncateToInt per lane.
[[gnu::always_inline]] inline IntLanes truncateToInt(softraster::FloatBatch x) {
  const softraster::FloatBatch::Native v = x.native();
  const IntLanes inRange = (v > -2147483904.0f) & (v < 2147483648.0f);
  const IntLanes whole = __builtin_convertvector(inRange ? v : softraster::FloatBatch::Native{}, IntLanes);
  return inRange ? whole : IntLanes{} + std::numeric_limits<std::int32_t>::min();
}

}  // namespace detail

inline float exp2(float x) {
  x = softraster::sseMin(128.0f, x);         // lp_build_min_ext(128, x): a NaN x passes
  x = softraster::sseMax(-126.99999f, x);    // lp_build_max_ext(-126.99999, x)
  const float whole = std::floor(x);         // lp_build_ifloor_fract: floor, fraction, integer
  const float fraction = x - whole;
  const std::uint32_t exponent =
      (static_cast<std::uint32_t>(detail::truncateToInt(whole)) + 127u) << 23;  // integer wrap as in the JIT
  return std::bit_cast<float>(exponent) * detail::polynomial<detail::kExp2Polynomial>(fraction);
}

inline float log2Safe(float x) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  const auto exponent = static_cast<float>(static_cast<std::int32_t>((bits & 0x7f800000u) >> 23) - 127);
  const float mantissa = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
  const float y = (mantissa - 1.0f) / (mantissa + 1.0f);
  const float z = y * y;
  float result = std::fma(y, detail::polynomial<detail::kLog2Polynomial>(z), exponent);
  if (x >= std::numeric_limits<float>::infinity()) result = std::numeric_limits<float>::infinity();
  if (x == 0.0f) result = -std::numeric_limits<float>::infinity();
  if (x < 0.0f) result = std::bit_cast<float>(0x7fc00000u);
  return result;
}

inline float pow(float x, float y) {
  const float result = exp2(log2Safe(x) * y);
  // lp_build_cmp(EQUAL) is an unordered compare: a NaN x counts as 0 too.
  return (x == 0.0f || std::isnan(x)) ? 0.0f : result;
}

// The same three over a batch, step for step (each lane gets the float version's bits).
inline softraster::FloatBatch exp2(softraster::FloatBatch x) {
  using softraster::FloatBatch;
  x = sseMin(FloatBatch(128.0f), x);
  x = sseMax(FloatBatch(-126.99999f), x);
  const FloatBatch whole = softraster::floor(x);
  const FloatBatch fraction = x - whole;
  const detail::BitLanes exponent = (reinterpret_cast<detail::BitLanes>(detail::truncateToInt(whole)) + 127u) << 23;
  return detail::fromBits(exponent) * detail::polynomial<detail::kExp2Polynomial>(fraction);
}

inline softraster::FloatBatch log2Safe(softraster::FloatBatch x) {
  using softraster::FloatBatch;
  const detail::BitLanes bits = detail::bitsOf(x);
  const FloatBatch exponent(__builtin_convertvector(
      reinterpret_cast<detail::IntLanes>((bits & 0x7f800000u) >> 23) - 127, FloatBatch::Native));
  const FloatBatch mantissa = detail::fromBits((bits & 0x007fffffu) | 0x3f800000u);
  const FloatBatch y = (mantissa - 1.0f) / (mantissa + 1.0f);
  const FloatBatch z = y * y;
  FloatBatch result = softraster::fma(y, detail::polynomial<detail::kLog2Polynomial>(z), exponent);
  const FloatBatch::Native v = x.native();
  result = detail::select(v >= std::numeric_limits<float>::infinity(), FloatBatch(std::numeric_limits<float>::infinity()), result);
  result = detail::select(v == 0.0f, FloatBatch(-std::numeric_limits<float>::infinity()), result);
  result = detail::select(v < 0.0f, detail::fromBits(detail::BitLanes{} + 0x7fc00000u), result);
  return result;
}

inline softraster::FloatBatch pow(softraster::FloatBatch x, softraster::FloatBatch y) {
  const softraster::FloatBatch result = exp2(log2Safe(x) * y);
  const softraster::FloatBatch::Native v = x.native();
  return detail::select((v == 0.0f) | (v != v), softraster::FloatBatch(0.0f), result);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// ---- The FloatBatch16 forms (simd.hpp; AVX-512 only): the batch forms' steps over 16 lanes ----
// In AVX-512 intrinsics where they compare, truncate or select: GCC 12 turns a 16-lane comparison
// in code without the AVX-512 target (the templates') into one scalar compare per lane.
namespace detail {
// The masked forms with every lane kept (GCC 12's unmasked shifts and conversions warn that their
// undefined source is used uninitialized).
inline constexpr __mmask16 kAll = 0xffff;
[[SOFTRASTER_WIDE_TARGET, gnu::always_inline]] inline __m512 wide(softraster::FloatBatch16 x) { return reinterpret_cast<__m512>(x.native()); }
[[SOFTRASTER_WIDE_TARGET, gnu::always_inline]] inline softraster::FloatBatch16 wide(__m512 v) {
  return softraster::FloatBatch16(reinterpret_cast<softraster::FloatBatch16::Native>(v));
}
}  // namespace detail

[[SOFTRASTER_WIDE_TARGET]] inline softraster::FloatBatch16 exp2(softraster::FloatBatch16 x) {
  using softraster::FloatBatch16;
  x = sseMin(FloatBatch16(128.0f), x);
  x = sseMax(FloatBatch16(-126.99999f), x);
  const FloatBatch16 whole = softraster::floor(x);
  const FloatBatch16 fraction = x - whole;
  // cvttps2dq (0x80000000 for NaN and out of range, as truncateToInt), + 127 wrapping, << 23.
  const __m512i exponent = _mm512_maskz_slli_epi32(detail::kAll, _mm512_add_epi32(_mm512_maskz_cvttps_epi32(detail::kAll, detail::wide(whole)), _mm512_set1_epi32(127)), 23);
  return detail::wide(_mm512_castsi512_ps(exponent)) * detail::polynomial<detail::kExp2Polynomial>(fraction);
}

[[SOFTRASTER_WIDE_TARGET]] inline softraster::FloatBatch16 log2Safe(softraster::FloatBatch16 x) {
  using softraster::FloatBatch16;
  const __m512 v = detail::wide(x);
  const __m512i bits = _mm512_castps_si512(v);
  const __m512i biased = _mm512_maskz_srli_epi32(detail::kAll, _mm512_and_si512(bits, _mm512_set1_epi32(0x7f800000)), 23);
  const FloatBatch16 exponent = detail::wide(_mm512_maskz_cvtepi32_ps(detail::kAll, _mm512_sub_epi32(biased, _mm512_set1_epi32(127))));
  const FloatBatch16 mantissa = detail::wide(_mm512_castsi512_ps(
      _mm512_or_si512(_mm512_and_si512(bits, _mm512_set1_epi32(0x007fffff)), _mm512_set1_epi32(0x3f800000))));
  const FloatBatch16 y = (mantissa - 1.0f) / (mantissa + 1.0f);
  const FloatBatch16 z = y * y;
  __m512 result = detail::wide(softraster::fma(y, detail::polynomial<detail::kLog2Polynomial>(z), exponent));
  // Ordered compares, as the batch form's (false where x is NaN).
  result = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(v, _mm512_set1_ps(std::numeric_limits<float>::infinity()), _CMP_GE_OQ), result,
                                _mm512_set1_ps(std::numeric_limits<float>::infinity()));
  result = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(v, _mm512_setzero_ps(), _CMP_EQ_OQ), result,
                                _mm512_set1_ps(-std::numeric_limits<float>::infinity()));
  result = _mm512_mask_blend_ps(_mm512_cmp_ps_mask(v, _mm512_setzero_ps(), _CMP_LT_OQ), result,
                                _mm512_castsi512_ps(_mm512_set1_epi32(0x7fc00000)));
  return detail::wide(result);
}

[[SOFTRASTER_WIDE_TARGET]] inline softraster::FloatBatch16 pow(softraster::FloatBatch16 x, softraster::FloatBatch16 y) {
  const __m512 result = detail::wide(exp2(log2Safe(x) * y));
  // x == 0 or x NaN: equal-or-unordered.
  return detail::wide(_mm512_mask_blend_ps(_mm512_cmp_ps_mask(detail::wide(x), _mm512_setzero_ps(), _CMP_EQ_UQ), result, _mm512_setzero_ps()));
}
#endif

// ---- The pair forms (simd.hpp's BatchPair: FloatBatchPair, FloatBatch16Pair): each half as the batch form ----

template <class H>
softraster::BatchPair<H> pow(const softraster::BatchPair<H>& x, const softraster::BatchPair<H>& y) {
  return {pow(x.low, y.low), pow(x.high, y.high)};
}
template <class H>
softraster::BatchPair<H> selectLessEqual(const softraster::BatchPair<H>& a, const softraster::BatchPair<H>& b,
                                         const softraster::BatchPair<H>& x, const softraster::BatchPair<H>& y) {
  return {selectLessEqual(a.low, b.low, x.low, y.low), selectLessEqual(a.high, b.high, x.high, y.high)};
}

}  // namespace shaders::glsl
