// The image formats softraster stores: colour is R8G8B8A8 or B8G8R8A8, UNORM or sRGB,
// A2B10G10R10_UNORM_PACK32, R16G16B16A16_SFLOAT or R32G32B32A32_SFLOAT (ColourFormat:
// colourBytes() per sample in the format's memory order; the shaders' outputs, blend constants and
// write masks stay RGBA and are swizzled where they meet memory; sRGB bytes are encoded from, and
// blended in, linear values; the 10-bit format is one little-endian word per sample, red in bits
// 0-9, green 10-19, blue 20-29, alpha 30-31; the float formats are four halves or four floats,
// red first); depth (and stencil) is
// one of the DepthFormat values below, depth kept as the format stores it (UNORM depth as its
// integer, D32_SFLOAT as its float's bits), stencil as one byte per sample beside it. A header of
// its own so setup and per-sample stages can name a depth format without depending on the
// Framebuffer.
// The two depth/stencil formats compute depth exactly as their depth-only twin does
// (depthAspect): the draw loop is instantiated per depth aspect, and stencil is a run-time
// branch, so they cost no more compiled code.
// Deliberately absent until a scene needs them: stencil-only formats (S8_UINT), D16_UNORM_S8_UINT
// (lavapipe does not offer it), other colour formats (a scene names one when it needs it).
#pragma once

#include <cstdint>

namespace softraster {

enum class ColourFormat : std::uint8_t {
  R8G8B8A8Unorm,
  B8G8R8A8Unorm,
  R8G8B8A8Srgb,
  B8G8R8A8Srgb,
  A2B10G10R10Unorm,
  R16G16B16A16Sfloat,
  R32G32B32A32Sfloat,
};

// Whether the format stores floats (halves or floats): unclamped, blended in float
// (fragment/colour.hpp), no logic op.
constexpr bool isFloat(ColourFormat f) {
  return f == ColourFormat::R16G16B16A16Sfloat || f == ColourFormat::R32G32B32A32Sfloat;
}

// Bytes per sample: 4, or 8 for four halves, 16 for four floats.
constexpr std::uint32_t colourBytes(ColourFormat f) {
  return f == ColourFormat::R16G16B16A16Sfloat ? 8u : f == ColourFormat::R32G32B32A32Sfloat ? 16u : 4u;
}

// Whether the format stores red in byte 2 and blue in byte 0 (B8G8R8A8): its bytes are
// R8G8B8A8's with those two swapped, as lavapipe blends it (the same arithmetic per channel, its
// constants swizzled alike; measured, scene colour_format_bgra).
constexpr bool swapsRedBlue(ColourFormat f) { return f == ColourFormat::B8G8R8A8Unorm || f == ColourFormat::B8G8R8A8Srgb; }

// Whether the format's red, green and blue bytes are sRGB-encoded (alpha stays linear): lavapipe
// blends them in linear float (fragment/colour.hpp), and clears and resolves convert.
constexpr bool isSrgb(ColourFormat f) { return f == ColourFormat::R8G8B8A8Srgb || f == ColourFormat::B8G8R8A8Srgb; }

// Whether the format packs 10-bit red, green and blue and 2-bit alpha into one word
// (A2B10G10R10_UNORM_PACK32): lavapipe blends it in 16-bit integers (fragment/colour.hpp).
constexpr bool isTenBit(ColourFormat f) { return f == ColourFormat::A2B10G10R10Unorm; }

// The word of A2B10G10R10 from its four channels (each already within its bits), and back.
constexpr std::uint32_t packTenBit(std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a) {
  return r | (g << 10) | (b << 20) | (a << 30);
}
constexpr std::uint32_t tenBitChannel(std::uint32_t word, int c) { return c < 3 ? (word >> (10 * c)) & 1023u : word >> 30; }

enum class DepthFormat : std::uint8_t { D16Unorm, X8D24UnormPack32, D32Sfloat, D24UnormS8Uint, D32SfloatS8Uint };

// Whether the format has a stencil aspect (8 bits).
constexpr bool hasStencil(DepthFormat f) { return f == DepthFormat::D24UnormS8Uint || f == DepthFormat::D32SfloatS8Uint; }

// The depth-only format whose depth arithmetic and storage the format's depth aspect shares:
// D24_UNORM_S8_UINT's depth is X8_D24_UNORM_PACK32's, D32_SFLOAT_S8_UINT's is D32_SFLOAT's.
constexpr DepthFormat depthAspect(DepthFormat f) {
  return f == DepthFormat::D24UnormS8Uint ? DepthFormat::X8D24UnormPack32
         : f == DepthFormat::D32SfloatS8Uint ? DepthFormat::D32Sfloat
                                             : f;
}

// Bits of a UNORM depth format (16 or 24), or 0 for D32_SFLOAT (and D32_SFLOAT_S8_UINT).
constexpr int unormDepthBits(DepthFormat f) {
  return depthAspect(f) == DepthFormat::D16Unorm ? 16 : depthAspect(f) == DepthFormat::X8D24UnormPack32 ? 24 : 0;
}

// A depth clear value as the format stores it: lrint(depth * (2^n - 1)) for UNORM formats, the
// float's bits for D32_SFLOAT.
std::uint32_t depthClearValue(DepthFormat format, float depth);

}  // namespace softraster
