// sRGB conversions as lavapipe makes them, three different ones (Mesa 22.3.6):
//   - srgbToLinear: a stored byte to linear float, gallivm's lp_build_srgb_to_linear (a cubic,
//     fused as on an FMA CPU): texels of sRGB textures, and the destination of sRGB blending;
//   - linearToSrgbByte: linear float to a byte as the fragment JIT code stores sRGB targets,
//     lp_build_linear_to_srgb: a rational approximation of x^(5/12) made of the CPU's approximate
//     reciprocal square root (rsqrtps, about 12 bits, whose exact bits are the CPU's own: softraster
//     runs the same instruction on the machine it runs on, so it matches the lavapipe beside it);
//   - linearToSrgbClearByte: linear float to a byte as a clear packs it (util_format_linear_float_
//     to_srgb_8unorm, a piecewise-linear table, Fabian Giesen's method; tools/srgb_clear_table.py
//     makes the table).
// Deliberately no exact transfer function: lavapipe uses none of these three exactly, and each
// rounds differently from it (and from the others) for some inputs.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace softraster::detail {

// lp_build_srgb_to_linear for 8 bits: v / (12.6 * 255) up to 15, else a cubic in v (1/255 folded
// into the coefficients), through lp_build_polynomial's even/odd scheme.
inline float srgbToLinear(std::uint8_t v) {
  const float x = static_cast<float>(v);
  if (x <= 15.0f) return x * (1.0f / (12.6f * 255.0f));
  const float c0 = 0.0023f, c1 = 0.0030f / 255.0f, c2 = 0.6935f / (255.0f * 255.0f),
              c3 = 0.3012f / (255.0f * 255.0f * 255.0f);
  const float x2 = x * x;
  const float even = std::fma(x2, c2, c0), odd = std::fma(x2, c3, c1);
  return std::fma(odd, x, even);
}

// The CPU's approximate 1/sqrt(x) (rsqrtss; lp_build_fast_rsqrt emits rsqrtps, the same
// per lane). Elsewhere than x86 an exact 1/sqrt, which lavapipe there would not use either.
inline float approximateRsqrt(float x) {
#if defined(__SSE__) || defined(__x86_64__)
  return _mm_cvtss_f32(_mm_rsqrt_ss(_mm_set_ss(x)));
#else
  return 1.0f / std::sqrt(x);
#endif
}

// lp_build_linear_to_srgb for 8 bits, then lp_build_iround: clamp to [0, 1] (min with 1, then max
// with 0), x^(5/12) approximated as 0.675 * 1.0622 * 255 * x^0.375 + 0.325 * 1.0622 * 255 * x^0.5
// - 0.062 * 255 (the x^0.5 term fused with the constant), 12.92 * 255 * x at or below 0.0031308,
// rounded half to even.
inline std::uint8_t linearToSrgbByte(float x) {
  float s = x < 1.0f ? x : 1.0f;  // minps(x, 1): a NaN gives 1
  s = s > 0.0f ? s : 0.0f;
  float v;
  if (s <= 0.0031308f) {
    v = s * (12.92f * 255.0f);
  } else {
    const float a = static_cast<float>(static_cast<double>(0.675f) * 1.0622 * 255.0f);
    const float b = static_cast<float>(static_cast<double>(0.325f) * 1.0622 * 255.0f);
    const float c = -0.0620f * 255.0f;
    const float x05 = s * approximateRsqrt(s);
    const float x0375 = approximateRsqrt(approximateRsqrt(x05 * s));
    v = a * x0375 + std::fma(b, x05, c);
  }
  return static_cast<std::uint8_t>(std::nearbyint(v));  // v in [0, 255.x]: rounds into [0, 255]
}

// Giesen's table: bucket k covers linear values from 2^-13 on, 8 buckets per binade; high half
// the fit's offset (times 2^7), low half its slope (times 2^16). srgb_clear_table.py prints it.
inline constexpr std::uint32_t kSrgbClearBuckets[104] = {
    0x0073000d, 0x007a000d, 0x0080000d, 0x0087000d, 0x008d000d, 0x0094000d,
    0x009a000d, 0x00a1000d, 0x00a7001a, 0x00b4001a, 0x00c1001a, 0x00ce001a,
    0x00da001a, 0x00e7001a, 0x00f4001a, 0x0101001a, 0x010e0033, 0x01280033,
    0x01410033, 0x015b0033, 0x01750033, 0x018f0033, 0x01a80033, 0x01c20033,
    0x01dc0067, 0x020f0067, 0x02430067, 0x02760067, 0x02aa0067, 0x02dd0067,
    0x03110067, 0x03440067, 0x037800ce, 0x03df00ce, 0x044600ce, 0x04ad00ce,
    0x051400ce, 0x057b00c5, 0x05dd00bc, 0x063b00b5, 0x06970158, 0x07420142,
    0x07e30130, 0x087b0120, 0x090b0112, 0x09940106, 0x0a1700fc, 0x0a9500f2,
    0x0b0f01cb, 0x0bf401ae, 0x0ccb0195, 0x0d950180, 0x0e56016e, 0x0f0d015e,
    0x0fbc0150, 0x10630143, 0x11070264, 0x1238023e, 0x1357021d, 0x14660201,
    0x156601e9, 0x165a01d3, 0x174401c0, 0x182401af, 0x18fe0331, 0x1a9602fe,
    0x1c1502d2, 0x1d7e02ad, 0x1ed4028d, 0x201a0270, 0x21520256, 0x227d0240,
    0x239f0443, 0x25c003fe, 0x27bf03c4, 0x29a10392, 0x2b6a0367, 0x2d1d0341,
    0x2ebe031f, 0x304d0300, 0x31d105b0, 0x34a80555, 0x37520507, 0x39d504c5,
    0x3c37048b, 0x3e7c0458, 0x40a8042a, 0x42bd0401, 0x44c20798, 0x488e071e,
    0x4c1c06b6, 0x4f76065d, 0x52a50610, 0x55ac05cc, 0x5892058f, 0x5b590559,
    0x5e0c0a23, 0x631c0980, 0x67db08f6, 0x6c55087f, 0x70940818, 0x74a007bd,
    0x787d076c, 0x7c330723,
};

// util_format_linear_float_to_srgb_8unorm: clamp to [2^-13, 1 - 2^-24] (a NaN to the low end),
// find the bucket from the float's bits, add its slope times the next 8 mantissa bits.
inline std::uint8_t linearToSrgbClearByte(float x) {
  const float low = 0x1p-13f, almostOne = 0x1.fffffep-1f;
  if (!(x > low)) x = low;
  if (x > almostOne) x = almostOne;
  std::uint32_t bits = 0, lowBits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  std::memcpy(&lowBits, &low, sizeof lowBits);
  const std::uint32_t bucket = kSrgbClearBuckets[(bits - lowBits) >> 20];
  const std::uint32_t offset = (bucket >> 16) << 9, slope = bucket & 0xffffu;
  const std::uint32_t t = (bits >> 12) & 0xffu;
  return static_cast<std::uint8_t>((offset + slope * t) >> 16);
}

}  // namespace softraster::detail
