// softraster::texture(): lavapipe's implicit-LOD sampling of a 2D texture, per 2x2 quad, in
// the order gallivm generates it (Mesa 22.3.6, gallivm/lp_bld_sample*.c), each step here naming
// the gallivm function it follows:
//   1. the sampler's static state as lp_sampler_static_sampler_state derives it (which LOD
//      adjustments apply; a one-level texture with maxLod > 0 has no mip filter at all);
//   2. per quad, rho squared from the quad's differences (lp_build_rho, no approximation):
//      max((dsdx*W)^2 + (dtdx*H)^2, (dsdy*W)^2 + (dtdy*H)^2), with ds/dx = s(TR) - s(TL) and
//      ds/dy = s(BL) - s(TL);
//   3. the LOD (lp_build_lod_selector): without bias and clamps, nearest mip levels take
//      ilog2_sqrt(rho^2) directly; otherwise 0.5 * fast_log2(rho^2) (piecewise linear), + bias,
//      min maxLod, max minLod; then the level(s) and the mip weight;
//   4. the min/mag choice (lod > 0 is minified) and the texels, filtered in 8-bit fixed point
//      (lp_bld_sample_aos.c): coordinates * (size * 256) rounded, the weight its low 8 bits, and
//      each lerp v0 + ((w * (v1 - v0) * 128 + 2^14) >> 15) (pmulhrsw), x then y, then between
//      levels with weight trunc(fraction * 256);
//   5. to float: byte * (1/255).
// Integer conversions follow the SSE instructions gallivm emits: cvtps2dq (round half to even)
// and cvttps2dq (truncate), both giving INT_MIN for NaN and out-of-range values; floor is roundps.
//   6. where the 8-bit path does not apply (sRGB; mirrored repeat or clamp to border on an axis),
//      lavapipe's float path instead: texels to float first (sRGB through its cubic), float
//      coordinates, fmuladd lerps, the border colour outside the level;
//   7. depth textures (D32_SFLOAT, one level, nearest) on the float path too; with a comparison
//      sampler the texel is compared with the reference (lp_build_sample_comparefunc).
// Deliberately absent: the float path's per-pixel min/mag switch (lp_build_sample_mipmap_both),
// which Sampler2D::validate refuses; denormal flushing of the derivatives; a build for CPUs
// without FMA (the float path's lerps are fused, as lavapipe's are on FMA CPUs).
#pragma once

#include <softraster/detail/fragment/depth.hpp>
#include <softraster/detail/fragment/srgb.hpp>
#include <softraster/math.hpp>
#include <softraster/simd.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>

