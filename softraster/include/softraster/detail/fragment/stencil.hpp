// Per-sample stencil operations, as lavapipe's fragment JIT code does them
// (llvmpipe/lp_bld_depth.c, lp_build_depth_stencil_test):
//   - the face's state is chosen by the primitive's facing (front for lines and points);
//   - the test compares (reference & compareMask) with (stored & compareMask), the reference on
//     the left of the compare op;
//   - exactly one op updates a sample: failOp where the stencil test fails, depthFailOp where it
//     passes and the depth test fails, passOp where both pass (a disabled depth test passes);
//   - the update is written through the face's write mask: (new & mask) | (old & ~mask);
//   - clamped ops saturate at 0 and 255, wrapping ops and INVERT keep the low 8 bits; REPLACE
//     writes the reference (not masked by compareMask).
// A fragment is shaded and writes colour and depth only where both tests pass.
// Deliberately absent: the depth test itself (depth.hpp), the loops over pixels and samples
// (shade.hpp), the depth bounds test (lavapipe has none: state.hpp).
#pragma once

#include <softraster/detail/fragment/depth.hpp>
#include <softraster/state.hpp>

#include <cstdint>

namespace softraster::detail {

// One face's state with the masks and reference cut to the stencil aspect's 8 bits.
struct StencilFace {
  StencilOp failOp, passOp, depthFailOp;
  CompareOp compareOp;
  std::uint8_t compareMask, writeMask, reference;
};

inline StencilFace stencilFace(const StencilOpState& s) {
  return {s.failOp,
          s.passOp,
          s.depthFailOp,
          s.compareOp,
          static_cast<std::uint8_t>(s.compareMask & 0xffu),
          static_cast<std::uint8_t>(s.writeMask & 0xffu),
          static_cast<std::uint8_t>(s.reference & 0xffu)};
}

// The draw's stencil state as the fragment stages read it: `enable` only when the state asks for
// the test and the framebuffer has a stencil aspect to test against.
struct StencilState {
  bool enable = false;
  StencilFace front{}, back{};
  const StencilFace& face(bool frontFacing) const { return frontFacing ? front : back; }
};

inline StencilState stencilState(const DepthState& depth, bool framebufferHasStencil) {
  if (!depth.stencilTestEnable || !framebufferHasStencil) return {};
  return {true, stencilFace(depth.front), stencilFace(depth.back)};
}

inline bool stencilTestPasses(const StencilFace& face, std::uint8_t stored) {
  return compare<unsigned>(face.compareOp, face.reference & face.compareMask, stored & face.compareMask);
}

// The value an op makes of `stored` (before the write mask).
inline std::uint8_t stencilOpResult(StencilOp op, std::uint8_t stored, std::uint8_t reference) {
  switch (op) {
    case StencilOp::Keep: return stored;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return reference;
    case StencilOp::IncrementAndClamp: return stored == 255 ? stored : static_cast<std::uint8_t>(stored + 1);
    case StencilOp::DecrementAndClamp: return stored == 0 ? stored : static_cast<std::uint8_t>(stored - 1);
    case StencilOp::Invert: return static_cast<std::uint8_t>(~stored);
    case StencilOp::IncrementAndWrap: return static_cast<std::uint8_t>(stored + 1);
    case StencilOp::DecrementAndWrap: return static_cast<std::uint8_t>(stored - 1);
  }
  return stored;
}

// `stored` after `op`, written through the face's write mask.
inline std::uint8_t stencilUpdate(const StencilFace& face, StencilOp op, std::uint8_t stored) {
  const std::uint8_t result = stencilOpResult(op, stored, face.reference);
  return static_cast<std::uint8_t>((result & face.writeMask) | (stored & ~face.writeMask));
}

// Which op applies to a sample, from the two tests' results.
inline StencilOp stencilOpFor(const StencilFace& face, bool stencilPasses, bool depthPasses) {
  return !stencilPasses ? face.failOp : !depthPasses ? face.depthFailOp : face.passOp;
}

}  // namespace softraster::detail
