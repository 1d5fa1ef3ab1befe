// The GLSL built-in functions the shader twins call, computed as lavapipe computes them (Mesa
// 22.3.6: SPIR-V lowering in compiler/spirv/vtn_glsl450.c and nir_builtin_builder.h, code
// generation in gallium/auxiliary/gallivm/lp_bld_arit.c; docs/lavapipe-rules.md, "Shader
// arithmetic"), so a twin gives the GLSL's bits. Each is written over the twin's float type F
// (float, or softraster::FloatBatch, one value per lane).
//   dot(a, b)         (a.x*b.x + a.y*b.y) + a.z*b.z, every step rounded
//   length(v)         sqrt(dot(v, v))
//   normalize(v)      v / length(v), a real division per component
//   reflect(i, n)     i - n * (dot(i, n) * 2)
//   maxConstant(x, c) max(x, c) with c a constant: SSE maxps(x, c) (a NaN x gives c)
//   pow(x, y)         exp2(log2_safe(x) * y), 0 where x == 0 or x is NaN; gallivm's polynomials
// Every one runs on a whole batch with the batch's own instructions (no lane loop).
// The polynomials use fmuladd as gallivm does on a CPU with FMA (every x86-64 CPU this project
// targets has it); a lavapipe on a CPU without FMA rounds them differently.
// Deliberately absent: denormal flushing (lavapipe's shaders run with DAZ/FTZ; the lit scenes
// never produce denormals), and every built-in no twin calls yet.
#pragma once

#include <softraster/simd.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

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

// ---- The batch primitives a SIMD twin needs beyond + - * / and compares ----
// sqrt, fused multiply-add and floor of a FloatBatch, one instruction each: AVX's vsqrtps,
// FMA's vfmadd and SSE4.1/AVX's vroundps, the same IEEE operations as sqrtss, vfmadd..ss and
// roundss (so each lane rounds as the float version does). Written as inline assembly because
// generic vector code has no such operations and an intrinsic would bind the instruction set at
// this header, not at the fast path that inlines it; a FloatBatch is only ever evaluated on that
// path, which runs only on CPUs with AVX2 and FMA. Elsewhere (not x86-64) a lane loop.

namespace detail {

using Native = softraster::FloatBatch::Native;
using Words = std::uint32_t __attribute__((vector_size(32)));
using Ints = softraster::FloatBatch::NativeMask;

template <class Function>
softraster::FloatBatch lanewise(softraster::FloatBatch a, softraster::FloatBatch b, softraster::FloatBatch c,
                                Function f) {
  alignas(32) float x[softraster::kBatchLanes], y[softraster::kBatchLanes], z[softraster::kBatchLanes];
  a.store(x);
  b.store(y);
  c.store(z);
  for (int i = 0; i < softraster::kBatchLanes; ++i) x[i] = f(x[i], y[i], z[i]);
  return softraster::FloatBatch::load(x);
}

}  // namespace detail

inline float sqrt(float x) { return std::sqrt(x); }
inline softraster::FloatBatch sqrt(softraster::FloatBatch x) {
#if defined(__x86_64__) && defined(__GNUC__)
  detail::Native r;
  asm("vsqrtps %1, %0" : "=x"(r) : "x"(x.native()));
  return softraster::FloatBatch(r);
#else
  return detail::lanewise(x, x, x, [](float v, float, float) { return std::sqrt(v); });
#endif
}

// a * b + c, rounded once (lp_build_mad on an FMA CPU).
inline float fusedMultiplyAdd(float a, float b, float c) { return std::fma(a, b, c); }
inline softraster::FloatBatch fusedMultiplyAdd(softraster::FloatBatch a, softraster::FloatBatch b,
                                               softraster::FloatBatch c) {
#if defined(__x86_64__) && defined(__GNUC__)
  detail::Native r = a.native();
  asm("vfmadd213ps %2, %1, %0" : "+x"(r) : "x"(b.native()), "x"(c.native()));  // r = b * r + c
  return softraster::FloatBatch(r);
#else
  return detail::lanewise(a, b, c, [](float x, float y, float z) { return std::fma(x, y, z); });
#endif
}

inline float floor(float x) { return std::floor(x); }
inline softraster::FloatBatch floor(softraster::FloatBatch x) {
#if defined(__x86_64__) && defined(__GNUC__)
  detail::Native r;
  asm("vroundps $9, %1, %0" : "=x"(r) : "x"(x.native()));  // round down, no precision exception
  return softraster::FloatBatch(r);
#else
  return detail::lanewise(x, x, x, [](float v, float, float) { return std::floor(v); });
#endif
}

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
// One source for both float types; where a step needs the float's bits, a pair of overloads
// (asBits / fromBits and the integer steps) does it for float and for a batch.