namespace softraster {

namespace detail::texture {

// cvtps2dq: round half to even; NaN and values outside int32 give INT_MIN.
inline std::int32_t roundToInt(float x) {
  if (!(x >= -2147483648.0f && x < 2147483648.0f)) return INT32_MIN;
  return static_cast<std::int32_t>(std::nearbyint(x));
}

// cvttps2dq: truncate toward zero; NaN and values outside int32 give INT_MIN.
inline std::int32_t truncateToInt(float x) {
  if (!(x >= -2147483648.0f && x < 2147483648.0f)) return INT32_MIN;
  return static_cast<std::int32_t>(x);
}

// lp_build_ifloor: roundps toward -inf, then cvttps2dq.
inline std::int32_t floorToInt(float x) { return truncateToInt(std::floor(x)); }

// Integer adds and shifts as the vector instructions do them: wrapping, arithmetic shifts.
inline std::int32_t wrappingAdd(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}

// lp_build_extract_exponent(x, bias): ((bits >> 23) & 255) - 127 + bias.
inline std::int32_t exponentOf(float x, int bias) {
  return static_cast<std::int32_t>((std::bit_cast<std::uint32_t>(x) >> 23) & 255u) - 127 + bias;
}

// lp_build_fast_log2: (exponent - 1) + mantissa in [1, 2).
inline float fastLog2(float x) {
  const float mantissa = std::bit_cast<float>((std::bit_cast<std::uint32_t>(x) & 0x007fffffu) | 0x3f800000u);
  return static_cast<float>(exponentOf(x, -1)) + mantissa;
}

// lp_build_ilog2_sqrt: (exponent + 1) >> 1, an arithmetic shift.
inline std::int32_t ilog2Sqrt(float x) { return exponentOf(x, 1) >> 1; }

// lp_build_lerp on unorm8 with prescaled weights (w in 0..255): pmulhrsw(w, (v1 - v0) << 7),
// its low 8 bits added to v0 in 8 bits.
inline std::uint8_t lerpUnorm8(std::int32_t w, std::uint8_t v0, std::uint8_t v1) {
  const std::int32_t delta = (static_cast<std::int32_t>(v1) - static_cast<std::int32_t>(v0)) * 128;
  const std::int32_t scaled = (w * delta + (1 << 14)) >> 15;
  return static_cast<std::uint8_t>((static_cast<std::uint32_t>(scaled) & 0xffu) + v0);
}

// The sampler's static state, as lp_sampler_static_sampler_state and lp_build_sample_soa_code
// derive it from lavapipe's pipe_sampler_state (mip filter NEAREST or LINEAR; Vulkan has no NONE).
struct StaticSampler {
  enum class Mip : std::uint8_t { None, Nearest, Linear };
  Filter minFilter, magFilter;
  Mip mip;
  bool lodBiasNonZero, minMaxLodEqual, applyMinLod, applyMaxLod;
  float lodBias, minLod, maxLod;
};

inline StaticSampler staticSampler(const SamplerState& s, std::uint32_t levels) {
  StaticSampler d{};
  d.minFilter = s.minFilter;
  d.magFilter = s.magFilter;
  d.mip = s.mipmapMode == MipmapMode::Linear ? StaticSampler::Mip::Linear : StaticSampler::Mip::Nearest;
  if (levels <= 1 && s.maxLod > 0.0f) d.mip = StaticSampler::Mip::None;  // level_zero_only && max_lod_pos
  d.lodBiasNonZero = s.mipLodBias != 0.0f;
  // The LOD clamps are derived before the one-level case drops the mip filter (lavapipe's
  // min_mip_filter is never NONE), so they always apply.
  if (s.minLod == s.maxLod) {
    d.minMaxLodEqual = true;
  } else {
    d.applyMinLod = s.minLod > 0.0f;
    d.applyMaxLod = s.maxLod < 15.0f;  // PIPE_MAX_TEXTURE_LEVELS - 1
  }
  d.lodBias = s.mipLodBias;
  d.minLod = s.minLod;
  d.maxLod = s.maxLod;
  return d;
}

// One quad's LOD decision (lp_build_lod_selector, then the mip level functions).
struct QuadLod {
  bool minified = false;        // lod_positive
  std::uint32_t level0 = 0, level1 = 0;
  std::int32_t mipWeight = 0;   // 0..255: trunc(lod fraction * 256), linear mip filtering only
};

// fraction: where the float path wants the mip weight as a float (lp_build_sample_mipmap's
// lerp), the clamped LOD fraction; the 8-bit path takes mipWeight.
inline QuadLod quadLod(const StaticSampler& d, float rhoSquared, std::uint32_t levels, float* fraction = nullptr) {
  QuadLod q;
  const bool needsLod = d.minFilter != d.magFilter || d.mip != StaticSampler::Mip::None;
  if (!needsLod) return q;
  std::int32_t ipart = 0;
  float fpart = 0.0f;
  if (!d.minMaxLodEqual && !d.lodBiasNonZero && !d.applyMaxLod && !d.applyMinLod &&
      d.mip != StaticSampler::Mip::Linear) {
    ipart = ilog2Sqrt(rhoSquared);
    q.minified = rhoSquared > 1.0f;
  } else {
    float lod;
    if (d.minMaxLodEqual) {
      lod = d.minLod;
    } else {
      lod = fastLog2(rhoSquared) * 0.5f;
      if (d.lodBiasNonZero) lod = lod + d.lodBias;
      if (d.applyMaxLod) lod = sseMin(lod, d.maxLod);
      if (d.applyMinLod) lod = sseMax(lod, d.minLod);
    }
    q.minified = lod > 0.0f;
    if (d.mip == StaticSampler::Mip::Linear) {
      const float whole = std::floor(lod);  // lp_build_ifloor_fract
      fpart = lod - whole;
      ipart = truncateToInt(whole);
    } else {
      ipart = roundToInt(lod);
    }
  }
  const std::int32_t last = static_cast<std::int32_t>(levels) - 1;
  switch (d.mip) {
    case StaticSampler::Mip::None:
      break;
    case StaticSampler::Mip::Nearest:
      q.level0 = q.level1 = static_cast<std::uint32_t>(std::clamp(ipart, 0, last));
      break;
    case StaticSampler::Mip::Linear: {
      std::int32_t l0 = ipart, l1 = wrappingAdd(ipart, 1);
      if (l0 < 0) l0 = l1 = 0, fpart = 0.0f;
      if (l0 >= last) l0 = l1 = last, fpart = 0.0f;
      q.level0 = static_cast<std::uint32_t>(l0);
      q.level1 = static_cast<std::uint32_t>(l1);
      q.mipWeight = std::max(truncateToInt(fpart * 256.0f), 0) & 0xff;
      if (fraction != nullptr) *fraction = sseMax(fpart, 0.0f);
      break;
    }
  }
  return q;
}

// One texel coordinate pair and weight along an axis of a level (lp_build_sample_wrap_*_int).
struct AxisTexels {
  std::uint32_t i0 = 0, i1 = 0;
  std::int32_t weight = 0;  // 0..255, linear filtering only
};

// Nearest filtering along one axis: coord the normalized coordinate, size the level's size.
inline std::uint32_t nearestTexel(float coord, std::uint32_t size, bool basePowerOfTwo, AddressMode wrap) {
  const std::int32_t last = static_cast<std::int32_t>(size) - 1;
  if (wrap == AddressMode::Repeat) {
    if (basePowerOfTwo) return static_cast<std::uint32_t>(floorToInt(coord * static_cast<float>(size)) & last);
    float fraction = coord - std::floor(coord);                    // lp_build_fract_safe
    fraction = std::isnan(fraction) ? 0.99999994f : std::min(fraction, 0.99999994f);
    return static_cast<std::uint32_t>(std::clamp(truncateToInt(fraction * static_cast<float>(size)), 0, last));
  }
  return static_cast<std::uint32_t>(std::clamp(floorToInt(coord * static_cast<float>(size)), 0, last));
}

// Linear filtering along one axis, in 8.8 fixed point.
inline AxisTexels linearTexels(float coord, std::uint32_t size, bool basePowerOfTwo, AddressMode wrap) {
  const std::int32_t last = static_cast<std::int32_t>(size) - 1;
  AxisTexels a;
  if (wrap == AddressMode::Repeat && !basePowerOfTwo) {  // lp_build_coord_repeat_npot_linear_int
    float f = coord - std::floor(coord);                     // lp_build_fract (not clamped)
    f = f * static_cast<float>(size);
    f = f * 256.0f;
    const std::int32_t fixed = wrappingAdd(roundToInt(f), -128);
    a.weight = fixed & 255;
    std::int32_t i0 = fixed >> 8;
    if (i0 < 0) i0 = last;
    i0 = std::min(i0, last);
    a.i0 = static_cast<std::uint32_t>(i0);
    a.i1 = i0 != last ? a.i0 + 1 : 0u;
    return a;
  }
  const float scaled = static_cast<float>(static_cast<std::int32_t>(size) << 8);
  const std::int32_t fixed = wrappingAdd(roundToInt(coord * scaled), -128);
  a.weight = fixed & 255;
  const std::int32_t i0 = fixed >> 8;
  if (wrap == AddressMode::Repeat) {
    a.i0 = static_cast<std::uint32_t>(i0 & last);
    a.i1 = static_cast<std::uint32_t>(wrappingAdd(i0, 1) & last);
  } else {
    a.i0 = static_cast<std::uint32_t>(std::clamp(i0, 0, last));
    a.i1 = static_cast<std::uint32_t>(std::clamp(wrappingAdd(i0, 1), 0, last));
  }
  return a;
}

using Texel = std::array<std::uint8_t, 4>;

inline Texel fetch(const TextureLevel& level, std::uint32_t x, std::uint32_t y) {
  const std::uint8_t* p = level.rgba.data() + (static_cast<std::size_t>(y) * level.width + x) * 4;
  return {p[0], p[1], p[2], p[3]};
}

// One pixel's texel from one level, nearest or bilinear, in 8 bits.
inline Texel sampleLevel(const TextureLevel& level, Filter filter, const SamplerState& s, bool potWidth,
                         bool potHeight, float u, float v) {
  if (filter == Filter::Nearest) {
    return fetch(level, nearestTexel(u, level.width, potWidth, s.addressModeU),
                 nearestTexel(v, level.height, potHeight, s.addressModeV));
  }
  const AxisTexels x = linearTexels(u, level.width, potWidth, s.addressModeU);
  const AxisTexels y = linearTexels(v, level.height, potHeight, s.addressModeV);
  const Texel c00 = fetch(level, x.i0, y.i0), c01 = fetch(level, x.i1, y.i0);
  const Texel c10 = fetch(level, x.i0, y.i1), c11 = fetch(level, x.i1, y.i1);
  Texel out;
  for (int c = 0; c < 4; ++c) {
    const std::uint8_t top = lerpUnorm8(x.weight, c00[c], c01[c]);
    const std::uint8_t bottom = lerpUnorm8(x.weight, c10[c], c11[c]);
    out[c] = lerpUnorm8(y.weight, top, bottom);
  }
  return out;
}

inline constexpr bool isPowerOfTwo(std::uint32_t n) { return (n & (n - 1)) == 0; }

// ---- lavapipe's float path (lp_bld_sample_soa.c): sRGB, mirrored repeat, clamp to border ----
// Taken where the 8-bit path does not apply (util_format_fits_8unorm is false for sRGB; the AoS
// path takes only repeat and clamp to edge). Texels become floats first (UNORM: byte * (1/255);
// sRGB: lp_build_srgb_to_linear's polynomial), wrapping works on float coordinates, and each
// lerp is fmuladd(w, v1 - v0, v0) (fused, as lavapipe's is on an FMA CPU).

// (srgbToLinear, lp_build_srgb_to_linear's cubic: fragment/srgb.hpp.)

// lp_build_coord_mirror(coord, posOnly): the distance to the nearest even integer, in [0, 1].
inline float mirrorCoordinate(float coord) {
  const float half = coord * 0.5f;
  const float fraction = half - std::nearbyint(half);  // lp_build_round: nearest, ties to even
  const float c = std::fabs(fraction + fraction);
  return std::isnan(c) ? 0.0f : sseMax(c, 0.0f);      // lp_build_max_ext(c, 0, NaN gives the other)
}

// lp_build_ifloor_fract: floor (roundps), the fraction a - floor(a), the integer cvttps2dq.
inline void floorFraction(float a, std::int32_t& whole, float& fraction) {
  const float f = std::floor(a);
  fraction = a - f;
  whole = truncateToInt(f);
}

// lp_build_sample_wrap_nearest: one axis's texel, possibly outside the level for clamp to border.
inline std::int32_t nearestTexelFloat(float coord, std::uint32_t size, bool basePowerOfTwo, AddressMode wrap) {
  const std::int32_t last = static_cast<std::int32_t>(size) - 1;
  const float length = static_cast<float>(size);
  switch (wrap) {
    case AddressMode::Repeat:
      if (basePowerOfTwo) return floorToInt(coord * length) & last;
      {
        float fraction = coord - std::floor(coord);  // lp_build_fract_safe
        fraction = std::isnan(fraction) ? 0.99999994f : std::min(fraction, 0.99999994f);
        return truncateToInt(fraction * length);
      }
    case AddressMode::ClampToEdge:
      return std::clamp(truncateToInt(coord * length), 0, last);
    case AddressMode::ClampToBorder:
      return floorToInt(coord * length);
    case AddressMode::MirroredRepeat:
      return std::min(truncateToInt(mirrorCoordinate(coord) * length), last);
  }
  return 0;
}

// lp_build_sample_wrap_linear: one axis's two texels (possibly outside for clamp to border) and weight.
struct AxisTexelsFloat {
  std::int32_t i0 = 0, i1 = 0;
  float weight = 0.0f;
};

inline AxisTexelsFloat linearTexelsFloat(float coord, std::uint32_t size, bool basePowerOfTwo, AddressMode wrap) {
  const std::int32_t last = static_cast<std::int32_t>(size) - 1;
  const float length = static_cast<float>(size);
  AxisTexelsFloat a;
  switch (wrap) {
    case AddressMode::Repeat:
      if (basePowerOfTwo) {
        floorFraction(coord * length - 0.5f, a.i0, a.weight);
        a.i1 = wrappingAdd(a.i0, 1) & last;
        a.i0 &= last;
      } else {  // lp_build_coord_repeat_npot_linear
        const float c = (coord - std::floor(coord)) * length - 0.5f;
        const bool below = !(c >= 0.0f);  // an unordered compare: NaN counts as below
        floorFraction(c, a.i0, a.weight);
        if (below) a.i0 = last;
        a.i1 = a.i0 != last ? a.i0 + 1 : 0;
      }
      break;
    case AddressMode::ClampToEdge: {
      float c = coord * length;
      c = std::isnan(c) ? length : sseMin(c, length);  // lp_build_min_ext, NaN gives the other
      c = sseMax(c - 0.5f, 0.0f);
      floorFraction(c, a.i0, a.weight);
      a.i1 = std::min(wrappingAdd(a.i0, 1), last);
      break;
    }
    case AddressMode::ClampToBorder:
      floorFraction(coord * length - 0.5f, a.i0, a.weight);
      a.i1 = wrappingAdd(a.i0, 1);
      break;
    case AddressMode::MirroredRepeat:
      floorFraction(mirrorCoordinate(coord) * length - 0.5f, a.i0, a.weight);
      a.i1 = std::min(wrappingAdd(a.i0, 1), last);
      a.i0 = std::max(a.i0, 0);
      break;
  }
  return a;
}

using TexelFloat = std::array<float, 4>;

inline TexelFloat borderColour(BorderColor c) {
  switch (c) {
    case BorderColor::TransparentBlack: return {0, 0, 0, 0};
    case BorderColor::OpaqueBlack: return {0, 0, 0, 1};
    case BorderColor::OpaqueWhite: return {1, 1, 1, 1};
  }
  return {0, 0, 0, 0};
}

// lp_build_sample_texel_soa: the texel at (x, y), or the border colour where a clamp-to-border
// axis falls outside the level; converted to float.
inline TexelFloat fetchFloat(const TextureLevel& level, TextureFormat format, const SamplerState& s, std::int32_t x,
                             std::int32_t y) {
  const bool outsideU = s.addressModeU == AddressMode::ClampToBorder && (x < 0 || x >= static_cast<std::int32_t>(level.width));
  const bool outsideV = s.addressModeV == AddressMode::ClampToBorder && (y < 0 || y >= static_cast<std::int32_t>(level.height));
  if (outsideU || outsideV) return borderColour(s.borderColor);
  if (format == TextureFormat::D32Sfloat) {  // Z32_FLOAT's swizzle: (depth, 0, 0, 1)
    const std::uint8_t* p = level.rgba.data() + (static_cast<std::size_t>(y) * level.width + static_cast<std::uint32_t>(x)) * 4;
    float depth;
    std::memcpy(&depth, p, sizeof depth);
    return {depth, 0.0f, 0.0f, 1.0f};
  }
  const bool srgb = format == TextureFormat::R8G8B8A8Srgb;
  const Texel t = fetch(level, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
  constexpr float kUnorm = static_cast<float>(1.0 / 255.0);
  if (srgb) return {srgbToLinear(t[0]), srgbToLinear(t[1]), srgbToLinear(t[2]), static_cast<float>(t[3]) * kUnorm};
  return {static_cast<float>(t[0]) * kUnorm, static_cast<float>(t[1]) * kUnorm, static_cast<float>(t[2]) * kUnorm,
          static_cast<float>(t[3]) * kUnorm};
}

inline float lerpFloat(float w, float v0, float v1) { return std::fma(w, v1 - v0, v0); }  // lp_build_lerp: fmuladd

// One pixel's colour from one level through the float path.
inline TexelFloat sampleLevelFloat(const TextureLevel& level, Filter filter, const SamplerState& s, TextureFormat format,
                                   bool potWidth, bool potHeight, float u, float v) {
  if (filter == Filter::Nearest) {
    return fetchFloat(level, format, s, nearestTexelFloat(u, level.width, potWidth, s.addressModeU),
                      nearestTexelFloat(v, level.height, potHeight, s.addressModeV));
  }
  const AxisTexelsFloat x = linearTexelsFloat(u, level.width, potWidth, s.addressModeU);
  const AxisTexelsFloat y = linearTexelsFloat(v, level.height, potHeight, s.addressModeV);
  const TexelFloat c00 = fetchFloat(level, format, s, x.i0, y.i0), c01 = fetchFloat(level, format, s, x.i1, y.i0);
  const TexelFloat c10 = fetchFloat(level, format, s, x.i0, y.i1), c11 = fetchFloat(level, format, s, x.i1, y.i1);
  TexelFloat out;
  for (int c = 0; c < 4; ++c) {
    out[c] = lerpFloat(y.weight, lerpFloat(x.weight, c00[c], c01[c]), lerpFloat(x.weight, c10[c], c11[c]));
  }
  return out;
}

// Whether lavapipe samples this in float rather than in 8-bit fixed point (use_aos is false).
inline bool usesFloatPath(TextureFormat format, const SamplerState& s) {
  const auto simple = [](AddressMode m) { return m == AddressMode::Repeat || m == AddressMode::ClampToEdge; };
  return format != TextureFormat::R8G8B8A8Unorm || !simple(s.addressModeU) || !simple(s.addressModeV);
}

// lp_build_sample_comparefunc: reference OP texel, an ordered compare (false with a NaN) for
// every op but NotEqual, which is unordered (true with a NaN), as D3D10's rules say: the depth
// test's compare (fragment/depth.hpp), whose C++ operators have exactly these semantics.
inline bool compareDepth(CompareOp op, float reference, float texel) { return detail::compare(op, reference, texel); }

// One pixel's comparison result from one level (lp_build_sample_image_nearest with a compare
// mode): the texel fetched as the float path fetches it (the border colour's red outside a
// clamp-to-border level), compared, 1 or 0. Nearest only: lavapipe gives depth formats no
// SAMPLED_IMAGE_FILTER_LINEAR, so a linear (percentage-closer) filter is invalid there
// (Sampler2D::validate refuses it).
inline float sampleLevelShadow(const TextureLevel& level, const SamplerState& s, bool potWidth, bool potHeight, float u,
                               float v, float reference) {
  const TexelFloat texel = fetchFloat(level, TextureFormat::D32Sfloat, s,
                                      nearestTexelFloat(u, level.width, potWidth, s.addressModeU),
                                      nearestTexelFloat(v, level.height, potHeight, s.addressModeV));
  return compareDepth(s.compareOp, reference, texel[0]) ? 1.0f : 0.0f;
}

}  // namespace detail::texture

namespace detail::texture {

// The two quads of a batch, lane by lane (lanes as in simd.hpp: lane = 4 * row + column), into
// out[channel][lane]. Out of line on purpose: each shader's fast path is flattened into one
// function, and sampling inlined there (twice for a normal map, per depth format and path) made
// one shader's translation unit take many minutes to compile; one call per batch costs nothing
// beside the per-lane work. Plain arrays, so no vector crosses the call (no ABI question).
[[gnu::noinline]] inline void sampleQuads(const Sampler2D& sampler, const float (&u)[kBatchLanes],
                                          const float (&v)[kBatchLanes], float (&out)[4][kBatchLanes]) {
  const Texture* tex = sampler.texture;
  if (tex == nullptr || tex->levels() == 0) {
    for (auto& channel : out) std::fill(std::begin(channel), std::end(channel), 0.0f);
    return;
  }
  const SamplerState& s = sampler.sampler;
  const StaticSampler d = staticSampler(s, tex->levels());
  const bool potWidth = isPowerOfTwo(tex->width()), potHeight = isPowerOfTwo(tex->height());
  const float width = static_cast<float>(tex->width()), height = static_cast<float>(tex->height());
  const bool floatPath = usesFloatPath(tex->format(), s);
  for (int quad = 0; quad < 2; ++quad) {
    float mipFraction = 0.0f;
    const int tl = 2 * quad, tr = tl + 1, bl = tl + 4;
    float dsdx = (u[tr] - u[tl]) * width, dsdy = (u[bl] - u[tl]) * width;
    float dtdx = (v[tr] - v[tl]) * height, dtdy = (v[bl] - v[tl]) * height;
    dsdx = dsdx * dsdx, dsdy = dsdy * dsdy, dtdx = dtdx * dtdx, dtdy = dtdy * dtdy;
    const float rhoSquared = sseMax(dsdx + dtdx, dsdy + dtdy);
    const QuadLod lod = quadLod(d, rhoSquared, tex->levels(), floatPath ? &mipFraction : nullptr);
    Filter filter = d.minFilter;
    bool mipLinear = d.mip == StaticSampler::Mip::Linear;
    if (d.minFilter != d.magFilter && !lod.minified) filter = d.magFilter, mipLinear = false;
    for (int lane : {tl, tr, bl, bl + 1}) {
      if (floatPath) {
        TexelFloat c = sampleLevelFloat(tex->level(lod.level0), filter, s, tex->format(), potWidth, potHeight, u[lane], v[lane]);
        if (mipLinear) {
          const TexelFloat c1 =
              sampleLevelFloat(tex->level(lod.level1), filter, s, tex->format(), potWidth, potHeight, u[lane], v[lane]);
          for (int ch = 0; ch < 4; ++ch) c[ch] = lerpFloat(mipFraction, c[ch], c1[ch]);
        }
        for (int ch = 0; ch < 4; ++ch) out[ch][lane] = c[ch];
        continue;
      }
      Texel c = sampleLevel(tex->level(lod.level0), filter, s, potWidth, potHeight, u[lane], v[lane]);
      if (mipLinear) {
        const Texel c1 = sampleLevel(tex->level(lod.level1), filter, s, potWidth, potHeight, u[lane], v[lane]);
        for (int ch = 0; ch < 4; ++ch) c[ch] = lerpUnorm8(lod.mipWeight, c[ch], c1[ch]);
      }
      for (int ch = 0; ch < 4; ++ch) out[ch][lane] = static_cast<float>(c[ch]) * static_cast<float>(1.0 / 255.0);
    }
  }
}

// The comparison results of a batch's lanes (textureShadow). No LOD: a depth texture has one
// level and nearest filters (Sampler2D::validate), so lavapipe computes none. Out of line, as sampleQuads.
[[gnu::noinline]] inline void sampleShadowLanes(const Sampler2D& sampler, const float (&u)[kBatchLanes],
                                                const float (&v)[kBatchLanes], const float (&reference)[kBatchLanes],
                                                float (&out)[kBatchLanes]) {
  const Texture* tex = sampler.texture;
  const SamplerState& s = sampler.sampler;
  if (tex == nullptr || tex->levels() == 0 || tex->format() != TextureFormat::D32Sfloat || !s.compareEnable) {
    std::fill(std::begin(out), std::end(out), 0.0f);
    return;
  }
  const bool potWidth = isPowerOfTwo(tex->width()), potHeight = isPowerOfTwo(tex->height());
  for (int lane = 0; lane < kBatchLanes; ++lane) {
    out[lane] = sampleLevelShadow(tex->level(0), s, potWidth, potHeight, u[lane], v[lane], reference[lane]);
  }
}

}  // namespace detail::texture

inline FloatBatch textureShadow(const Sampler2D& sampler, FloatBatch u, FloatBatch v, FloatBatch reference) {
  alignas(32) float us[kBatchLanes], vs[kBatchLanes], refs[kBatchLanes], out[kBatchLanes];
  u.store(us);
  v.store(vs);
  reference.store(refs);
  detail::texture::sampleShadowLanes(sampler, us, vs, refs, out);
  return FloatBatch::load(out);
}

inline Vec4T<FloatBatch> texture(const Sampler2D& sampler, FloatBatch u, FloatBatch v) {
  alignas(32) float us[kBatchLanes], vs[kBatchLanes], out[4][kBatchLanes];
  u.store(us);
  v.store(vs);
  detail::texture::sampleQuads(sampler, us, vs, out);
  return {FloatBatch::load(out[0]), FloatBatch::load(out[1]), FloatBatch::load(out[2]), FloatBatch::load(out[3])};
}

}  // namespace softraster
