// Colour output: R8G8B8A8 and B8G8R8A8 (UNORM and sRGB) stores and blending, as lavapipe's
// fragment JIT code does them. B8G8R8A8 is R8G8B8A8 with red and blue swapped where the colour
// meets memory: the shader's output, the blend constants and the write mask are swizzled
// (ColourBlend), the arithmetic per channel is the same. sRGB targets: see blendColourSrgb.
// A store clamps to [0, 1] (NaN to 0), multiplies by 255 in float and rounds half to even.
// Blending (every core VkBlendFactor and VkBlendOp, separate colour and alpha, blend constants,
// the colour write mask) is lavapipe's 8-bit integer arithmetic on UNORM8 targets (Mesa 22.3.6,
// llvmpipe lp_state_fs.c generate_unswizzled_blend, lp_bld_blend_aos.c lp_build_blend_aos,
// lp_bld_blend.c lp_build_blend, gallivm lp_bld_arit.c):
//   - the source colour and the blend constants are converted to UNORM8 first, as a store does
//     (lp_build_conv); the destination is the stored byte;
//   - each factor is a byte: ONE 255, ONE_MINUS_x 255 - x (a bitwise not, lp_build_comp), the
//     alpha factors are the alpha byte, SRC_ALPHA_SATURATE min(As, 255 - Ad) for colour and 255
//     for alpha;
//   - each term is mul(x, f) = (t + (t >> 8) + 128) >> 8 with t = x * f (lp_build_mul_norm:
//     x*f/255 rounded to nearest but for 24 pairs, see mulUnorm8), ADD a saturating add,
//     SUBTRACT and REVERSE_SUBTRACT saturating subtractions, MIN and MAX of source and
//     destination (lavapipe sets their factors to ONE, lvp_execute.c), per channel;
//   - components the write mask leaves out keep the destination byte (with blending off too);
//   - a logic op (VkLogicOp) instead of blending works bit by bit on the source converted to
//     UNORM8 as a store converts it and the destination byte (lp_build_logicop on the converted
//     values), then the write mask.
// A2B10G10R10 targets: the same integer arithmetic in 16 bits, see blendColourTenBit. Float
// targets (R16G16B16A16_SFLOAT, R32G32B32A32_SFLOAT): see blendColourFloat.
// Deliberately absent: dual-source factors, and the SIMD form of the sRGB, 10-bit and float paths
// (the fast path draws those targets with the scalar fragment stage). Those three paths are out
// of line (noinline: built with the translation unit's flags, unfused, never an FMA): inlined they
// made every draw-loop instantiation larger (models_vertex_color.cpp: 288 s to compile, 233 s without).
#pragma once

#include <softraster/detail/fragment/half.hpp>
#include <softraster/detail/fragment/srgb.hpp>
#include <softraster/formats.hpp>
#include <softraster/math.hpp>
#include <softraster/state.hpp>

#include <bit>
#include <cstdint>
#include <cstring>
#include <utility>

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

// A float as lavapipe converts it to a 16-bit UNORM blend value (lp_build_conv: max with 0, NaN
// giving 0, then min with 1; lp_build_clamped_float_to_unsigned_norm: the float
// x * (65535/65536) + 128, whose low 16 mantissa bits are x * 65535 rounded half to even, nearly).
inline int unorm16FromFloat(float v) {
  float c = v > 0.0f ? v : 0.0f;
  c = c < 1.0f ? c : 1.0f;
  const float scaled = c * (65535.0f / 65536.0f);
  return static_cast<int>(std::bit_cast<std::uint32_t>(scaled + 128.0f) & 0xffffu);
}

