// Colour output: R8G8B8A8_UNORM stores and blending, as lavapipe's fragment JIT code does them.
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
// Deliberately absent: dual-source factors, other colour formats (sRGB and float targets blend
// in float in lavapipe, and take no logic op).
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

// A draw's BlendState prepared for UNORM8 blending: the blend constants as bytes (converted as
// a store converts), and whether the destination is read at all.
struct ColourBlend {
  BlendState state;
  std::uint8_t constants[4] = {0, 0, 0, 0};
  bool readsDestination = false;  // blending on, or a write mask without every component
};

inline ColourBlend colourBlend(const BlendState& state) {
  ColourBlend b{state};
  for (int i = 0; i < 4; ++i) b.constants[i] = unorm8FromFloat(state.blendConstants[i]);
  b.readsDestination = state.enable || (state.colorWriteMask & kColourRGBA) != kColourRGBA ||
                       (state.logicOpEnable && state.logicOp != LogicOp::Copy);
  return b;
}

// VkLogicOp on one byte (s the source, d the destination), as the table in state.hpp.
inline int logicOp8(LogicOp op, int s, int d) {
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
    case LogicOp::Set: out = 0xff; break;
  }
  return out & 0xff;
}

// x * f / 255 in 16-bit integers, lp_build_mul_norm's geometric series with rounding: the product
// rounded to nearest, except for 24 pairs of bytes (152 * 229 among them), each with
// x * f = 128 (mod 255), where k + 0.502 gives k. lavapipe's output has the same bits
// (scene blend_products).
inline int mulUnorm8(int x, int f) {
  const int t = x * f;
  return (t + (t >> 8) + 128) >> 8;
}

// The factor byte for channel c (3 = alpha) of source s and destination d.
inline int blendFactor8(BlendFactor f, int c, const int (&s)[4], const int (&d)[4], const std::uint8_t (&k)[4]) {
  switch (f) {
    case BlendFactor::Zero: return 0;
    case BlendFactor::One: return 255;
    case BlendFactor::SrcColor: return s[c];
    case BlendFactor::OneMinusSrcColor: return 255 - s[c];
    case BlendFactor::DstColor: return d[c];
    case BlendFactor::OneMinusDstColor: return 255 - d[c];
    case BlendFactor::SrcAlpha: return s[3];
    case BlendFactor::OneMinusSrcAlpha: return 255 - s[3];
    case BlendFactor::DstAlpha: return d[3];
    case BlendFactor::OneMinusDstAlpha: return 255 - d[3];
    case BlendFactor::ConstantColor: return k[c];
    case BlendFactor::OneMinusConstantColor: return 255 - k[c];
    case BlendFactor::ConstantAlpha: return k[3];
    case BlendFactor::OneMinusConstantAlpha: return 255 - k[3];
    case BlendFactor::SrcAlphaSaturate: return c == 3 ? 255 : (s[3] < 255 - d[3] ? s[3] : 255 - d[3]);
  }
  return 0;
}

inline int blendChannel8(BlendOp op, BlendFactor sf, BlendFactor df, int c, const int (&s)[4], const int (&d)[4],
                         const std::uint8_t (&k)[4]) {
  switch (op) {
    case BlendOp::Min: return s[c] < d[c] ? s[c] : d[c];
    case BlendOp::Max: return s[c] > d[c] ? s[c] : d[c];
    default: break;
  }
  const int st = mulUnorm8(s[c], blendFactor8(sf, c, s, d, k));
  const int dt = mulUnorm8(d[c], blendFactor8(df, c, s, d, k));
  switch (op) {
    case BlendOp::Add: return st + dt > 255 ? 255 : st + dt;
    case BlendOp::Subtract: return st > dt ? st - dt : 0;
    case BlendOp::ReverseSubtract: return dt > st ? dt - st : 0;
    default: return 0;
  }
}

// The colour output of one fragment (or sample) into its RGBA8 pixel: the store, or blending in
// 8-bit integers as lavapipe blends UNORM8 targets, then the write mask.
[[gnu::always_inline]] inline void blendColour(std::uint8_t* pixel, Vec4 c, const ColourBlend& blend) {
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
