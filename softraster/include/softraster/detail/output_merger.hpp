// Per-sample operations: the depth range clamp, the conversion of depth to its storage format,
// the depth test and the colour and depth writes, as lavapipe's fragment JIT code does them:
//   D32_SFLOAT compared as float; D24: cvtps2dq(z * 16777215.0f); D16: the "magic number"
//   conversion, the low 16 bits of float(z * (65535/65536)) + 128.0f.
// Colour is stored as R8G8B8A8_UNORM: clamp to [0, 1] (NaN to 0), multiply by 255 in float,
// round half to even.
// Blending: factors ZERO and ONE with op ADD (8-bit saturating, as lavapipe blends UNORM8).
// Deliberately absent: other blend factors, colour write masks, stencil, other colour formats.
#pragma once

#include <softraster/framebuffer.hpp>
#include <softraster/math.hpp>
#include <softraster/state.hpp>

#include <bit>
#include <cmath>
#include <cstdint>

namespace softraster::detail {

// Vulkan keeps fragment depth in [0, 1]; with depth clamp also in the viewport's depth range.
struct DepthRange {
  float min = 0, max = 1;
};

inline DepthRange fragmentDepthRange(const Viewport& vp, bool depthClamp) {
  if (!depthClamp) return {};
  return {std::fmin(vp.minDepth, vp.maxDepth), std::fmax(vp.minDepth, vp.maxDepth)};
}

// SSE minps/maxps, which lavapipe's clamps compile to: the second operand when either is NaN.
inline float sseMin(float a, float b) { return a < b ? a : b; }
inline float sseMax(float a, float b) { return a > b ? a : b; }

// lp_build_clamp: max(min(z, hi), lo). A NaN depth (a degenerate plane setup) becomes hi.
inline float clampDepth(float z, DepthRange range) {
  z = sseMax(sseMin(z, 1.0f), 0.0f);
  return sseMax(sseMin(z, range.max), range.min);
}

// A depth in [0, 1] as the format stores it.
template <DepthFormat Format>
inline std::uint32_t depthToStorage(float z) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return std::bit_cast<std::uint32_t>(z);
  } else if constexpr (Format == DepthFormat::X8D24UnormPack32) {
    return static_cast<std::uint32_t>(std::nearbyint(z * 16777215.0f));
  } else {
    const float shifted = z * (65535.0f / 65536.0f) + 128.0f;  // two roundings, as in the JIT code
    return std::bit_cast<std::uint32_t>(shifted) & 0xffffu;
  }
}

template <class T>
inline bool compare(CompareOp op, T incoming, T stored) {
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

template <DepthFormat Format>
inline bool depthTestPasses(CompareOp op, std::uint32_t incoming, std::uint32_t stored) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return compare(op, std::bit_cast<float>(incoming), std::bit_cast<float>(stored));
  } else {
    return compare(op, incoming, stored);
  }
}

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
