// The fast path's per-lane operations over 16 lanes (AVX-512 F, VL, BW and DQ), for the runs of
// whole blocks drawn two blocks at a time (fast/fragments.hpp, shadeRunWide): a plane evaluated,
// the depth clamped, converted to its storage and tested, and colours packed, each the same
// operations in the same order as batch.hpp's 8-lane form, so each lane gets the same bits
// (tests/softraster/wide_batch_test.cpp compares them over every class of float).
// Every function is compiled for AVX-512 (SOFTRASTER_WIDE_TARGET) and called from AVX-512 code
// only; comparisons are written here, in that code, because GCC 12 compiles a 16-lane comparison
// outside it to one scalar compare per lane (simd.hpp, floor).
// Deliberately absent: edge tests, partial blocks, stencil, blending and MSAA (batch.hpp's 8 lanes).
#pragma once

#include <softraster/detail/fast/batch.hpp>

#if SOFTRASTER_HAS_FAST_PATH && defined(SOFTRASTER_WIDE_TARGET)

#include <softraster/simd.hpp>
#include <softraster/state.hpp>

#include <cassert>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster::detail::fast {

using WideFloats = NativeLanes<16>::Float;
using WideWords = NativeLanes<16>::Bits;
using WideMask = NativeLanes<16>::Int;

// Lanes 0-7 are a block row's eight pixels (two blocks side by side), lanes 8-15 the row below.
inline constexpr WideFloats kWideLaneX = {0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7};
inline constexpr WideFloats kWideLaneY = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1};

// The zero-masking forms of AVX-512 intrinsics with every lane kept are the plain instructions;
// GCC 12's plain forms start from an undefined vector that -Wmaybe-uninitialized reports.
inline constexpr __mmask16 kAllLanes = 0xffff;

// A plane's coefficients in every one of 16 lanes.
struct WidePlane {
  WideFloats a0, dadx, dady;
};

// A broadcast 8-lane value (every lane the same) in 16 lanes.
[[SOFTRASTER_WIDE_TARGET]] inline WideFloats widen(Floats f) {
  return __builtin_shufflevector(f, f, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7);
}
[[SOFTRASTER_WIDE_TARGET]] inline WidePlane widen(const BatchPlane& p) { return {widen(p.a0), widen(p.dadx), widen(p.dady)}; }

// evaluatePlane over 16 lanes: fmuladd(dady, py, fmuladd(dadx, px, a0)), fused.
[[SOFTRASTER_WIDE_TARGET]] inline WideFloats evaluateWide(const WidePlane& p, WideFloats px, WideFloats py) {
  const __m512 inner = _mm512_fmadd_ps(reinterpret_cast<__m512>(p.dadx), reinterpret_cast<__m512>(px), reinterpret_cast<__m512>(p.a0));
  return reinterpret_cast<WideFloats>(_mm512_fmadd_ps(reinterpret_cast<__m512>(p.dady), reinterpret_cast<__m512>(py), inner));
}

// clampDepth over 16 lanes: max(min(z, range.max), range.min) in minps/maxps operand order.
[[SOFTRASTER_WIDE_TARGET]] inline WideFloats clampDepthWide(WideFloats z, DepthRange range) {
  assert(range.min >= 0.0f && range.max <= 1.0f);  // as clampDepth: one clamp is the scalar two only then
  const __m512 v = _mm512_maskz_max_ps(kAllLanes, _mm512_maskz_min_ps(kAllLanes, reinterpret_cast<__m512>(z), _mm512_set1_ps(range.max)),
                                       _mm512_set1_ps(range.min));
  return reinterpret_cast<WideFloats>(v);
}

// depthToStorage<Format> over 16 lanes.
template <DepthFormat Format>
[[SOFTRASTER_WIDE_TARGET]] inline WideWords depthToStorageWide(WideFloats z) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return reinterpret_cast<WideWords>(z);
  } else if constexpr (Format == DepthFormat::X8D24UnormPack32) {
    return reinterpret_cast<WideWords>(_mm512_maskz_cvtps_epi32(kAllLanes, reinterpret_cast<__m512>(z * 16777215.0f)));
  } else {
    const WideFloats shifted = z * (65535.0f / 65536.0f) + 128.0f;
    return reinterpret_cast<WideWords>(shifted) & 0xffffu;
  }
}

