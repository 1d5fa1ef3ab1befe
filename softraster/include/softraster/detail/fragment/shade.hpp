// The fragment stage of the exact method: for every pixel (or, with 4x MSAA, every sample) a
// primitive covers, depth, the depth test, the shader's fragment function, blending and the
// colour and depth writes, in lavapipe's order:
//   - single sample: depth at the pixel centre; a fragment failing the depth or the stencil test
//     is not shaded; the stencil test and update (fragment/stencil.hpp) with the primitive's
//     facing (TriangleInterpolants::frontFacing);
//   - 4x MSAA (triangles, lines and points): coverage and depth per sample, the fragment shaded once at the
//     pixel centre and written to the samples that are covered and pass the depth and stencil
//     tests (stencil tested and updated per sample); the
//     region's left column and top row as lavapipe's scissor planes cut them (MsaaRegionEdges),
//     or as the spec's per-fragment scissor test does (Deviations::Spec); a line passes which of
//     those planes it carries (exact/line_point_setup.hpp, msaaLineWalk);
//   - 4x MSAA Bresenham lines (line topologies; shadeBroadcast): lavapipe turns multisampling off
//     for them, so coverage, depth and the shader are the single-sample ones, depth and stencil
//     are tested and written at sample 0 only, and the colour goes to all four samples, the draw
//     region cut exactly (single-sample scissor planes); the sample mask does not apply (alpha to
//     coverage, alpha to one and sample shading are invalid there, Context refuses them); with
//     Deviations::Spec every sample the mask keeps is covered and tested with the centre's depth;
//   - depth is tested and written only with the depth test on (Vulkan); the course's 1/z buffer
//     (DepthMode::InverseZ) compares the other way round, larger being nearer.
//   - a shader with the fragment built-ins (shader.hpp) runs before the depth and stencil tests,
//     and a fragment it discards writes nothing (lavapipe: late tests, or early ones with the
//     write deferred to the kill mask; the same pixels either way); one that writes
//     gl_FragDepth has every sample tested and written with that value (clamped, no bias); the
//     samples its gl_SampleMask drops are neither tested nor written (one sample, or lines with
//     multisampling off: bit 0 for the whole fragment);
//   - the sample mask narrows the coverage first; with alpha to coverage the fragment is shaded
//     before the tests, which see only the samples its alpha keeps; alpha to one sets the
//     alpha to 1 before blending (fragment/coverage.hpp);
//   - sample shading (4x MSAA) with a shader that reads the built-ins: shaded once per covered
//     sample, gl_FragCoord.xy and .z at the sample, each sample tested and written on its own
//     (shadeSampleBySample; with alpha to coverage once per sample, covered or not, each
//     invocation's alpha narrowing the other samples, as lavapipe does); without the built-ins
//     every sample would get the same colour, so such a shader is shaded once per pixel as
//     before; a shader reading gl_SampleID or gl_SamplePosition (ShadesPerSample) is shaded
//     sample by sample without the state too.
//   - a shader with several colour outputs (ColourOutputs, shader.hpp) writes output i to colour
//     attachment i, each blended with its own state and format (attachments 1.. are the
//     FragmentTarget's moreColour); alpha to coverage reads output 0's alpha, alpha to one sets
//     every output's.
// Deliberately absent: coverage itself (exact/rasterizer.hpp walks it).
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/rasterizer.hpp>
#include <softraster/detail/fragment/builtins.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/coverage.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/detail/fragment/stencil.hpp>
#include <softraster/detail/instruction_set.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/options.hpp>
#include <softraster/shader.hpp>
#include <softraster/simd.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace softraster::detail {