namespace detail {

// lp_build_polynomial: x2 = x*x; even and odd coefficients each walked from the highest index
// down, the first taken as it is, each later one fmuladd(x2, value, coeff); then
// fmuladd(odd, x, even). Coefficients are rounded to float.
template <class F, std::size_t N>
F polynomial(const F& x, const double (&coefficients)[N]) {
  const F x2 = x * x;
  F even{}, odd{};
  bool haveEven = false, haveOdd = false;
  for (std::size_t i = N; i-- > 0;) {
    const F c(static_cast<float>(coefficients[i]));
    if (i % 2 == 0) {
      even = haveEven ? fusedMultiplyAdd(x2, even, c) : c;
      haveEven = true;
    } else {
      odd = haveOdd ? fusedMultiplyAdd(x2, odd, c) : c;
      haveOdd = true;
    }
  }
  return haveOdd ? fusedMultiplyAdd(odd, x, even) : even;
}

// lp_build_exp2_polynomial, EXP_POLY_DEGREE 5: 2^x on [0, 1).
inline constexpr double kExp2Polynomial[] = {1.000000000000000000000, 0.693153073200168932794,
                                             0.240153617044375388211, 0.0558263180532956664775,
                                             0.00898934009049466391101, 0.00187757667519147912699};
// lp_build_log2_polynomial, LOG_POLY_DEGREE 4.
inline constexpr double kLog2Polynomial[] = {2.88539009343309178325, 0.961791550404184197881,
                                             0.577440339438736392009, 0.403343858251329912514,
                                             0.406718052498846252698};

// 2^whole as a float's bits: cvttps2dq (0x80000000 for NaN), + 127, << 23, wrapping as the JIT's
// integer arithmetic does.
inline float scaleOf(float whole) {
  const std::int32_t i = (whole > -2147483904.0f && whole < 2147483648.0f) ? static_cast<std::int32_t>(whole)
                                                                           : std::numeric_limits<std::int32_t>::min();
  return std::bit_cast<float>((static_cast<std::uint32_t>(i) + 127u) << 23);
}
inline softraster::FloatBatch scaleOf(softraster::FloatBatch whole) {
  Ints i;  // vcvttps2dq: the batch is clamped to [-127, 128] here, or NaN (0x80000000 either way)
#if defined(__x86_64__) && defined(__GNUC__)
  asm("vcvttps2dq %1, %0" : "=x"(i) : "x"(whole.native()));
#else
  for (int k = 0; k < softraster::kBatchLanes; ++k) {
    const float w = whole[k];
    i[k] = (w > -2147483904.0f && w < 2147483648.0f) ? static_cast<std::int32_t>(w)
                                                     : std::numeric_limits<std::int32_t>::min();
  }
#endif
  const Words bits = (reinterpret_cast<Words>(i) + 127u) << 23;
  return softraster::FloatBatch(reinterpret_cast<Native>(bits));
}

// log2_safe's exponent and mantissa: float(((bits >> 23) & 255) - 127) and the float with bits
// (bits & 0x7fffff) | 0x3f800000.
inline void splitFloat(float x, float& exponent, float& mantissa) {
  const auto bits = std::bit_cast<std::uint32_t>(x);
  exponent = static_cast<float>(static_cast<std::int32_t>((bits & 0x7f800000u) >> 23) - 127);
  mantissa = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f800000u);
}
inline void splitFloat(softraster::FloatBatch x, softraster::FloatBatch& exponent, softraster::FloatBatch& mantissa) {
  const Words bits = reinterpret_cast<Words>(x.native());
  const Ints e = reinterpret_cast<Ints>((bits & 0x7f800000u) >> 23) - 127;
  exponent = softraster::FloatBatch(__builtin_convertvector(e, Native));
  mantissa = softraster::FloatBatch(reinterpret_cast<Native>((bits & 0x007fffffu) | 0x3f800000u));
}

// The selects at the end of log2_safe and pow.
inline float log2Edges(float x, float result) {
  if (x >= std::numeric_limits<float>::infinity()) result = std::numeric_limits<float>::infinity();
  if (x == 0.0f) result = -std::numeric_limits<float>::infinity();
  if (x < 0.0f) result = std::bit_cast<float>(0x7fc00000u);
  return result;
}
inline softraster::FloatBatch log2Edges(softraster::FloatBatch x, softraster::FloatBatch result) {
  const Native v = x.native();
  Native r = result.native();
  r = v >= std::numeric_limits<float>::infinity() ? Native{} + std::numeric_limits<float>::infinity() : r;
  r = v == 0.0f ? Native{} - std::numeric_limits<float>::infinity() : r;
  r = v < 0.0f ? Native{} + std::bit_cast<float>(0x7fc00000u) : r;
  return softraster::FloatBatch(r);
}
// lp_build_cmp(EQUAL) is an unordered compare: a NaN x counts as 0 too.
inline float zeroWhereXIsZero(float x, float result) { return (x == 0.0f || std::isnan(x)) ? 0.0f : result; }
inline softraster::FloatBatch zeroWhereXIsZero(softraster::FloatBatch x, softraster::FloatBatch result) {
  const Native v = x.native();
  return softraster::FloatBatch((v == 0.0f) | (v != v) ? Native{} : result.native());
}

}  // namespace detail

template <class F>
F exp2(F x) {
  using softraster::sseMax;
  using softraster::sseMin;
  x = sseMin(F(128.0f), x);        // lp_build_min_ext(128, x): a NaN x passes
  x = sseMax(F(-126.99999f), x);   // lp_build_max_ext(-126.99999, x)
  const F whole = floor(x);        // lp_build_ifloor_fract: floor, fraction, integer
  const F fraction = x - whole;
  return detail::scaleOf(whole) * detail::polynomial(fraction, detail::kExp2Polynomial);
}

template <class F>
F log2Safe(const F& x) {
  F exponent, mantissa;
  detail::splitFloat(x, exponent, mantissa);
  const F y = (mantissa - F(1.0f)) / (mantissa + F(1.0f));
  const F z = y * y;
  return detail::log2Edges(x, fusedMultiplyAdd(y, detail::polynomial(z, detail::kLog2Polynomial), exponent));
}

template <class F>
F pow(const F& x, const F& y) {
  return detail::zeroWhereXIsZero(x, exp2(log2Safe(x) * y));
}

}  // namespace shaders::glsl