// A draw's BlendState prepared for UNORM8 blending in the target's byte order: the blend
// constants as bytes (converted as a store converts) and the write mask, both in that order;
// whether the shader's red and blue swap places before the store; and whether the destination is
// read at all.
struct ColourBlend {
  BlendState state;  // colorWriteMask: bit i for byte i of the stored pixel
  std::uint8_t constants[4] = {0, 0, 0, 0};  // byte i for byte i of the stored pixel
  float linearConstants[4] = {0, 0, 0, 0};   // sRGB: the constants clamped to [0, 1], in byte order
  float floatConstants[4] = {0, 0, 0, 0};    // float targets: the constants as given, R, G, B, A
  int constants16[4] = {0, 0, 0, 0};         // A2B10G10R10: the constants as 16-bit UNORM, R, G, B, A
  bool swapRedBlue = false;       // B8G8R8A8: the colour's x goes to byte 2, z to byte 0
  bool srgb = false;              // an sRGB target: blendColourSrgb
  bool tenBit = false;            // an A2B10G10R10 target: blendColourTenBit
  ColourFormat floatFormat = ColourFormat::R8G8B8A8Unorm;  // a float target's format: blendColourFloat
  bool readsDestination = false;  // blending on, or a write mask without every component
};

inline ColourBlend colourBlend(const BlendState& state, ColourFormat format = ColourFormat::R8G8B8A8Unorm) {
  ColourBlend b{state};
  for (int i = 0; i < 4; ++i) b.constants[i] = unorm8FromFloat(state.blendConstants[i]);
  for (int i = 0; i < 4; ++i) b.constants16[i] = unorm16FromFloat(state.blendConstants[i]);
  b.tenBit = isTenBit(format);
  if (isFloat(format)) b.floatFormat = format;
  for (int i = 0; i < 4; ++i) b.floatConstants[i] = state.blendConstants[i];
  for (int i = 0; i < 4; ++i) {  // lp_build_clamp: min with 1, then max with 0
    const float k = state.blendConstants[i] < 1.0f ? state.blendConstants[i] : 1.0f;
    b.linearConstants[i] = k > 0.0f ? k : 0.0f;
  }
  b.srgb = isSrgb(format);
  if (swapsRedBlue(format)) {
    b.swapRedBlue = true;
    std::swap(b.constants[0], b.constants[2]);
    std::swap(b.linearConstants[0], b.linearConstants[2]);
    const std::uint32_t mask = state.colorWriteMask;
    b.state.colorWriteMask = static_cast<std::uint8_t>((mask & 0b1010u) | ((mask & 1u) << 2) | ((mask >> 2) & 1u));
  }
  b.readsDestination = state.enable || (state.colorWriteMask & kColourRGBA) != kColourRGBA ||
                       (state.logicOpEnable && state.logicOp != LogicOp::Copy);
  return b;
}

// VkLogicOp on one channel of `ones` bits set (0xff or 0xffff; s the source, d the destination),
// as the table in state.hpp.
inline int logicOpUnorm(LogicOp op, int s, int d, int ones) {
  int out = 0;
  switch (op) {
    case LogicOp::Clear: out = 0; break;
    case LogicOp::And: out = s & d; break;
    case LogicOp::AndReverse: out = s & ~d; break;
    case LogicOp::Copy: out = s; break;
    case LogicOp::AndInverted: out = ~s & d; break;
    case LogicOp::NoOp: out = d; break;
    case LogicOp::Xor: out = s ^ d; break;
    case LogicOp::Or: out = s | d; break;
    case LogicOp::Nor: out = ~(s | d); break;
    case LogicOp::Equivalent: out = ~(s ^ d); break;
    case LogicOp::Invert: out = ~d; break;
    case LogicOp::OrReverse: out = s | ~d; break;
    case LogicOp::CopyInverted: out = ~s; break;
    case LogicOp::OrInverted: out = ~s | d; break;
    case LogicOp::Nand: out = ~(s & d); break;
    case LogicOp::Set: out = ones; break;
  }
  return out & ones;
}

inline int logicOp8(LogicOp op, int s, int d) { return logicOpUnorm(op, s, d, 0xff); }

// x * f / 255 in 16-bit integers, lp_build_mul_norm's geometric series with rounding: the product
// rounded to nearest, except for 24 pairs of bytes (152 * 229 among them), each with
// x * f = 128 (mod 255), where k + 0.502 gives k. lavapipe's output has the same bits
// (scene blend_products).
inline int mulUnorm8(int x, int f) {
  const int t = x * f;
  return (t + (t >> 8) + 128) >> 8;
}

