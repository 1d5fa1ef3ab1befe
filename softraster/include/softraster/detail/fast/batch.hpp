// The fast path's SIMD building blocks, for one 4x2 block of pixels (kBatchLanes = 8 lanes;
// lane = 4 * row + column, so lanes 0-3 are one row and lanes 4-7 the next, and the block is two
// 2x2 quads side by side): 64-bit edge tests, plane evaluation with the same fmuladd the scalar
// path uses, the depth range clamp, depth storage conversion and test, UNORM8 colour conversion,
// blending, and masked loads and stores of one block's colour and depth.
// Every operation is the scalar path's operation per lane (same order, same rounding, FMA exactly
// where the scalar path fuses), so the results are the same bits; two are shorter but give the
// same bits for every input they can get, each checked over every class of float by a test: the
// depth clamp (one clamp for a range inside [0, 1]) and UNORM8 packing (the packs clamp below 0).
// AVX2 + FMA code (SOFTRASTER_FAST_TARGET), inlined into the fast path's entry point only; GCC
// only (Clang rejects the by-value batches across targets) and not at -O0 (no inlining, so ABIs differ).
// Deliberately absent: coverage walking and shading (fast/fragments.hpp), AVX-512 (16 lanes).
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__NO_INLINE__)  // see the top
#define SOFTRASTER_HAS_FAST_PATH 1
#include <immintrin.h>
#define SOFTRASTER_FAST_TARGET gnu::target("avx2,fma")
#else
#define SOFTRASTER_HAS_FAST_PATH 0
#endif

#if SOFTRASTER_HAS_FAST_PATH

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/formats.hpp>
#include <softraster/simd.hpp>
#include <softraster/state.hpp>

#include <cassert>
#include <cstddef>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster::detail::fast {

// Whether this CPU runs the fast path (AVX2 for the lanes, FMA for lavapipe's fused fmuladd).
inline bool cpuRunsFastPath() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }

// Whether this CPU (and its OS) runs AVX-512 F, VL, BW and DQ: a block pair's 16 lanes in one register.
inline bool cpuShadesWidePairs() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
         __builtin_cpu_supports("avx512dq");
}

inline constexpr int kBatchWidth = 4, kBatchHeight = 2;

using Floats = FloatBatch::Native;
using Mask = FloatBatch::NativeMask;  // per lane: -1 (true) or 0
using Words = std::uint32_t __attribute__((vector_size(32)));

inline constexpr Floats kLaneX = {0, 1, 2, 3, 0, 1, 2, 3};
inline constexpr Floats kLaneY = {0, 0, 0, 0, 1, 1, 1, 1};

[[SOFTRASTER_FAST_TARGET]] inline Floats broadcast(float s) { return reinterpret_cast<Floats>(_mm256_set1_ps(s)); }
[[SOFTRASTER_FAST_TARGET]] inline Words broadcastWord(std::uint32_t s) {
  return reinterpret_cast<Words>(_mm256_set1_epi32(static_cast<int>(s)));
}

// Lane mask (-1 or 0 per lane) of the low 8 bits of `bits`.
[[SOFTRASTER_FAST_TARGET]] inline Mask laneMask(unsigned bits) {
  const Mask b = reinterpret_cast<Mask>(_mm256_set1_epi32(static_cast<int>(bits)));
  return (b & Mask{1, 2, 4, 8, 16, 32, 64, 128}) != 0;
}

// Per lane: `yes` where `mask` is set (all ones), `no` where it is clear (one blend).
[[SOFTRASTER_FAST_TARGET]] inline Words selectLanes(Mask mask, Words yes, Words no) {
  return reinterpret_cast<Words>(_mm256_blendv_epi8(reinterpret_cast<__m256i>(no), reinterpret_cast<__m256i>(yes),
                                                    reinterpret_cast<__m256i>(mask)));
}

[[SOFTRASTER_FAST_TARGET]] inline unsigned maskBits(Mask m) {
  return static_cast<unsigned>(_mm256_movemask_ps(reinterpret_cast<__m256>(m)));
}

// fmuladd(a, b, c) fused, as the scalar path's fmuladd<true>.
[[SOFTRASTER_FAST_TARGET]] inline Floats fmuladd(Floats a, Floats b, Floats c) {
  return reinterpret_cast<Floats>(
      _mm256_fmadd_ps(reinterpret_cast<__m256>(a), reinterpret_cast<__m256>(b), reinterpret_cast<__m256>(c)));
}