// What a fragment stage tests against and writes to, for one draw (or one band of it): derived
// once from the state and the framebuffer, shared by the scalar and the fast stage.
struct FragmentTarget {
  DepthState depth;
  StencilState stencil;  // enable: the state asks for the test and the framebuffer has stencil
  ColourBlend blend;  // the draw's BlendState, prepared for the UNORM8 target (fragment/colour.hpp)
  PixelRect region;   // what this stage may touch: the draw's raster region, or one band of it
  MsaaRegionEdges msaa;  // 4x MSAA: the whole draw's region edges (the same for every band)
  SampleCoverage coverage;  // sample mask, alpha to coverage, alpha to one
  Deviations deviations;
  DepthRange depthRange;
  bool inverseZ;
  std::uint32_t width;
  std::uint32_t colourBytes;  // per sample: colourBytes(the framebuffer's format)
  std::uint8_t* colour;
  std::uint32_t* depthStorage;
  std::uint8_t* stencilStorage;  // null without a stencil aspect
  // Colour attachments 1.. (the scalar stage writes them; the fast stage takes one attachment).
  struct Attachment {
    ColourBlend blend;
    std::uint32_t colourBytes = 0;
    std::uint8_t* colour = nullptr;
  };
  std::uint32_t colourAttachments = 1;  // the framebuffer's
  std::array<Attachment, kMaxColourAttachments - 1> moreColour{};
};

inline FragmentTarget fragmentTarget(const PipelineState& state, Framebuffer& framebuffer, const Viewport& viewport,
                                     const PixelRect& region, bool inverseZ,
                                     Deviations deviations = Deviations::Driver) {
  FragmentTarget target{state.depth,
          stencilState(state.depth, hasStencil(framebuffer.depthFormat())),
          colourBlend(state.blend, framebuffer.colourFormat()),
          region,
          framebuffer.samples() == 4
              ? msaaRegionEdges(drawRegion(state.scissor, viewport, framebuffer.width(), framebuffer.height()),
                                state.scissor, deviations)
              : MsaaRegionEdges{},
          sampleCoverage(state.multisample, framebuffer.samples(), deviations),
          deviations,
          fragmentDepthRange(viewport, state.rasterization.depthClampEnable),
          inverseZ,
          framebuffer.width(),
          colourBytes(framebuffer.colourFormat()),
          framebuffer.colour().data(),
          FramebufferAccess::depthWords(framebuffer),  // the draw keeps or forgets the tiles' bounds
          hasStencil(framebuffer.depthFormat()) ? framebuffer.stencilStorage().data() : nullptr};
  target.colourAttachments = framebuffer.colourAttachments();
  for (std::uint32_t a = 1; a < target.colourAttachments; ++a) {
    const ColourFormat format = framebuffer.colourFormat(a);
    target.moreColour[a - 1] = {colourBlend(attachmentBlend(state, a), format), colourBytes(format),
                                framebuffer.colour(a).data()};
  }
  return target;
}

// A fragment's colours, one per colour output of the shader (a shader returning one Vec4 has one).
template <class Shader>
using FragmentColours = std::array<Vec4, static_cast<std::size_t>(colourOutputsOf<Shader>())>;
inline std::array<Vec4, 1> fragmentColours(const Vec4& colour) { return {colour}; }
template <std::size_t K>
const std::array<Vec4, K>& fragmentColours(const std::array<Vec4, K>& colours) {
  return colours;
}

// Alpha to one: every output's alpha (lavapipe's generate_fs_loop sets each colour output's).
template <std::size_t K>
void setAlphaToOne(std::array<Vec4, K>& colours) {
  for (Vec4& c : colours) c.w = 1.0f;
}

// Output i blended into colour attachment i at `sample` (an index into the depth storage), for
// every attachment the shader has an output for (Context refuses a draw that leaves an attachment
// with colour writes unwritten).
template <std::size_t K>
void writeColours(const FragmentTarget& target, std::size_t sample, const std::array<Vec4, K>& colours) {
  blendColour(target.colour + target.colourBytes * sample, colours[0], target.blend);
  if constexpr (K > 1) {
    const std::uint32_t attachments = std::min<std::uint32_t>(target.colourAttachments, K);
    for (std::uint32_t a = 1; a < attachments; ++a) {
      const FragmentTarget::Attachment& more = target.moreColour[a - 1];
      blendColour(more.colour + more.colourBytes * sample, colours[a], more.blend);
    }
  }
}