// The same for 16-bit UNORM values (lp_build_mul_norm with n = 16, in 32-bit lanes: no overflow).
inline int mulUnorm16(int x, int f) {
  const std::uint32_t t = static_cast<std::uint32_t>(x) * static_cast<std::uint32_t>(f);
  return static_cast<int>((t + (t >> 16) + 0x8000u) >> 16);
}

// The factor for channel c (3 = alpha) of source s and destination d, as a UNORM of `One` (255 or
// 65535); ONE_MINUS_x is One - x (lp_build_comp's bitwise not).
template <int One, class Constant>
inline int blendFactorUnorm(BlendFactor f, int c, const int (&s)[4], const int (&d)[4], const Constant (&k)[4]) {
  switch (f) {
    case BlendFactor::Zero: return 0;
    case BlendFactor::One: return One;
    case BlendFactor::SrcColor: return s[c];
    case BlendFactor::OneMinusSrcColor: return One - s[c];
    case BlendFactor::DstColor: return d[c];
    case BlendFactor::OneMinusDstColor: return One - d[c];
    case BlendFactor::SrcAlpha: return s[3];
    case BlendFactor::OneMinusSrcAlpha: return One - s[3];
    case BlendFactor::DstAlpha: return d[3];
    case BlendFactor::OneMinusDstAlpha: return One - d[3];
    case BlendFactor::ConstantColor: return k[c];
    case BlendFactor::OneMinusConstantColor: return One - k[c];
    case BlendFactor::ConstantAlpha: return k[3];
    case BlendFactor::OneMinusConstantAlpha: return One - k[3];
    case BlendFactor::SrcAlphaSaturate: return c == 3 ? One : (s[3] < One - d[3] ? s[3] : One - d[3]);
  }
  return 0;
}

// One channel blended in UNORM integers of `One`: each term mul(x, f), then the saturating op.
template <int One, class Constant>
inline int blendChannelUnorm(BlendOp op, BlendFactor sf, BlendFactor df, int c, const int (&s)[4], const int (&d)[4],
                             const Constant (&k)[4]) {
  switch (op) {
    case BlendOp::Min: return s[c] < d[c] ? s[c] : d[c];
    case BlendOp::Max: return s[c] > d[c] ? s[c] : d[c];
    default: break;
  }
  auto mul = [](int x, int f) { return One == 255 ? mulUnorm8(x, f) : mulUnorm16(x, f); };
  const int st = mul(s[c], blendFactorUnorm<One>(sf, c, s, d, k));
  const int dt = mul(d[c], blendFactorUnorm<One>(df, c, s, d, k));
  switch (op) {
    case BlendOp::Add: return st + dt > One ? One : st + dt;
    case BlendOp::Subtract: return st > dt ? st - dt : 0;
    case BlendOp::ReverseSubtract: return dt > st ? dt - st : 0;
    default: return 0;
  }
}

inline int blendChannel8(BlendOp op, BlendFactor sf, BlendFactor df, int c, const int (&s)[4], const int (&d)[4],
                         const std::uint8_t (&k)[4]) {
  return blendChannelUnorm<255>(op, sf, df, c, s, d, k);
}

// ---- sRGB targets: lavapipe's float path (lp_state_fs.c, format_expands_to_float_soa) ----
// The source colour is clamped to [0, 1] (NaN to 0, lp_build_clamp_zero_one_nanzero), the
// constants to [0, 1]; the destination's red, green and blue are decoded to linear (srgbToLinear)
// and its alpha is byte * (1/255 as a float). Blending is float arithmetic per channel, unfused
// (lp_build_blend on floats: one multiply per term, ONE_MINUS_x as 1 - x, SRC_ALPHA_SATURATE
// min(As, 1 - Ad)), with lp_build_blend's one shortcut for floats: when the source and the
// destination factor are the same for colour and the same for alpha, ADD, SUBTRACT and
// REVERSE_SUBTRACT are computed as (s op d) * factor. MIN and MAX take the unweighted values
// (lavapipe sets their factors to ONE before that test). A logic op is not applied (Vulkan: not on
// sRGB targets; lavapipe stores the source). The write mask selects between result and
// destination in linear values, then every channel is encoded again: red, green and blue by
// linearToSrgbByte, alpha as a UNORM8 store (encode(decode(b)) == b for every byte, so what the
// mask leaves keeps its byte).