// A plane equation with its coefficients in every lane (set up once per primitive).
struct BatchPlane {
  Floats a0, dadx, dady;
};

[[SOFTRASTER_FAST_TARGET]] inline BatchPlane batchPlane(const PlaneEquation& p) {
  return {broadcast(p.a0), broadcast(p.dadx), broadcast(p.dady)};
}

// evaluatePlane<true> per lane: fmuladd(dady, py, fmuladd(dadx, px, a0)).
[[SOFTRASTER_FAST_TARGET]] inline Floats evaluatePlane(const BatchPlane& p, Floats px, Floats py) {
  return fmuladd(p.dady, py, fmuladd(p.dadx, px, p.a0));
}

// The E edge functions of a primitive (3: a triangle, 4: a line or point quad) over one block:
// value at the block's first lane plus a constant offset per lane (-dcdx * column + dcdy * row),
// in two halves of four 64-bit lanes (rows 0 and 1).
template <int E>
struct BlockEdges {
  __m256i offsetRow0[E], offsetRow1[E];
};

template <int E>
[[SOFTRASTER_FAST_TARGET]] inline BlockEdges<E> blockEdges(const EdgeFunction (&edges)[E]) {
  BlockEdges<E> b;
  for (int i = 0; i < E; ++i) {
    const std::int64_t dx = edges[i].dcdx, dy = edges[i].dcdy;
    b.offsetRow0[i] = _mm256_set_epi64x(-3 * dx, -2 * dx, -dx, 0);
    b.offsetRow1[i] = _mm256_add_epi64(b.offsetRow0[i], _mm256_set1_epi64x(dy));
  }
  return b;
}

// Bit l set where lane l is strictly inside all E edges (value > 0), `first` the edge values
// at lane 0, each in every lane of its vector.
template <int E>
[[SOFTRASTER_FAST_TARGET]] inline unsigned insideBits(const BlockEdges<E>& b, const __m256i (&first)[E]) {
  const __m256i zero = _mm256_setzero_si256();
  __m256i row0 = _mm256_set1_epi64x(-1), row1 = row0;
  for (int i = 0; i < E; ++i) {
    row0 = _mm256_and_si256(row0, _mm256_cmpgt_epi64(_mm256_add_epi64(first[i], b.offsetRow0[i]), zero));
    row1 = _mm256_and_si256(row1, _mm256_cmpgt_epi64(_mm256_add_epi64(first[i], b.offsetRow1[i]), zero));
  }
  const unsigned bits0 = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(row0)));
  const unsigned bits1 = static_cast<unsigned>(_mm256_movemask_pd(_mm256_castsi256_pd(row1)));
  return bits0 | (bits1 << 4);
}

// The same, `first` as integers.
template <int E>
[[SOFTRASTER_FAST_TARGET]] inline unsigned insideBits(const BlockEdges<E>& b, const std::int64_t (&first)[E]) {
  __m256i broadcast[E];
  for (int i = 0; i < E; ++i) broadcast[i] = _mm256_set1_epi64x(first[i]);
  return insideBits(b, broadcast);
}

// clampDepth per lane: the scalar max(min(max(min(z, 1), 0), range.max), range.min) in one clamp,
// max(min(z, range.max), range.min), which gives the same bits whenever 0 <= range.min and
// range.max <= 1 (a NaN or z >= 1 gives range.max, z <= 0 range.min, signed zeros as the scalar's:
// minps(a, b) is a < b ? a : b and maxps(a, b) a > b ? a : b). A DepthRange always is in [0, 1]:
// fragmentDepthRange takes it from a viewport the draw checked to be
// (tests/softraster/depth_tiles_test.cpp compares the two over every class of z).
[[SOFTRASTER_FAST_TARGET]] inline Floats clampDepth(Floats z, DepthRange range) {
  assert(range.min >= 0.0f && range.max <= 1.0f);
  const __m256 v = _mm256_max_ps(_mm256_min_ps(reinterpret_cast<__m256>(z), _mm256_set1_ps(range.max)), _mm256_set1_ps(range.min));
  return reinterpret_cast<Floats>(v);
}