// compareLanes over 16 lanes: bit l set where lane l passes.
template <class V>
[[SOFTRASTER_WIDE_TARGET]] inline unsigned compareWide(CompareOp op, V incoming, V stored) {
  WideMask m{};
  switch (op) {
    case CompareOp::Never: m = WideMask{}; break;
    case CompareOp::Less: m = reinterpret_cast<WideMask>(incoming < stored); break;
    case CompareOp::Equal: m = reinterpret_cast<WideMask>(incoming == stored); break;
    case CompareOp::LessOrEqual: m = reinterpret_cast<WideMask>(incoming <= stored); break;
    case CompareOp::Greater: m = reinterpret_cast<WideMask>(incoming > stored); break;
    case CompareOp::NotEqual: m = reinterpret_cast<WideMask>(incoming != stored); break;
    case CompareOp::GreaterOrEqual: m = reinterpret_cast<WideMask>(incoming >= stored); break;
    case CompareOp::Always: m = ~WideMask{}; break;
  }
  return _mm512_movepi32_mask(reinterpret_cast<__m512i>(m));
}

// depthTestPasses over 16 lanes (floats for D32_SFLOAT, unsigned integers otherwise), as bits.
template <DepthFormat Format>
[[SOFTRASTER_WIDE_TARGET]] inline unsigned depthTestPassesWide(CompareOp op, WideWords incoming, WideWords stored) {
  if constexpr (Format == DepthFormat::D32Sfloat) {
    return compareWide(op, reinterpret_cast<WideFloats>(incoming), reinterpret_cast<WideFloats>(stored));
  } else {
    return compareWide(op, incoming, stored);
  }
}

// unorm8BeforePacking over 16 lanes.
[[SOFTRASTER_WIDE_TARGET]] inline __m512i unorm8BeforePackingWide(const FloatBatch16& v) {
  const __m512 clamped = _mm512_maskz_min_ps(kAllLanes, _mm512_set1_ps(1.0f), reinterpret_cast<__m512>(v.native()));
  return _mm512_maskz_cvtps_epi32(kAllLanes, _mm512_mul_ps(clamped, _mm512_set1_ps(255.0f)));
}

// packColour over 16 lanes: the packs and the byte shuffle work per 128-bit quarter, four lanes'
// pixels each, as they work per half there.
[[SOFTRASTER_WIDE_TARGET]] inline __m512i packColourWide(const Vec4T<FloatBatch16>& c, bool swapRedBlue) {
  const __m512i red = unorm8BeforePackingWide(c.x), green = unorm8BeforePackingWide(c.y), blue = unorm8BeforePackingWide(c.z),
                alpha = unorm8BeforePackingWide(c.w);
  const __m512i low = _mm512_packus_epi32(swapRedBlue ? blue : red, green);
  const __m512i high = _mm512_packus_epi32(swapRedBlue ? red : blue, alpha);
  const __m512i channelMajor = _mm512_packus_epi16(low, high);
  const __m512i pixelMajor = _mm512_maskz_broadcast_i32x4(kAllLanes, _mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
  return _mm512_shuffle_epi8(channelMajor, pixelMajor);
}

// Row `y` of 16 lanes (0: lanes 0-7, 1: lanes 8-15) as 8 words, stored at `at`; with `bits`
// (one per lane of the row) only those lanes.
[[SOFTRASTER_WIDE_TARGET]] inline __m256i wideRow(__m512i v, int y) {
  const auto q = reinterpret_cast<NativeLanes<16>::Int>(v);
  return reinterpret_cast<__m256i>(y == 0 ? __builtin_shufflevector(q, q, 0, 1, 2, 3, 4, 5, 6, 7)
                                          : __builtin_shufflevector(q, q, 8, 9, 10, 11, 12, 13, 14, 15));
}
[[SOFTRASTER_WIDE_TARGET]] inline void storeWideRow(std::uint32_t* at, __m512i v, int y) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(at), wideRow(v, y));
}
[[SOFTRASTER_WIDE_TARGET]] inline void storeWideRow(std::uint32_t* at, __m512i v, int y, unsigned bits) {
  _mm256_mask_storeu_epi32(at, static_cast<__mmask8>(bits), wideRow(v, y));
}

// 8 words at `row0` and 8 at `row1` as 16 lanes.
[[SOFTRASTER_WIDE_TARGET]] inline __m512i loadWideRows(const std::uint32_t* row0, const std::uint32_t* row1) {
  const auto a = reinterpret_cast<NativeLanes<8>::Int>(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row0)));
  const auto b = reinterpret_cast<NativeLanes<8>::Int>(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row1)));
  return reinterpret_cast<__m512i>(__builtin_shufflevector(a, b, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
}

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif
