// The fragment stage of the exact method: for every pixel (or, with 4x MSAA, every sample) a
// primitive covers, depth, the depth test, the shader's fragment function, blending and the
// colour and depth writes, in lavapipe's order:
//   - single sample: depth at the pixel centre; a fragment failing the depth test is not shaded;
//   - 4x MSAA (filled triangles): coverage and depth per sample, the fragment shaded once at the
//     pixel centre and written to the samples that are covered and pass the depth test;
//   - depth is tested and written only with the depth test on (Vulkan); the course's 1/z buffer
//     (DepthMode::InverseZ) compares the other way round, larger being nearer.
// Deliberately absent: coverage itself (exact/rasterizer.hpp walks it), stencil, sample shading.
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/rasterizer.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace softraster::detail {

// The instructions a fragment stage's code is compiled for (where the draw loop runs it on
// other threads, fast/bands.hpp compiles it the same way there).
enum class InstructionSet : std::uint8_t { Baseline, Fma, Avx2Fma };

template <class Shader, bool Fused, DepthFormat Format>
class FragmentStage {
 public:
  static constexpr int N = Shader::kVaryings;
  static constexpr InstructionSet kInstructionSet = Fused ? InstructionSet::Fma : InstructionSet::Baseline;

  FragmentStage(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                const Viewport& viewport, const PixelRect& region, bool inverseZ)
      : uniforms_(uniforms),
        depthState_(state.depth),
        blend_(state.blend),
        region_(region),
        depthRange_(fragmentDepthRange(viewport, state.rasterization.depthClampEnable)),
        inverseZ_(inverseZ),
        width_(framebuffer.width()),
        colour_(framebuffer.colour().data()),
        depth_(framebuffer.depthStorage().data()) {}

  // Every pixel centre inside all E edges (3: a triangle; 4: a line or point quad).
  template <int E>
  void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    rasterizeEdges(edges, bounds, region_, [&](int px, int py) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * width_ + static_cast<std::size_t>(px);
      std::uint32_t stored = 0;
      if (depthState_.testEnable) {
        bool passes;
        if (inverseZ_) {
          stored = std::bit_cast<std::uint32_t>(evaluatePlane<Fused>(t.oneOverW, fx, fy));
          passes = depthTestPasses<Format>(depthState_.compareOp, depth_[pixel], stored);
        } else {
          stored = depthToStorage<Format>(clampDepth(interpolateDepth<Fused>(t, fx, fy), depthRange_));
          passes = depthTestPasses<Format>(depthState_.compareOp, stored, depth_[pixel]);
        }
        if (!passes) return;
      }
      interpolateVaryings<Fused>(t, kInterpolation, fx, fy, varyings.data());
      blendColour(colour_ + 4 * pixel, shadeFragment<Shader>(uniforms_, varyings.data()), blend_);
      if (depthState_.testEnable && depthState_.writeEnable) depth_[pixel] = stored;
    });
  }

  // 4x MSAA: every pixel with a sample inside all three edges of a triangle.
  void shadeSamples(const EdgeFunction (&edges)[3], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    rasterizeEdgesSampled(edges, bounds, region_, [&](int px, int py, unsigned mask) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * width_ + static_cast<std::size_t>(px);
      std::uint32_t stored[4];
      unsigned passed = depthState_.testEnable ? 0u : mask;  // without the depth test every covered sample passes
      for (int s = 0; s < 4 && depthState_.testEnable; ++s) {
        if (!(mask & (1u << s))) continue;
        const float z = clampDepth(
            interpolateDepth<Fused>(t, fx + kSamplePositions4x[s][0], fy + kSamplePositions4x[s][1]), depthRange_);
        stored[s] = depthToStorage<Format>(z);
        if (depthTestPasses<Format>(depthState_.compareOp, stored[s], depth_[pixel * 4 + static_cast<std::size_t>(s)])) {
          passed |= 1u << s;
        }
      }
      if (passed == 0) return;
      interpolateVaryings<Fused>(t, kInterpolation, fx + 0.5f, fy + 0.5f, varyings.data());
      const Vec4 c = shadeFragment<Shader>(uniforms_, varyings.data());
      for (int s = 0; s < 4; ++s) {
        if (!(passed & (1u << s))) continue;
        const std::size_t sample = pixel * 4 + static_cast<std::size_t>(s);
        blendColour(colour_ + 4 * sample, c, blend_);
        if (depthState_.testEnable && depthState_.writeEnable) depth_[sample] = stored[s];
      }
    });
  }

 private:
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  const typename Shader::Uniforms& uniforms_;
  DepthState depthState_;
  BlendState blend_;
  PixelRect region_;
  DepthRange depthRange_;
  bool inverseZ_;
  std::uint32_t width_;
  std::uint8_t* colour_;
  std::uint32_t* depth_;
};

}  // namespace softraster::detail