// depthToStorage<Format> per lane.
template <DepthFormat Format>
[[SOFTRASTER_FAST_TARGET]] inline Words depthToStorage(Floats z) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return reinterpret_cast<Words>(z);
  } else if constexpr (Format == DepthFormat::X8D24UnormPack32) {
    // cvtps2dq rounds half to even, as nearbyint does in the default rounding mode.
    return reinterpret_cast<Words>(_mm256_cvtps_epi32(reinterpret_cast<__m256>(z * broadcast(16777215.0f))));
  } else {
    const Floats shifted = z * broadcast(65535.0f / 65536.0f) + broadcast(128.0f);
    return reinterpret_cast<Words>(shifted) & broadcastWord(0xffffu);
  }
}

// compare(op, incoming, stored) per lane: floats for D32_SFLOAT, unsigned integers otherwise.
// (Compiled for the fast path's target like every function here that takes or returns a vector:
// out of line, as in the sanitizer build at -O1, a copy without it takes its vectors in memory
// while its AVX2 callers pass them in registers.)
template <class V>
[[SOFTRASTER_FAST_TARGET]] inline Mask compareLanes(CompareOp op, V incoming, V stored) {
  if (op == CompareOp::Less) return reinterpret_cast<Mask>(incoming < stored);  // the common op, without the jump table
  switch (op) {
    case CompareOp::Never: return Mask{};
    case CompareOp::Less: return reinterpret_cast<Mask>(incoming < stored);
    case CompareOp::Equal: return reinterpret_cast<Mask>(incoming == stored);
    case CompareOp::LessOrEqual: return reinterpret_cast<Mask>(incoming <= stored);
    case CompareOp::Greater: return reinterpret_cast<Mask>(incoming > stored);
    case CompareOp::NotEqual: return reinterpret_cast<Mask>(incoming != stored);
    case CompareOp::GreaterOrEqual: return reinterpret_cast<Mask>(incoming >= stored);
    case CompareOp::Always: return ~Mask{};
  }
  return Mask{};
}

template <DepthFormat Format>
[[SOFTRASTER_FAST_TARGET]] inline Mask depthTestPasses(CompareOp op, Words incoming, Words stored) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return compareLanes(op, reinterpret_cast<Floats>(incoming), reinterpret_cast<Floats>(stored));
  } else {
    return compareLanes(op, incoming, stored);
  }
}

// unorm8FromFloat per lane: clamp to [0, 1] (NaN to 0), times 255, round half to even.
// SSE max(v, 0) then min(., 1) is the scalar clamp exactly (maxps returns its second operand for
// a NaN, and +0 for -0); cvtps2dq rounds as the scalar path's add and subtract of 2^23 do, in the
// current rounding mode (half to even by default), to an integer in [0, 255].
[[SOFTRASTER_FAST_TARGET]] inline Words unorm8FromFloat(Floats v) {
  const __m256 clamped = _mm256_min_ps(_mm256_max_ps(reinterpret_cast<__m256>(v), _mm256_setzero_ps()),
                                       _mm256_set1_ps(1.0f));
  return reinterpret_cast<Words>(_mm256_cvtps_epi32(_mm256_mul_ps(clamped, _mm256_set1_ps(255.0f))));
}

// unorm8FromFloat but for the clamp below 0 (packColour's packs do it), as a signed 32-bit integer.
[[SOFTRASTER_FAST_TARGET]] inline __m256i unorm8BeforePacking(Floats v) {
  return _mm256_cvtps_epi32(
      _mm256_mul_ps(_mm256_min_ps(_mm256_set1_ps(1.0f), reinterpret_cast<__m256>(v)), _mm256_set1_ps(255.0f)));
}

