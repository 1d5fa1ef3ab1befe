// Per-sample operations: the depth range clamp, the depth test and the colour and depth writes.
// Colour is stored as R8G8B8A8_UNORM the way lavapipe converts: clamp to [0, 1] (NaN to 0),
// multiply by 255 in float, round half to even.
// Deliberately absent: blending, colour write masks, stencil, other formats.
#pragma once

#include <softraster/math.hpp>
#include <softraster/state.hpp>

#include <cmath>
#include <cstdint>

namespace softraster::detail {

inline float clampDepth(float z) { return std::fmin(std::fmax(z, 0.0f), 1.0f); }

inline bool depthTestPasses(CompareOp op, float incoming, float stored) {
  switch (op) {
    case CompareOp::Never: return false;
    case CompareOp::Less: return incoming < stored;
    case CompareOp::Equal: return incoming == stored;
    case CompareOp::LessOrEqual: return incoming <= stored;
    case CompareOp::Greater: return incoming > stored;
    case CompareOp::NotEqual: return incoming != stored;
    case CompareOp::GreaterOrEqual: return incoming >= stored;
    case CompareOp::Always: return true;
  }
  return false;
}

inline std::uint8_t unorm8FromFloat(float v) {
  const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN compares false: 0
  return static_cast<std::uint8_t>(std::nearbyint(clamped * 255.0f));
}

inline void storeColour(std::uint8_t* pixel, Vec4 c) {
  pixel[0] = unorm8FromFloat(c.x);
  pixel[1] = unorm8FromFloat(c.y);
  pixel[2] = unorm8FromFloat(c.z);
  pixel[3] = unorm8FromFloat(c.w);
}

}  // namespace softraster::detail