// VkBlendFactor in float for channel c (3 = alpha).
inline float blendFactorFloat(BlendFactor f, int c, const float (&s)[4], const float (&d)[4], const float (&k)[4]) {
  switch (f) {
    case BlendFactor::Zero: return 0.0f;
    case BlendFactor::One: return 1.0f;
    case BlendFactor::SrcColor: return s[c];
    case BlendFactor::OneMinusSrcColor: return 1.0f - s[c];
    case BlendFactor::DstColor: return d[c];
    case BlendFactor::OneMinusDstColor: return 1.0f - d[c];
    case BlendFactor::SrcAlpha: return s[3];
    case BlendFactor::OneMinusSrcAlpha: return 1.0f - s[3];
    case BlendFactor::DstAlpha: return d[3];
    case BlendFactor::OneMinusDstAlpha: return 1.0f - d[3];
    case BlendFactor::ConstantColor: return k[c];
    case BlendFactor::OneMinusConstantColor: return 1.0f - k[c];
    case BlendFactor::ConstantAlpha: return k[3];
    case BlendFactor::OneMinusConstantAlpha: return 1.0f - k[3];
    case BlendFactor::SrcAlphaSaturate: {
      if (c == 3) return 1.0f;
      const float inverse = 1.0f - d[3];
      return s[3] < inverse ? s[3] : inverse;
    }
  }
  return 0.0f;
}

// ADD, SUBTRACT, REVERSE_SUBTRACT of two terms; MIN and MAX in SSE's operand order.
inline float blendFunctionFloat(BlendOp op, float a, float b) {
  switch (op) {
    case BlendOp::Add: return a + b;
    case BlendOp::Subtract: return a - b;
    case BlendOp::ReverseSubtract: return b - a;
    case BlendOp::Min: return a < b ? a : b;
    case BlendOp::Max: return a > b ? a : b;
  }
  return 0.0f;
}

[[gnu::noinline]] inline void blendColourSrgb(std::uint8_t* pixel, Vec4 c, const ColourBlend& blend) {
  const BlendState& b = blend.state;
  float s[4] = {c.x, c.y, c.z, c.w};
  for (float& v : s) {
    v = v > 0.0f ? v : 0.0f;  // NaN to 0
    v = v < 1.0f ? v : 1.0f;
  }
  float out[4] = {s[0], s[1], s[2], s[3]};
  if (blend.readsDestination) {
    const float d[4] = {srgbToLinear(pixel[0]), srgbToLinear(pixel[1]), srgbToLinear(pixel[2]),
                        static_cast<float>(pixel[3]) * static_cast<float>(1.0 / 255.0)};
    if (b.enable && !b.logicOpEnable) {
      // The factors lavapipe hands llvmpipe: ONE for MIN and MAX.
      const bool colourMinMax = b.colorBlendOp == BlendOp::Min || b.colorBlendOp == BlendOp::Max;
      const bool alphaMinMax = b.alphaBlendOp == BlendOp::Min || b.alphaBlendOp == BlendOp::Max;
      const BlendFactor colourSource = colourMinMax ? BlendFactor::One : b.srcColorBlendFactor;
      const BlendFactor colourDestination = colourMinMax ? BlendFactor::One : b.dstColorBlendFactor;
      const BlendFactor alphaSource = alphaMinMax ? BlendFactor::One : b.srcAlphaBlendFactor;
      const BlendFactor alphaDestination = alphaMinMax ? BlendFactor::One : b.dstAlphaBlendFactor;
      const bool sameFactors = colourSource == colourDestination && alphaSource == alphaDestination;
      for (int i = 0; i < 4; ++i) {
        const BlendOp op = i < 3 ? b.colorBlendOp : b.alphaBlendOp;
        const BlendFactor source = i < 3 ? colourSource : alphaSource;
        const BlendFactor destination = i < 3 ? colourDestination : alphaDestination;
        if (op == BlendOp::Min || op == BlendOp::Max) {
          out[i] = blendFunctionFloat(op, s[i], d[i]);
        } else if (sameFactors) {
          out[i] = blendFunctionFloat(op, s[i], d[i]) * blendFactorFloat(source, i, s, d, blend.linearConstants);
        } else {
          out[i] = blendFunctionFloat(op, s[i] * blendFactorFloat(source, i, s, d, blend.linearConstants),
                                      d[i] * blendFactorFloat(destination, i, s, d, blend.linearConstants));
        }
      }
    }
    for (int i = 0; i < 4; ++i) {
      if (!(b.colorWriteMask & (1u << i))) out[i] = d[i];
    }
  }
  pixel[0] = linearToSrgbByte(out[0]);
  pixel[1] = linearToSrgbByte(out[1]);
  pixel[2] = linearToSrgbByte(out[2]);
  pixel[3] = unorm8FromFloat(out[3]);
}

