// Half floats as lavapipe converts them for R16G16B16A16_SFLOAT targets: a half widens to the
// float of the same value (vcvtph2ps, exact), and a float narrows toward zero (vcvtps2ph with
// rounding immediate 3, lp_build_float_to_half; the clear's _mesa_float_to_float16_rtz is the same
// instruction): the magnitude truncated, finite values beyond 65504 kept at 65504 (toward zero
// never reaches infinity), infinities kept, NaNs quieted with their sign and top payload bits,
// results below the smallest normal half stored as half denormals (truncated). Software, so the
// result is the same on a CPU without F16C.
// Also the flush of denormals that lavapipe's rasterizer threads apply (FTZ and DAZ) to float
// arithmetic everywhere but in the blend of a half-float target.
// Deliberately no round-to-nearest conversion: nothing lavapipe stores uses it.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace softraster::detail {

inline float floatFromHalf(std::uint16_t h) {
  const std::uint32_t sign = static_cast<std::uint32_t>(h & 0x8000u) << 16;
  const std::uint32_t exponent = (h >> 10) & 0x1fu, mantissa = h & 0x3ffu;
  if (exponent == 0x1f) return std::bit_cast<float>(sign | 0x7f800000u | (mantissa << 13));  // Inf, NaN
  if (exponent != 0) return std::bit_cast<float>(sign | ((exponent + 112) << 23) | (mantissa << 13));
  const float magnitude = static_cast<float>(mantissa) * 0x1p-24f;  // zero or a denormal: exact
  return sign ? -magnitude : magnitude;
}

inline std::uint16_t halfFromFloatTowardZero(float v) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
  const auto sign = static_cast<std::uint16_t>((bits >> 16) & 0x8000u);
  const std::uint32_t exponent = (bits >> 23) & 0xffu, mantissa = bits & 0x7fffffu;
  if (exponent == 0xff) {  // Inf, or NaN made quiet
    return static_cast<std::uint16_t>(sign | 0x7c00u | (mantissa != 0 ? 0x200u | (mantissa >> 13) : 0u));
  }
  if (exponent >= 143) return static_cast<std::uint16_t>(sign | 0x7bffu);  // |v| >= 65536: the largest finite half
  if (exponent >= 113) return static_cast<std::uint16_t>(sign | ((exponent - 112) << 10) | (mantissa >> 13));
  if (exponent < 102) return sign;  // below half the smallest half denormal (float denormals too): zero
  // A half denormal: |v| / 2^-24 = (2^23 + mantissa) * 2^(exponent - 126 - 23 + 23), truncated.
  return static_cast<std::uint16_t>(sign | ((0x800000u | mantissa) >> (126 - exponent)));
}

// A float as an operation under FTZ and DAZ reads or leaves it: a denormal becomes a zero of its sign.
inline float flushDenormal(float x) {
  return std::fabs(x) < std::numeric_limits<float>::min() ? std::copysign(0.0f, x) : x;
}

}  // namespace softraster::detail
