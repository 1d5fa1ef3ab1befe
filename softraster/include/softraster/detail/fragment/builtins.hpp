// The fragment built-ins' inputs for one pixel, as lavapipe's fragment JIT code forms them
// (llvmpipe lp_bld_interp.c, attribute 0 = the position):
//   gl_FragCoord.xy = px + 0.5, py + 0.5 (dadx = 1, a0 = the half-pixel centre offset);
//   gl_FragCoord.z  = the depth plane at the shading position, plus the polygon offset, NOT
//                     clamped (lp_state_fs.c clamps only the depth test's copy);
//   gl_FragCoord.w  = the 1/w plane at the shading position (no reciprocal);
// the shading position being the pixel's plane coordinate: (px, py) for single-sample planes,
// (px + 0.5, py + 0.5) for the 4x MSAA ones (shaded once at the centre, min_samples == 1).
// gl_FrontFacing: the primitive's facing as the draw loop set it (the stencil's face).
// Deliberately absent: the depth test and the writes (fragment/shade.hpp decides what a
// discarded fragment leaves alone), per-sample built-ins and gl_SampleMaskIn (the caller's, who
// knows the coverage).
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/fragment_builtins.hpp>

namespace softraster::detail {

template <bool Fused, int N>
inline FragmentBuiltins<float> fragmentBuiltinsAt(const TriangleInterpolants<N>& t, int px, int py, float offset) {
  const float x = static_cast<float>(px) + offset, y = static_cast<float>(py) + offset;
  FragmentBuiltins<float> b;
  b.fragCoord = {static_cast<float>(px) + 0.5f, static_cast<float>(py) + 0.5f, interpolateDepth<Fused>(t, x, y),
                 evaluatePlane<Fused>(t.oneOverW, x, y)};
  b.frontFacing = t.frontFacing;
  b.discard = false;
  return b;
}

}  // namespace softraster::detail
