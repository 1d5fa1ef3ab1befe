// The fast path's stencil test and update for 8 lanes at once (one 4x2 block of pixels, or one
// pair of pixels' eight samples): the scalar fragment/stencil.hpp per lane, on 32-bit lanes
// holding the 8-bit values, so the results are the same bytes.
//   - load and store of 8 stencil bytes (lanes outside `lanes` are neither read nor written);
//   - the masked compare, the op chosen per lane by the two tests' results, the write mask.
// The face is the primitive's, the same for every lane. AVX2 code, as batch.hpp.
// Deliberately absent: the depth test (batch.hpp), the block loops (fast/fragments.hpp).
#pragma once

#include <softraster/detail/fast/batch.hpp>

#if SOFTRASTER_HAS_FAST_PATH

#include <softraster/detail/fragment/stencil.hpp>

#include <cstddef>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster::detail::fast {

// Lane l's byte at at[offset(l)], for the lanes of `lanes`; 0 elsewhere.
template <class Offset>
[[SOFTRASTER_FAST_TARGET]] inline Words loadStencil(const std::uint8_t* at, unsigned lanes, Offset&& offset) {
  alignas(32) std::uint32_t v[8] = {};
  for (int l = 0; l < 8; ++l) {
    if (lanes & (1u << l)) v[l] = at[offset(l)];
  }
  return reinterpret_cast<Words>(_mm256_load_si256(reinterpret_cast<const __m256i*>(v)));
}

template <class Offset>
[[SOFTRASTER_FAST_TARGET]] inline void storeStencil(std::uint8_t* at, unsigned lanes, Words values, Offset&& offset) {
  alignas(32) std::uint32_t v[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(v), reinterpret_cast<__m256i>(values));
  for (int l = 0; l < 8; ++l) {
    if (lanes & (1u << l)) at[offset(l)] = static_cast<std::uint8_t>(v[l]);
  }
}

// stencilOpResult per lane (lanes hold 0..255).
[[SOFTRASTER_FAST_TARGET]] inline Words stencilOpLanes(StencilOp op, Words s, std::uint8_t reference) {
  const Words one = broadcastWord(1), byte = broadcastWord(0xff);
  switch (op) {
    case StencilOp::Keep: return s;
    case StencilOp::Zero: return Words{};
    case StencilOp::Replace: return broadcastWord(reference);
    case StencilOp::IncrementAndClamp: return s - reinterpret_cast<Words>(s != byte);  // + 1 below 255 (true is -1)
    case StencilOp::DecrementAndClamp: return s + reinterpret_cast<Words>(s != Words{});  // - 1 above 0
    case StencilOp::Invert: return ~s & byte;
    case StencilOp::IncrementAndWrap: return (s + one) & byte;
    case StencilOp::DecrementAndWrap: return (s - one) & byte;
  }
  return s;
}

// The stencil test of `s` (lanes hold 0..255) with the face's masked reference: -1 where it passes.
[[SOFTRASTER_FAST_TARGET]] inline Mask stencilTestLanes(const StencilFace& face, Words s) {
  const Words mask = broadcastWord(face.compareMask);
  return compareLanes(face.compareOp, broadcastWord(face.reference) & mask, s & mask);
}

// The new stencil of every lane: failOp where the stencil test failed, depthFailOp where it
// passed and depth failed, passOp where both passed, through the write mask.
[[SOFTRASTER_FAST_TARGET]] inline Words stencilUpdateLanes(const StencilFace& face, Words s, Mask stencilPasses,
                                                         Mask depthPasses) {
  const Words sp = reinterpret_cast<Words>(stencilPasses), dp = reinterpret_cast<Words>(depthPasses);
  const Words fail = stencilOpLanes(face.failOp, s, face.reference);
  const Words depthFail = stencilOpLanes(face.depthFailOp, s, face.reference);
  const Words pass = stencilOpLanes(face.passOp, s, face.reference);
  const Words result = (fail & ~sp) | (depthFail & sp & ~dp) | (pass & sp & dp);
  const Words write = broadcastWord(face.writeMask);
  return (result & write) | (s & ~write);
}

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif  // SOFTRASTER_HAS_FAST_PATH