// The lanes' colours as stored: RGBA8, or with swapRedBlue BGRA8 (ColourBlend::swapRedBlue).
// Each channel as unorm8FromFloat, with the clamp below 0 left to the packs: min(1, v) keeps a
// NaN (minps returns its second operand), and cvtps2dq makes a NaN, -inf or any negative product
// a negative integer (or 0 for a product rounding to -0), which the signed-saturating packs take to 0,
// as the clamp would; [0, 1] is multiplied and rounded exactly as there. The packs interleave
// per 128-bit half (four pixels of a row: r0-3 g0-3 b0-3 a0-3), and one byte shuffle per half
// puts each pixel's four bytes together.
[[SOFTRASTER_FAST_TARGET]] inline Words packColour(const Vec4T<FloatBatch>& c, bool swapRedBlue) {
  const __m256i red = unorm8BeforePacking(c.x.native()), green = unorm8BeforePacking(c.y.native()),
                blue = unorm8BeforePacking(c.z.native()), alpha = unorm8BeforePacking(c.w.native());
  const __m256i low = _mm256_packus_epi32(swapRedBlue ? blue : red, green);
  const __m256i high = _mm256_packus_epi32(swapRedBlue ? red : blue, alpha);
  const __m256i channelMajor = _mm256_packus_epi16(low, high);
  const __m256i pixelMajor = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15,  //
                                              0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
  return reinterpret_cast<Words>(_mm256_shuffle_epi8(channelMajor, pixelMajor));
}

// blendColour per lane on packed RGBA8 (fragment/colour.hpp's arithmetic, 32 bytes at a time):
// factors as bytes, the products in 16-bit lanes, saturating 8-bit adds and subtractions, byte
// min and max, or a logic op on the bytes, then the write mask.
[[SOFTRASTER_FAST_TARGET]] inline __m256i bytesOf(Words w) { return reinterpret_cast<__m256i>(w); }

// Each pixel's alpha byte in all four of its bytes.
[[SOFTRASTER_FAST_TARGET]] inline __m256i alphaInEveryByte(__m256i v) {
  const __m256i alpha = _mm256_setr_epi8(3, 3, 3, 3, 7, 7, 7, 7, 11, 11, 11, 11, 15, 15, 15, 15,  //
                                         3, 3, 3, 3, 7, 7, 7, 7, 11, 11, 11, 11, 15, 15, 15, 15);
  return _mm256_shuffle_epi8(v, alpha);
}

// The inputs every factor is made of, per pixel: source, destination, their alphas, the constants.
struct BlendInputs {
  __m256i s, d, sa, da, k, ka;
};

// 255 - v in every byte.
[[SOFTRASTER_FAST_TARGET]] inline __m256i inverse(__m256i v) { return _mm256_xor_si256(v, _mm256_set1_epi8(-1)); }

// blendFactorUnorm<255> on bytes: the factor for the colour channels (alpha = false) or for alpha.
[[SOFTRASTER_FAST_TARGET]] inline __m256i factorBytes(BlendFactor f, bool alpha, const BlendInputs& in) {
  const __m256i ones = _mm256_set1_epi8(-1);
  switch (f) {
    case BlendFactor::Zero: return _mm256_setzero_si256();
    case BlendFactor::One: return ones;
    case BlendFactor::SrcColor: return in.s;
    case BlendFactor::OneMinusSrcColor: return inverse(in.s);
    case BlendFactor::DstColor: return in.d;
    case BlendFactor::OneMinusDstColor: return inverse(in.d);
    case BlendFactor::SrcAlpha: return in.sa;
    case BlendFactor::OneMinusSrcAlpha: return inverse(in.sa);
    case BlendFactor::DstAlpha: return in.da;
    case BlendFactor::OneMinusDstAlpha: return inverse(in.da);
    case BlendFactor::ConstantColor: return in.k;
    case BlendFactor::OneMinusConstantColor: return inverse(in.k);
    case BlendFactor::ConstantAlpha: return in.ka;
    case BlendFactor::OneMinusConstantAlpha: return inverse(in.ka);
    case BlendFactor::SrcAlphaSaturate: return alpha ? ones : _mm256_min_epu8(in.sa, inverse(in.da));
  }
  return _mm256_setzero_si256();
}

// mulUnorm8 (fragment/colour.hpp) on 16-bit lanes holding bytes, and on bytes: both halves widened to 16 bits, (t + (t >> 8) + 128) >> 8, packed back
// (unpack and pack work within 128-bit lanes alike, so the bytes return to their places).
[[SOFTRASTER_FAST_TARGET]] inline __m256i mulUnorm16(__m256i a, __m256i b) {
  const __m256i t = _mm256_mullo_epi16(a, b);
  return _mm256_srli_epi16(_mm256_add_epi16(_mm256_add_epi16(t, _mm256_srli_epi16(t, 8)), _mm256_set1_epi16(128)), 8);
}

