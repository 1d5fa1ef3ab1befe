// Per-sample depth operations: the depth range clamp, the conversion of depth to its storage
// format and the depth test, as lavapipe's fragment JIT code does them:
//   D32_SFLOAT compared as float; D24: cvtps2dq(z * 16777215.0f); D16: the "magic number"
//   conversion, the low 16 bits of float(z * (65535/65536)) + 128.0f.
// Deliberately absent: stencil (stencil.hpp), depth bounds (lavapipe has none). The writes
// themselves are the fragment loop's (shade.hpp); colour is colour.hpp's.
#pragma once

#include <softraster/formats.hpp>
#include <softraster/simd.hpp>
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

// lp_build_clamp: max(min(z, hi), lo) with SSE minps/maxps (simd.hpp). A NaN depth (a degenerate plane setup) becomes hi.
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

}  // namespace softraster::detail
