// Colour output: R8G8B8A8_UNORM stores and blending, as lavapipe's fragment JIT code does them.
// A store clamps to [0, 1] (NaN to 0), multiplies by 255 in float and rounds half to even.
// Blending: factors ZERO and ONE with op ADD (8-bit saturating, as lavapipe blends UNORM8).
// Deliberately absent: other blend factors, colour write masks, other colour formats.
#pragma once

#include <softraster/math.hpp>
#include <softraster/state.hpp>

#include <cstdint>

namespace softraster::detail {

// Round half to even of x in [0, 2^23): adding 2^23 leaves no fraction bits, so the float add
// itself rounds (to nearest even); it inlines where std::nearbyint is a library call.
inline float roundHalfEvenSmall(float x) { return (x + 8388608.0f) - 8388608.0f; }

inline std::uint8_t unorm8FromFloat(float v) {
  const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN compares false: 0
  return static_cast<std::uint8_t>(roundHalfEvenSmall(clamped * 255.0f));
}

inline void storeColour(std::uint8_t* pixel, Vec4 c) {
  pixel[0] = unorm8FromFloat(c.x);
  pixel[1] = unorm8FromFloat(c.y);
  pixel[2] = unorm8FromFloat(c.z);
  pixel[3] = unorm8FromFloat(c.w);
}

// Blending with op ADD in 8-bit integers, as lavapipe blends UNORM8 targets: each side is the
// value or zero, the sum saturates.
[[gnu::always_inline]] inline void blendColour(std::uint8_t* pixel, Vec4 c, const BlendState& blend) {
  if (!blend.enable) {
    storeColour(pixel, c);
    return;
  }
  const float source[4] = {c.x, c.y, c.z, c.w};
  for (int i = 0; i < 4; ++i) {
    const int s = blend.source == BlendFactor::One ? unorm8FromFloat(source[i]) : 0;
    const int d = blend.destination == BlendFactor::One ? pixel[i] : 0;
    pixel[i] = static_cast<std::uint8_t>(s + d > 255 ? 255 : s + d);
  }
}

}  // namespace softraster::detail