[[SOFTRASTER_FAST_TARGET]] inline __m256i mulUnorm8(__m256i x, __m256i f) {
  const __m256i zero = _mm256_setzero_si256();
  const __m256i lo = mulUnorm16(_mm256_unpacklo_epi8(x, zero), _mm256_unpacklo_epi8(f, zero));
  const __m256i hi = mulUnorm16(_mm256_unpackhi_epi8(x, zero), _mm256_unpackhi_epi8(f, zero));
  return _mm256_packus_epi16(lo, hi);
}

// A blend term: the product, with the ZERO and ONE factors (both channel groups alike) skipped.
[[SOFTRASTER_FAST_TARGET]] inline __m256i blendTerm(__m256i x, __m256i factor, BlendFactor colour, BlendFactor alpha) {
  if (colour == BlendFactor::One && alpha == BlendFactor::One) return x;
  if (colour == BlendFactor::Zero && alpha == BlendFactor::Zero) return _mm256_setzero_si256();
  return mulUnorm8(x, factor);
}

[[SOFTRASTER_FAST_TARGET]] inline __m256i blendOpBytes(BlendOp op, __m256i s, __m256i d, __m256i st, __m256i dt) {
  switch (op) {
    case BlendOp::Add: return _mm256_adds_epu8(st, dt);
    case BlendOp::Subtract: return _mm256_subs_epu8(st, dt);
    case BlendOp::ReverseSubtract: return _mm256_subs_epu8(dt, st);
    case BlendOp::Min: return _mm256_min_epu8(s, d);
    case BlendOp::Max: return _mm256_max_epu8(s, d);
  }
  return s;
}

// logicOp8 (fragment/colour.hpp) on every byte.
[[SOFTRASTER_FAST_TARGET]] inline __m256i logicOpBytes(LogicOp op, __m256i s, __m256i d) {
  switch (op) {
    case LogicOp::Clear: return _mm256_setzero_si256();
    case LogicOp::And: return _mm256_and_si256(s, d);
    case LogicOp::AndReverse: return _mm256_andnot_si256(d, s);
    case LogicOp::Copy: return s;
    case LogicOp::AndInverted: return _mm256_andnot_si256(s, d);
    case LogicOp::NoOp: return d;
    case LogicOp::Xor: return _mm256_xor_si256(s, d);
    case LogicOp::Or: return _mm256_or_si256(s, d);
    case LogicOp::Nor: return inverse(_mm256_or_si256(s, d));
    case LogicOp::Equivalent: return inverse(_mm256_xor_si256(s, d));
    case LogicOp::Invert: return inverse(d);
    case LogicOp::OrReverse: return _mm256_or_si256(s, inverse(d));
    case LogicOp::CopyInverted: return inverse(s);
    case LogicOp::OrInverted: return _mm256_or_si256(inverse(s), d);
    case LogicOp::Nand: return inverse(_mm256_and_si256(s, d));
    case LogicOp::Set: return _mm256_set1_epi8(-1);
  }
  return s;
}

[[SOFTRASTER_FAST_TARGET]] inline Words blendColour(Words source, Words destination, const ColourBlend& blend) {
  if (!blend.readsDestination) return source;
  const BlendState& b = blend.state;
  const __m256i s = bytesOf(source), d = bytesOf(destination);
  const __m256i alphaBytes = _mm256_set1_epi32(static_cast<int>(0xff000000u));
  __m256i out = s;
  if (b.logicOpEnable) {  // blending is off whatever b.enable says
    out = logicOpBytes(b.logicOp, s, d);
  } else if (b.enable) {
    const auto k = blend.constants;
    const std::uint32_t packed = k[0] | (k[1] << 8) | (k[2] << 16) | (std::uint32_t{k[3]} << 24);
    const BlendInputs in{s, d, alphaInEveryByte(s), alphaInEveryByte(d), _mm256_set1_epi32(static_cast<int>(packed)),
                         _mm256_set1_epi8(static_cast<char>(k[3]))};
    const __m256i sf = _mm256_blendv_epi8(factorBytes(b.srcColorBlendFactor, false, in),
                                          factorBytes(b.srcAlphaBlendFactor, true, in), alphaBytes);
    const __m256i df = _mm256_blendv_epi8(factorBytes(b.dstColorBlendFactor, false, in),
                                          factorBytes(b.dstAlphaBlendFactor, true, in), alphaBytes);
    const __m256i st = blendTerm(s, sf, b.srcColorBlendFactor, b.srcAlphaBlendFactor);
    const __m256i dt = blendTerm(d, df, b.dstColorBlendFactor, b.dstAlphaBlendFactor);
    out = blendOpBytes(b.colorBlendOp, s, d, st, dt);
    if (b.alphaBlendOp != b.colorBlendOp) {
      out = _mm256_blendv_epi8(out, blendOpBytes(b.alphaBlendOp, s, d, st, dt), alphaBytes);
    }
  }
  if ((b.colorWriteMask & kColourRGBA) != kColourRGBA) {
    std::uint32_t keep = 0;
    for (int i = 0; i < 4; ++i) keep |= (b.colorWriteMask & (1u << i)) ? 0xffu << (8 * i) : 0u;
    const __m256i m = _mm256_set1_epi32(static_cast<int>(keep));
    out = _mm256_or_si256(_mm256_and_si256(out, m), _mm256_andnot_si256(m, d));
  }
  return reinterpret_cast<Words>(out);
}