// ---- A2B10G10R10 targets: lavapipe's 16-bit integer path (lp_state_fs.c) ----
// lp_blend_type_from_format_desc widens the format's channels to a 16-bit UNORM blend type, and
// convert_to_blend_type / convert_from_blend_type rescale with scale_bits:
//   - the source colour and the blend constants are converted by unorm16FromFloat;
//   - the destination's 10-bit v is widened to (v << 6) | (v >> 4), its 2-bit alpha a to a
//     repeated eight times (a * 0x5555);
//   - blending, the logic op and the write mask are the 8-bit path's arithmetic with 65535 for
//     one and mulUnorm16 (lp_build_blend_aos on the 16-bit type);
//   - the result is narrowed again: red, green and blue by v >> 6 (scale_bits' single shift, a
//     truncation, so even a plain store is not round(x * 1023)), alpha by
//     ((v >> 2) * 3 + (1 << 13)) >> 14. Both narrowings invert the widenings, so a component the
//     write mask leaves keeps its bits.

inline int widenTenBit(std::uint32_t v) { return static_cast<int>((v << 6) | (v >> 4)); }
inline int widenTwoBit(std::uint32_t a) { return static_cast<int>(a * 0x5555u); }
inline std::uint32_t narrowToTenBit(int v) { return static_cast<std::uint32_t>(v) >> 6; }
inline std::uint32_t narrowToTwoBit(int v) { return ((static_cast<std::uint32_t>(v) >> 2) * 3u + (1u << 13)) >> 14; }

[[gnu::noinline]] inline void blendColourTenBit(std::uint8_t* pixel, Vec4 c, const ColourBlend& blend) {
  const BlendState& b = blend.state;
  int out[4] = {unorm16FromFloat(c.x), unorm16FromFloat(c.y), unorm16FromFloat(c.z), unorm16FromFloat(c.w)};
  if (blend.readsDestination) {
    std::uint32_t word;
    std::memcpy(&word, pixel, sizeof word);
    const int s[4] = {out[0], out[1], out[2], out[3]};
    const int d[4] = {widenTenBit(tenBitChannel(word, 0)), widenTenBit(tenBitChannel(word, 1)),
                      widenTenBit(tenBitChannel(word, 2)), widenTwoBit(tenBitChannel(word, 3))};
    for (int i = 0; i < 4; ++i) {
      if (!(b.colorWriteMask & (1u << i))) {
        out[i] = d[i];
      } else if (b.logicOpEnable) {  // blending is off whatever b.enable says
        out[i] = logicOpUnorm(b.logicOp, s[i], d[i], 0xffff);
      } else if (b.enable) {
        out[i] = i < 3 ? blendChannelUnorm<65535>(b.colorBlendOp, b.srcColorBlendFactor, b.dstColorBlendFactor, i, s, d,
                                                   blend.constants16)
                       : blendChannelUnorm<65535>(b.alphaBlendOp, b.srcAlphaBlendFactor, b.dstAlphaBlendFactor, i, s, d,
                                                   blend.constants16);
      }
    }
  }
  const std::uint32_t word =
      packTenBit(narrowToTenBit(out[0]), narrowToTenBit(out[1]), narrowToTenBit(out[2]), narrowToTwoBit(out[3]));
  std::memcpy(pixel, &word, sizeof word);
}

