// The multisample state's part of a fragment's coverage (VkPipelineMultisampleStateCreateInfo),
// as lavapipe applies it (llvmpipe lp_state_fs.c, lp_bld_blend.c, lp_state_derived.c):
//   - the sample mask is ANDed into the rasterized coverage before the depth and stencil tests
//     (4x MSAA: bits 0..3); with one sample lavapipe only discards the whole draw when the mask
//     is 0 (rasterizer discard), where the spec keeps the fragment iff bit 0 is set
//     (Deviations::Spec follows the spec);
//   - alpha to coverage takes the shader's alpha as it returns it (not clamped) and keeps, with
//     4x MSAA, sample s where alpha > s * 0.25 (0, 0.25, 0.5, 0.75: no dither), with one sample
//     the fragment where alpha > 0.5 (an unordered compare, lp_build_cmp: a NaN alpha keeps all); the
//     samples it drops are neither tested nor written (lavapipe tests depth early and defers the
//     write to the final mask, or tests late when the stencil is written: the same samples);
//   - alpha to one then replaces the alpha of the colour with 1.0 before blending;
//   - 4x MSAA Bresenham lines of a line topology are drawn with multisampling off (lvp_execute.c):
//     no sample mask applies (only a mask of 0 discards the draw). Vulkan forbids alpha to
//     coverage, alpha to one and sample shading with Bresenham lines (VUID-VkGraphicsPipeline
//     CreateInfo-lineRasterizationMode-02766): Context refuses them, as crosscheck's loader does;
//   - sample shading: lavapipe's min_samples = ceil(samples * minSampleShading); above 1 the
//     fragment shader runs once for every covered sample (not only min_samples of them). Each
//     invocation's gl_FragCoord.xy is the sample's position (px + its offset) and .z the depth
//     there, while .w and the varyings stay at the pixel centre (lp_bld_interp.c: only inputs
//     declared `sample` move, and none of ours is); its discard and gl_FragDepth apply to its
//     sample alone. A shader without the built-ins therefore gives the same bits either way.
// Deliberately absent: coverage itself (exact/rasterizer.hpp), the built-ins (gl_SampleID,
// gl_SamplePosition, gl_SampleMask: fragment/shade.hpp), and alpha to coverage together with
// per-sample built-ins (lavapipe's invocations then narrow one another's masks in sample order;
// refused, pipeline.hpp).
#pragma once

#include <softraster/options.hpp>
#include <softraster/state.hpp>

#include <cmath>
#include <cstdint>

namespace softraster::detail {

struct SampleCoverage {
  unsigned sampleMask = 0xfu;  // bit s: sample s kept (one sample: bit 0)
  bool alphaToCoverage = false;
  bool alphaToOne = false;
  bool perSample = false;  // sample shading: the shader runs once per covered sample (4x MSAA)

  // Anything beyond plain coverage: a stage takes its general path only then.
  bool shadesFirst() const { return alphaToCoverage; }
};

inline SampleCoverage sampleCoverage(const MultisampleState& m, std::uint32_t samples, Deviations deviations) {
  SampleCoverage c;
  if (samples == 4) {
    c.sampleMask = m.sampleMask & 0xfu;
  } else {
    c.sampleMask = deviations == Deviations::Spec ? (m.sampleMask & 1u) : (m.sampleMask != 0 ? 1u : 0u);
  }
  c.alphaToCoverage = m.alphaToCoverageEnable;
  c.alphaToOne = m.alphaToOneEnable;
  c.perSample = samples == 4 && m.sampleShadingEnable && std::ceil(4.0f * m.minSampleShading) > 1.0f;
  return c;
}

// The samples (bit s) alpha to coverage keeps of a fragment with this alpha. lavapipe's
// `alpha > t` is an unordered compare (LLVMRealUGT), true for a NaN alpha: `!(alpha <= t)` here.
template <std::uint32_t Samples>
constexpr unsigned alphaToCoverageSamples(float alpha) {
  if constexpr (Samples == 1) {
    return !(alpha <= 0.5f) ? 1u : 0u;
  } else {
    static_assert(Samples == 4);
    return (!(alpha <= 0.0f) ? 1u : 0u) | (!(alpha <= 0.25f) ? 2u : 0u) | (!(alpha <= 0.5f) ? 4u : 0u) |
           (!(alpha <= 0.75f) ? 8u : 0u);
  }
}

}  // namespace softraster::detail
