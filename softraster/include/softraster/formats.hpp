// The image formats softraster stores: colour is always R8G8B8A8_UNORM; depth is one of the
// DepthFormat values below, kept as the format stores it (UNORM depth as its integer, D32_SFLOAT
// as its float's bits). A header of its own so setup and per-sample stages can name a depth
// format without depending on the Framebuffer.
// Deliberately absent until a scene needs them: stencil, other colour formats.
#pragma once

#include <cstdint>

namespace softraster {

enum class DepthFormat : std::uint8_t { D16Unorm, X8D24UnormPack32, D32Sfloat };

// Bits of a UNORM depth format (16 or 24), or 0 for D32_SFLOAT.
constexpr int unormDepthBits(DepthFormat f) {
  return f == DepthFormat::D16Unorm ? 16 : f == DepthFormat::X8D24UnormPack32 ? 24 : 0;
}

// A depth clear value as the format stores it: lrint(depth * (2^n - 1)) for UNORM formats, the
// float's bits for D32_SFLOAT.
std::uint32_t depthClearValue(DepthFormat format, float depth);

}  // namespace softraster