// ---- Float targets: lavapipe's float path without clamping (lp_state_fs.c, lp_bld_blend*.c) ----
//   - the shader's output, the blend constants and the destination are used as they are: no
//     clamp, NaN kept (an R16G16B16A16 destination widened exactly, floatFromHalf);
//   - blending is float per channel, unfused, as on sRGB targets (the same-factor shortcut
//     (s op d) * f; MIN and MAX unweighted, minps/maxps operand order: `s < d ? s : d`, so a NaN
//     in either gives d), with lp_build_blend's constant shortcuts: a factor that is ONE (ZERO) for
//     colour and alpha alike is the constant vector, so its term is the value itself (a constant
//     zero that an add or subtract then skips), where a mixed factor vector is really multiplied;
//   - a logic op is not applied (lp_build_blend_aos stores the source); the write mask keeps the
//     destination's bits;
//   - R32G32B32A32 arithmetic runs under the rasterizer threads' FTZ and DAZ (a denormal operand
//     or result is a zero of its sign); for R16G16B16A16 generate_unswizzled_blend turns both off
//     around the blend and the store, which narrows toward zero (halfFromFloatTowardZero).

// A blend term or result: a float, or lavapipe's constant zero vector.
struct FloatTerm {
  float value = 0.0f;
  bool constantZero = false;
};

[[gnu::noinline]] inline void blendColourFloat(std::uint8_t* pixel, Vec4 c, const ColourBlend& blend) {
  const BlendState& b = blend.state;
  const bool half = blend.floatFormat == ColourFormat::R16G16B16A16Sfloat;
  auto in = [half](float x) { return half ? x : flushDenormal(x); };  // DAZ for R32G32B32A32
  auto mul = [&](float x, float y) { return in(in(x) * in(y)); };
  auto add = [&](FloatTerm x, FloatTerm y) {
    if (x.constantZero) return y;
    if (y.constantZero) return x;
    return FloatTerm{in(in(x.value) + in(y.value))};
  };
  auto subtract = [&](FloatTerm x, FloatTerm y) {  // lp_build_sub: x - 0 is x; 0 - 0 is 0
    if (y.constantZero) return x;
    return FloatTerm{in(in(x.value) - in(y.value))};
  };
  const float s[4] = {c.x, c.y, c.z, c.w};
  float d[4];
  std::uint16_t halves[4] = {0, 0, 0, 0};
  if (half) {
    std::memcpy(halves, pixel, sizeof halves);
    for (int i = 0; i < 4; ++i) d[i] = floatFromHalf(halves[i]);
  } else {
    std::memcpy(d, pixel, sizeof d);
  }
  float out[4] = {s[0], s[1], s[2], s[3]};
  if (b.enable && !b.logicOpEnable) {
    const bool colourMinMax = b.colorBlendOp == BlendOp::Min || b.colorBlendOp == BlendOp::Max;
    const bool alphaMinMax = b.alphaBlendOp == BlendOp::Min || b.alphaBlendOp == BlendOp::Max;
    const BlendFactor colourSource = colourMinMax ? BlendFactor::One : b.srcColorBlendFactor;
    const BlendFactor colourDestination = colourMinMax ? BlendFactor::One : b.dstColorBlendFactor;
    const BlendFactor alphaSource = alphaMinMax ? BlendFactor::One : b.srcAlphaBlendFactor;
    const BlendFactor alphaDestination = alphaMinMax ? BlendFactor::One : b.dstAlphaBlendFactor;
    const bool sameFactors = colourSource == colourDestination && alphaSource == alphaDestination;
    // ONE or ZERO for colour and alpha alike: lp_build_blend_factor returns the constant vector.
    auto constantFactor = [](BlendFactor colour, BlendFactor alpha) {
      return colour == alpha && (colour == BlendFactor::One || colour == BlendFactor::Zero);
    };
    const bool sourceConstant = constantFactor(colourSource, alphaSource);
    const bool destinationConstant = constantFactor(colourDestination, alphaDestination);
    auto term = [&](float x, BlendFactor f, bool constant, int i) {
      if (constant) return f == BlendFactor::One ? FloatTerm{x} : FloatTerm{0.0f, true};
      return FloatTerm{mul(x, blendFactorFloat(f, i, s, d, blend.floatConstants))};
    };
    for (int i = 0; i < 4; ++i) {
      const BlendOp op = i < 3 ? b.colorBlendOp : b.alphaBlendOp;
      const BlendFactor source = i < 3 ? colourSource : alphaSource;
      const BlendFactor destination = i < 3 ? colourDestination : alphaDestination;
      if (op == BlendOp::Min || op == BlendOp::Max) {
        const float x = in(s[i]), y = in(d[i]);
        out[i] = op == BlendOp::Min ? (x < y ? x : y) : (x > y ? x : y);
        continue;
      }
      FloatTerm result;
      if (sameFactors) {  // (s op d) * factor
        const FloatTerm x{s[i]}, y{d[i]};
        result = op == BlendOp::Add ? add(x, y) : op == BlendOp::Subtract ? subtract(x, y) : subtract(y, x);
        result = term(result.value, source, sourceConstant, i);
      } else {
        const FloatTerm x = term(s[i], source, sourceConstant, i), y = term(d[i], destination, destinationConstant, i);
        result = op == BlendOp::Add ? add(x, y) : op == BlendOp::Subtract ? subtract(x, y) : subtract(y, x);
      }
      out[i] = result.value;
    }
  }
  if (half) {
    for (int i = 0; i < 4; ++i) {
      if (b.colorWriteMask & (1u << i)) halves[i] = halfFromFloatTowardZero(out[i]);
    }
    std::memcpy(pixel, halves, sizeof halves);
  } else {
    for (int i = 0; i < 4; ++i) {
      if (b.colorWriteMask & (1u << i)) std::memcpy(pixel + 4 * i, &out[i], sizeof out[i]);
    }
  }
}