template <class Shader, bool Fused, DepthFormat Format>
class FragmentStage {
 public:
  static constexpr int N = Shader::kVaryings;
  using Colours = FragmentColours<Shader>;
  static constexpr InstructionSet kInstructionSet = Fused ? InstructionSet::Fma : InstructionSet::Baseline;

  FragmentStage(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                const Viewport& viewport, const PixelRect& region, bool inverseZ, const ContextOptions& options = {})
      : uniforms_(uniforms), target_(fragmentTarget(state, framebuffer, viewport, region, inverseZ, options.deviations)) {}

  const FragmentTarget& target() const { return target_; }

  // Every pixel centre inside all E edges (3: a triangle; 4: a line or point quad). Compiled once
  // per stage for its instruction set, not copied into each caller (detail/instruction_set.hpp).
  template <int E>
  void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    callCompiledFor<kInstructionSet, &FragmentStage::template shadePixelsHere<E>>(*this, edges, bounds, t);
  }

  // 4x MSAA: every pixel with a sample inside all E edges (3: a triangle; 4: a line's or a point's
  // quad). regionPlanes: which of the draw region's left and top planes the primitive carries
  // (MsaaRegionEdges::allowedSamples).
  template <int E>
  void shadeSamples(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t,
                    unsigned regionPlanes = MsaaRegionEdges::kBothPlanes) const {
    callCompiledFor<kInstructionSet, &FragmentStage::template shadeSamplesHere<E>>(*this, edges, bounds, t, regionPlanes);
  }

  // 4x MSAA Bresenham lines: every pixel centre inside the quad's 4 edges, as one sample covers
  // it, written to the four samples (the top of this file).
  void shadeBroadcast(const EdgeFunction (&edges)[4], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    callCompiledFor<kInstructionSet, &FragmentStage::shadeBroadcastHere>(*this, edges, bounds, t);
  }

 private:
  template <int E>
  void shadePixelsHere(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    rasterizeEdges(edges, bounds, target_.region, [&](int px, int py) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
      Colours colour{};
      [[maybe_unused]] float fragDepth = 0.0f;
      const bool shadedFirst = kBuiltins || target_.coverage.shadesFirst();
      if (shadedFirst) {  // a discarded fragment, or one its alpha or gl_SampleMask drops, tests and writes nothing
        unsigned maskOut = ~0u;
        if (!shadeFirst(t, px, py, 0.0f, varyings.data(), colour, fragDepth, 1u, maskOut) || !(maskOut & 1u)) return;
        if (target_.coverage.alphaToCoverage && !alphaToCoverageSamples<1>(colour[0].w)) return;
      }
      std::uint32_t stored = 0;
      bool passes = true;
      if (target_.depth.testEnable) {
        if (target_.inverseZ) {
          stored = std::bit_cast<std::uint32_t>(evaluatePlane<Fused>(t.oneOverW, fx, fy));
          passes = depthTestPasses<Format>(target_.depth.compareOp, target_.depthStorage[pixel], stored);
        } else {
          const float z = kWritesDepth ? fragDepth : interpolateDepth<Fused>(t, fx, fy);
          stored = depthToStorage<Format>(clampDepth(z, target_.depthRange));
          passes = depthTestPasses<Format>(target_.depth.compareOp, stored, target_.depthStorage[pixel]);
        }
      }
      if (target_.stencil.enable && !stencilTestAndUpdate(t.frontFacing, pixel, passes)) return;
      if (!passes) return;
      if constexpr (!kBuiltins) {  // (a shader with the built-ins is always shaded first)
        if (!shadedFirst) colour = shadeAt(t, px, py, 0.0f, varyings.data());
      }
      if (target_.coverage.alphaToOne) setAlphaToOne(colour);
      writeColours(pixel, colour);
      if (target_.depth.testEnable && target_.depth.writeEnable) target_.depthStorage[pixel] = stored;
    });
  }

  template <int E>
  void shadeSamplesHere(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t,
                        unsigned regionPlanes) const {
    if (intersect(bounds, target_.msaa.drawRegion).empty()) return;  // lavapipe culls it
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    rasterizeEdgesSampled(edges, bounds, target_.region, [&](int px, int py, unsigned covered) {
      unsigned mask = covered & target_.msaa.allowedSamples(px, py, regionPlanes) & target_.coverage.sampleMask;
      if (mask == 0) return;
      if constexpr (kBuiltins) {
        if (kPerSampleShader || target_.coverage.perSample) {
          shadeSampleBySample(t, px, py, mask, varyings.data());
          return;
        }
      }
      Colours c{};
      [[maybe_unused]] float fragDepth = 0.0f;
      const bool shadedFirst = kBuiltins || target_.coverage.shadesFirst();
      if (shadedFirst) {  // a discarded fragment leaves every sample alone; alpha to coverage and gl_SampleMask drop some
        unsigned maskOut = ~0u;
        if (!shadeFirst(t, px, py, 0.5f, varyings.data(), c, fragDepth, mask, maskOut)) return;
        mask &= maskOut;
        if (target_.coverage.alphaToCoverage) mask &= alphaToCoverageSamples<4>(c[0].w);
        if (mask == 0) return;
      }
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
      std::uint32_t stored[4];
      unsigned passed = target_.depth.testEnable ? 0u : mask;  // without the depth test every covered sample passes
      for (int s = 0; s < 4 && target_.depth.testEnable; ++s) {
        if (!(mask & (1u << s))) continue;
        const float z = clampDepth(  // gl_FragDepth: one value for every sample
            kWritesDepth ? fragDepth
                         : interpolateDepth<Fused>(t, fx + kSamplePositions4x[s][0], fy + kSamplePositions4x[s][1]),
            target_.depthRange);
        stored[s] = depthToStorage<Format>(z);
        if (depthTestPasses<Format>(target_.depth.compareOp, stored[s], target_.depthStorage[pixel * 4 + static_cast<std::size_t>(s)])) {
          passed |= 1u << s;
        }
      }
      if (target_.stencil.enable) {  // per sample; a sample failing the stencil test is not written
        for (int s = 0; s < 4; ++s) {
          const unsigned bit = 1u << s;
          if ((mask & bit) && !stencilTestAndUpdate(t.frontFacing, pixel * 4 + static_cast<std::size_t>(s), (passed & bit) != 0)) {
            passed &= ~bit;
          }
        }
      }
      if (passed == 0) return;
      if constexpr (!kBuiltins) {
        if (!shadedFirst) c = shadeAt(t, px, py, 0.5f, varyings.data());
      }
      if (target_.coverage.alphaToOne) setAlphaToOne(c);
      for (int s = 0; s < 4; ++s) {
        if (!(passed & (1u << s))) continue;
        const std::size_t sample = pixel * 4 + static_cast<std::size_t>(s);
        writeColours(sample, c);
        if (target_.depth.testEnable && target_.depth.writeEnable) target_.depthStorage[sample] = stored[s];
      }
    });
  }

  void shadeBroadcastHere(const EdgeFunction (&edges)[4], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    const bool spec = target_.deviations == Deviations::Spec;
    // lavapipe: sample 0's depth and stencil only, and no sample mask (multisampling is off; a
    // mask of 0 is dropped before the draw, pipeline.hpp); the spec: every sample the mask keeps.
    const unsigned tested = spec ? target_.coverage.sampleMask : 0x1u;
    // Not multisampled, so no scissor plane reaches past the draw region (MsaaRegionEdges).
    const PixelRect region = intersect(target_.region, target_.msaa.drawRegion);
    rasterizeEdges(edges, bounds, region, [&](int px, int py) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
      Colours colour{};
      [[maybe_unused]] float fragDepth = 0.0f;
      unsigned kept = tested;
      const bool shadedFirst = kBuiltins || target_.coverage.shadesFirst();
      if (shadedFirst) {  // a discarded fragment tests and writes nothing
        // Multisampling off (lavapipe): gl_SampleMaskIn is 1 and bit 0 of gl_SampleMask decides.
        unsigned maskOut = ~0u;
        if (!shadeFirst(t, px, py, 0.0f, varyings.data(), colour, fragDepth, spec ? tested : 1u, maskOut)) return;
        kept &= spec ? maskOut : ((maskOut & 1u) ? 0xfu : 0u);
        if (kept == 0) return;
      }
      std::uint32_t stored = 0;
      unsigned passed = kept;
      if (target_.depth.testEnable) {
        const float z = kWritesDepth ? fragDepth : interpolateDepth<Fused>(t, fx, fy);
        stored = depthToStorage<Format>(clampDepth(z, target_.depthRange));
        passed = 0;
        for (int s = 0; s < 4; ++s) {
          if ((kept & (1u << s)) &&
              depthTestPasses<Format>(target_.depth.compareOp, stored, target_.depthStorage[pixel * 4 + static_cast<std::size_t>(s)])) {
            passed |= 1u << s;
          }
        }
      }
      if (target_.stencil.enable) {
        for (int s = 0; s < 4; ++s) {
          const unsigned bit = 1u << s;
          if ((kept & bit) && !stencilTestAndUpdate(t.frontFacing, pixel * 4 + static_cast<std::size_t>(s), (passed & bit) != 0)) {
            passed &= ~bit;
          }
        }
      }
      if (passed == 0) return;
      if constexpr (!kBuiltins) {
        if (!shadedFirst) colour = shadeAt(t, px, py, 0.0f, varyings.data());
      }
      const unsigned written = spec ? passed : 0xfu;  // lavapipe: sample 0 passing writes every colour sample
      for (int s = 0; s < 4; ++s) {
        const unsigned bit = 1u << s;
        const std::size_t sample = pixel * 4 + static_cast<std::size_t>(s);
        if (written & bit) writeColours(sample, colour);
        if ((passed & bit) && target_.depth.testEnable && target_.depth.writeEnable) target_.depthStorage[sample] = stored;
      }
    });
  }

  // Sample shading with the built-ins: the samples `mask` of pixel (px, py), each shaded on its
  // own (fragment/coverage.hpp says where each input is taken), then tested and written.
  void shadeSampleBySample(const TriangleInterpolants<N>& t, int px, int py, unsigned mask, float* varyings) const {
    const float fx = static_cast<float>(px), fy = static_cast<float>(py);
    const float cx = fx + 0.5f, cy = fy + 0.5f;
    const std::size_t pixel = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
    interpolateVaryings<Fused>(t, kInterpolation, cx, cy, varyings);  // the centre, for every sample
    const float oneOverW = evaluatePlane<Fused>(t.oneOverW, cx, cy);
    // Every invocation first, then the tests: with alpha to coverage lavapipe's sample loop
    // (generate_fs_loop) runs an invocation for every sample, covered or not, and each one's
    // alpha narrows the coverage of every *other* sample (its own is stored back from its
    // execution mask, which the alpha test never touches): sample s keeps alpha_k > s/4 for each
    // k != s. Without alpha to coverage the uncovered samples' invocations change nothing. The
    // spec (Deviations::Spec) narrows each invocation's own sample by its own alpha.
    const bool alphaToCoverage = target_.coverage.alphaToCoverage;
    const bool spec = target_.deviations == Deviations::Spec;
    std::array<Colours, 4> colours{};
    std::array<float, 4> depths{};
    unsigned kept = 0;  // samples whose invocation was neither discarded nor dropped by gl_SampleMask
    unsigned alphaKept = 0xfu;
    for (int s = 0; s < 4; ++s) {
      const unsigned bit = 1u << s;
      if (!(mask & bit) && !(alphaToCoverage && !spec)) continue;
      const float sx = fx + kSamplePositions4x[s][0], sy = fy + kSamplePositions4x[s][1];
      const float z = interpolateDepth<Fused>(t, sx, sy);
      FragmentBuiltins<float> builtins;
      builtins.fragCoord = {sx, sy, z, oneOverW};
      builtins.frontFacing = t.frontFacing;
      builtins.discard = false;
      builtins.sampleId = s;
      builtins.samplePosition = {kSamplePositions4x[s][0], kSamplePositions4x[s][1]};
      builtins.sampleMaskIn = static_cast<std::int32_t>(mask & bit);  // the invocation's own sample, if covered
      colours[static_cast<std::size_t>(s)] = fragmentColours(shadeFragment<Shader>(uniforms_, varyings, builtins));
      depths[static_cast<std::size_t>(s)] = kWritesDepth ? builtins.fragDepth : z;
      if (alphaToCoverage) {  // lavapipe: every other sample; the spec: its own
        alphaKept &= alphaToCoverageSamples<4>(colours[static_cast<std::size_t>(s)][0].w) | (spec ? ~bit : bit);
      }
      if (builtins.discard) continue;
      if (kWritesSampleMask && !(static_cast<std::uint32_t>(builtins.sampleMask) & bit)) continue;
      kept |= bit;
    }
    mask &= kept & alphaKept;
    for (int s = 0; s < 4; ++s) {
      if (!(mask & (1u << s))) continue;
      const std::size_t sample = pixel * 4 + static_cast<std::size_t>(s);
      std::uint32_t stored = 0;
      bool passes = true;
      if (target_.depth.testEnable) {
        stored = depthToStorage<Format>(clampDepth(depths[static_cast<std::size_t>(s)], target_.depthRange));
        passes = depthTestPasses<Format>(target_.depth.compareOp, stored, target_.depthStorage[sample]);
      }
      if (target_.stencil.enable && !stencilTestAndUpdate(t.frontFacing, sample, passes)) continue;
      if (!passes) continue;
      Colours& c = colours[static_cast<std::size_t>(s)];
      if (target_.coverage.alphaToOne) setAlphaToOne(c);
      writeColours(sample, c);
      if (target_.depth.testEnable && target_.depth.writeEnable) target_.depthStorage[sample] = stored;
    }
  }

  // The stencil test of one sample (index into the stencil storage) and its update with the depth
  // test's result; whether the stencil test passed.
  bool stencilTestAndUpdate(bool frontFacing, std::size_t sample, bool depthPasses) const {
    const StencilFace& face = target_.stencil.face(frontFacing);
    std::uint8_t& value = target_.stencilStorage[sample];
    const bool passes = stencilTestPasses(face, value);
    value = stencilUpdate(face, stencilOpFor(face, passes, depthPasses), value);
    return passes;
  }

  // The shader's colour for pixel (px, py), its varyings at (px + offset, py + offset) (the plane
  // origin: 0 for single-sample planes, 0.5 for the MSAA ones). A shader that samples textures
  // is shaded with the 4x2 block whose left 2x2 quad holds the pixel (lanes as in simd.hpp), the
  // quad's other pixels as helpers, and this pixel's lane taken: its derivatives are the quad's.
  Colours shadeAt(const TriangleInterpolants<N>& t, int px, int py, float offset, float* varyings) const {
    if constexpr (ShadesQuads<Shader>) {
      const int qx = px & ~1, qy = py & ~1;
      alignas(32) float lanes[N == 0 ? 1 : N][kBatchLanes] = {};
      for (int lane = 0; lane < kBatchLanes; ++lane) {
        interpolateVaryings<Fused>(t, kInterpolation, static_cast<float>(qx + lane % 4) + offset,
                                   static_cast<float>(qy + lane / 4) + offset, varyings);
        for (int i = 0; i < N; ++i) lanes[i][lane] = varyings[i];
      }
      std::array<FloatBatch, (N == 0 ? 1 : N)> batch{};
      for (int i = 0; i < N; ++i) batch[static_cast<std::size_t>(i)] = FloatBatch::load(lanes[i]);
      const Vec4T<FloatBatch> c = Shader::template fragment<FloatBatch>(uniforms_, batch.data());
      const int lane = (px - qx) + 4 * (py - qy);
      return {Vec4{c.x[lane], c.y[lane], c.z[lane], c.w[lane]}};
    } else {
      interpolateVaryings<Fused>(t, kInterpolation, static_cast<float>(px) + offset, static_cast<float>(py) + offset,
                                 varyings);  // + 0 changes no pixel coordinate (none is -0)
      return fragmentColours(shadeFragment<Shader>(uniforms_, varyings));
    }
  }

  // The fragment shaded before the tests (a shader with the fragment built-ins, or alpha to
  // coverage): its colour in `colour`, its gl_FragDepth in `fragDepth`, its gl_SampleMask in
  // `maskOut` (left alone without the built-ins), and whether the fragment survives (was not
  // discarded); `maskIn` is its gl_SampleMaskIn.
  bool shadeFirst(const TriangleInterpolants<N>& t, int px, int py, float offset, float* varyings, Colours& colour,
                  float& fragDepth, unsigned maskIn, unsigned& maskOut) const {
    if constexpr (kBuiltins) {
      return shadeWithBuiltins(t, px, py, offset, varyings, colour, fragDepth, maskIn, maskOut);
    } else {
      colour = shadeAt(t, px, py, offset, varyings);
      return true;
    }
  }

  // A shader with the fragment built-ins (fragment/builtins.hpp): its colour in `colour`, its
  // gl_FragDepth in `fragDepth`, its gl_SampleMask in `maskOut` (every bit without
  // kWritesSampleMask), and whether the fragment survives (was not discarded); `maskIn` is its
  // gl_SampleMaskIn.
  bool shadeWithBuiltins(const TriangleInterpolants<N>& t, int px, int py, float offset, float* varyings,
                         Colours& colour, float& fragDepth, unsigned maskIn, unsigned& maskOut) const {
    interpolateVaryings<Fused>(t, kInterpolation, static_cast<float>(px) + offset, static_cast<float>(py) + offset,
                               varyings);
    FragmentBuiltins<float> builtins = fragmentBuiltinsAt<Fused>(t, px, py, offset);
    builtins.sampleMaskIn = static_cast<std::int32_t>(maskIn);
    colour = fragmentColours(shadeFragment<Shader>(uniforms_, varyings, builtins));
    fragDepth = builtins.fragDepth;
    maskOut = kWritesSampleMask ? static_cast<std::uint32_t>(builtins.sampleMask) : ~0u;
    return !builtins.discard;
  }

  void writeColours(std::size_t sample, const Colours& colours) const { detail::writeColours(target_, sample, colours); }

  static constexpr bool kBuiltins = UsesFragmentBuiltins<Shader>;
  static constexpr bool kWritesDepth = WritesFragDepth<Shader>;
  static constexpr bool kWritesSampleMask = WritesSampleMask<Shader>;
  static constexpr bool kPerSampleShader = ShadesPerSample<Shader>;  // reads gl_SampleID: shaded per sample
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  const typename Shader::Uniforms& uniforms_;
  FragmentTarget target_;
};

}  // namespace softraster::detail