// One block's 32-bit values (colour as packed RGBA8, or depth as stored) at `first` (lane 0) in
// an image `stride` values wide; only the lanes in `bits` are read or written, so a block may
// overhang the image.
[[SOFTRASTER_FAST_TARGET]] inline Words loadBlock(const std::uint32_t* first, std::size_t stride, unsigned bits) {
  const __m256i mask = reinterpret_cast<__m256i>(laneMask(bits));
  const __m128i row0 = _mm_maskload_epi32(reinterpret_cast<const int*>(first), _mm256_castsi256_si128(mask));
  __m128i row1 = _mm_setzero_si128();
  if (bits >> 4) row1 = _mm_maskload_epi32(reinterpret_cast<const int*>(first + stride), _mm256_extracti128_si256(mask, 1));
  return reinterpret_cast<Words>(_mm256_set_m128i(row1, row0));
}

// The same for a block wholly inside the image (all eight lanes): plain loads and stores.
[[SOFTRASTER_FAST_TARGET]] inline Words loadFullBlock(const std::uint32_t* first, std::size_t stride) {
  const __m128i row0 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(first));
  const __m128i row1 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(first + stride));
  return reinterpret_cast<Words>(_mm256_set_m128i(row1, row0));
}

[[SOFTRASTER_FAST_TARGET]] inline void storeFullBlock(std::uint32_t* first, std::size_t stride, Words values) {
  const __m256i v = reinterpret_cast<__m256i>(values);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(first), _mm256_castsi256_si128(v));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(first + stride), _mm256_extracti128_si256(v, 1));
}

// Eight consecutive 32-bit values (the four samples of two adjacent pixels, with 4x MSAA); only
// the lanes in `bits` are read or written (all eight: plain loads and stores).
[[SOFTRASTER_FAST_TARGET]] inline Words loadWords(const std::uint32_t* first, unsigned bits = 0xffu) {
  if (bits == 0xffu) return reinterpret_cast<Words>(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(first)));
  return reinterpret_cast<Words>(
      _mm256_maskload_epi32(reinterpret_cast<const int*>(first), reinterpret_cast<__m256i>(laneMask(bits))));
}

[[SOFTRASTER_FAST_TARGET]] inline void storeWords(std::uint32_t* first, unsigned bits, Words values) {
  if (bits == 0xffu) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(first), reinterpret_cast<__m256i>(values));
  } else {
    _mm256_maskstore_epi32(reinterpret_cast<int*>(first), reinterpret_cast<__m256i>(laneMask(bits)),
                           reinterpret_cast<__m256i>(values));
  }
}

[[SOFTRASTER_FAST_TARGET]] inline void storeBlock(std::uint32_t* first, std::size_t stride, unsigned bits, Words values) {
  const __m256i mask = reinterpret_cast<__m256i>(laneMask(bits));
  const __m256i v = reinterpret_cast<__m256i>(values);
  _mm_maskstore_epi32(reinterpret_cast<int*>(first), _mm256_castsi256_si128(mask), _mm256_castsi256_si128(v));
  if (bits >> 4) {
    _mm_maskstore_epi32(reinterpret_cast<int*>(first + stride), _mm256_extracti128_si256(mask, 1),
                        _mm256_extracti128_si256(v, 1));
  }
}

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif  // SOFTRASTER_HAS_FAST_PATH