// The colour output of one fragment (or sample) into its RGBA8 (or BGRA8) pixel: the store, or
// blending in 8-bit integers as lavapipe blends UNORM8 targets, then the write mask. (sRGB,
// A2B10G10R10 and float pixels: their own paths above.)
[[gnu::always_inline]] inline void blendColour(std::uint8_t* pixel, Vec4 c, const ColourBlend& blend) {
  if (blend.floatFormat != ColourFormat::R8G8B8A8Unorm) {
    blendColourFloat(pixel, c, blend);
    return;
  }
  if (blend.tenBit) {
    blendColourTenBit(pixel, c, blend);
    return;
  }
  if (blend.swapRedBlue) std::swap(c.x, c.z);
  if (blend.srgb) {
    blendColourSrgb(pixel, c, blend);
    return;
  }
  if (!blend.readsDestination) {
    storeColour(pixel, c);
    return;
  }
  const BlendState& b = blend.state;
  const int s[4] = {unorm8FromFloat(c.x), unorm8FromFloat(c.y), unorm8FromFloat(c.z), unorm8FromFloat(c.w)};
  const int d[4] = {pixel[0], pixel[1], pixel[2], pixel[3]};
  for (int i = 0; i < 4; ++i) {
    if (!(b.colorWriteMask & (1u << i))) continue;
    int out = s[i];
    if (b.logicOpEnable) {  // blending is off whatever b.enable says
      out = logicOp8(b.logicOp, s[i], d[i]);
    } else if (b.enable) {
      out = i < 3 ? blendChannel8(b.colorBlendOp, b.srcColorBlendFactor, b.dstColorBlendFactor, i, s, d, blend.constants)
                  : blendChannel8(b.alphaBlendOp, b.srcAlphaBlendFactor, b.dstAlphaBlendFactor, i, s, d, blend.constants);
    }
    pixel[i] = static_cast<std::uint8_t>(out);
  }
}

}  // namespace softraster::detail
