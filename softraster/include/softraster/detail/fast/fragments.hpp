// The fast path's fragment stage: the same contract as the scalar FragmentStage
// (fragment/shade.hpp), with filled single-sample triangles walked and shaded in 4x2 blocks of
// SIMD lanes (fast/batch.hpp) and the shader's fragment function run over FloatBatch:
//   - the triangle's bounding box (clipped to the draw region) is walked block by block, each
//     block's coverage from the 64-bit edge functions at its eight pixel centres;
//   - depth per lane at the integer pixel coordinates (no incremental stepping: the plane is
//     evaluated per pixel exactly as the scalar path does), the depth test before shading;
//   - varyings with the real 1/w division, the shader on the batch, UNORM8 conversion, blending
//     (every factor and op, in 8-bit integer SIMD on the packed pixels) and the write mask,
//     masked stores of the lanes that are covered and pass the depth test.
// Pixels of one triangle are independent, and triangles are drawn one after another, so the
// result is the scalar path's, bit for bit (tests/softraster/fast_path_test.cpp checks it).
// Lines, points and 4x MSAA go to the scalar stage it holds.
// Threads are the band queue's (fast/bands.hpp), which gives each thread a stage of its own.
// Deliberately absent: a per-tile depth range, whole-block accept/reject, AVX-512.
#pragma once

#include <softraster/detail/fast/batch.hpp>

#if SOFTRASTER_HAS_FAST_PATH

#include <softraster/detail/fragment/shade.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster::detail::fast {

template <class Shader, DepthFormat Format>
class FastFragmentStage {
 public:
  static constexpr int N = Shader::kVaryings;
  static constexpr InstructionSet kInstructionSet = InstructionSet::Avx2Fma;

  FastFragmentStage(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                    const Viewport& viewport, const PixelRect& region, bool inverseZ)
      : scalar_(state, uniforms, framebuffer, viewport, region, inverseZ),
        uniforms_(uniforms),
        target_(scalar_.target()),
        colour_(reinterpret_cast<std::uint32_t*>(target_.colour)) {}

  // target_ refers into scalar_, so a copy would point at another stage's target.
  FastFragmentStage(const FastFragmentStage&) = delete;
  FastFragmentStage& operator=(const FastFragmentStage&) = delete;

  template <int E>
  void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    if constexpr (E == 3) {
      shadeTriangle(edges, bounds, t);
    } else {
      scalar_.shadePixels(edges, bounds, t);
    }
  }

  void shadeSamples(const EdgeFunction (&edges)[3], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    scalar_.shadeSamples(edges, bounds, t);
  }

 private:
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  // A triangle's interpolants with every coefficient in every lane.
  struct BlockPlanes {
    BatchPlane depth;
    Floats depthOffset;
    BatchPlane oneOverW;
    std::array<BatchPlane, (N == 0 ? 1 : N)> varyings;
  };

  [[SOFTRASTER_FAST_TARGET]] void shadeTriangle(const EdgeFunction (&edges)[3], const PixelRect& bounds,
                                                const TriangleInterpolants<N>& t) const {
    const PixelRect box = intersect(bounds, target_.region);
    if (box.empty()) return;
    const BlockEdges blocks = blockEdges(edges);
    BlockPlanes planes;
    planes.depth = batchPlane(t.depth);
    planes.depthOffset = broadcast(t.depthOffset);
    planes.oneOverW = batchPlane(t.oneOverW);
    for (int i = 0; i < N; ++i) planes.varyings[static_cast<std::size_t>(i)] = batchPlane(t.varyings[static_cast<std::size_t>(i)]);
    std::int64_t rowStart[3];
    for (int i = 0; i < 3; ++i) rowStart[i] = edges[i].c + edges[i].dcdy * box.y0 - edges[i].dcdx * box.x0;
    for (int py = box.y0; py <= box.y1; py += kBatchHeight) {
      const unsigned rows = py + 1 <= box.y1 ? 0xffu : 0x0fu;
      std::int64_t value[3] = {rowStart[0], rowStart[1], rowStart[2]};
      for (int px = box.x0; px <= box.x1; px += kBatchWidth) {
        const int columns = std::min(kBatchWidth, box.x1 - px + 1);
        const unsigned inBox = rows & (((1u << columns) - 1u) * 0x11u);
        const unsigned covered = insideBits(blocks, value) & inBox;
        if (covered != 0) shadeBlock(px, py, covered, planes);
        for (int i = 0; i < 3; ++i) value[i] -= kBatchWidth * edges[i].dcdx;
      }
      for (int i = 0; i < 3; ++i) rowStart[i] += kBatchHeight * edges[i].dcdy;
    }
  }

  // Depth test, shading and writes of the lanes `covered` of the block whose lane 0 is (px, py).
  [[SOFTRASTER_FAST_TARGET]] void shadeBlock(int px, int py, unsigned covered, const BlockPlanes& t) const {
    const Floats fx = broadcast(static_cast<float>(px)) + kLaneX;
    const Floats fy = broadcast(static_cast<float>(py)) + kLaneY;
    const std::size_t first = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
    Words stored{};
    if (target_.depth.testEnable) {
      const Words current = loadBlock(target_.depthStorage + first, target_.width, covered);
      Mask passes;
      if (target_.inverseZ) {  // the course's 1/z buffer: larger is nearer, so compare the other way round
        stored = reinterpret_cast<Words>(evaluatePlane(t.oneOverW, fx, fy));
        passes = depthTestPasses<Format>(target_.depth.compareOp, current, stored);
      } else {
        const Floats z = evaluatePlane(t.depth, fx, fy) + t.depthOffset;
        stored = depthToStorage<Format>(clampDepth(z, target_.depthRange));
        passes = depthTestPasses<Format>(target_.depth.compareOp, stored, current);
      }
      covered &= maskBits(passes);
      if (covered == 0) return;
    }
    std::array<FloatBatch, (N == 0 ? 1 : N)> varyings{};
    if constexpr (N > 0) {
      const Floats w = broadcast(1.0f) / evaluatePlane(t.oneOverW, fx, fy);
      for (int i = 0; i < N; ++i) {
        const BatchPlane& p = t.varyings[static_cast<std::size_t>(i)];
        switch (kInterpolation[static_cast<std::size_t>(i)]) {
          case Interpolation::Perspective: varyings[i] = FloatBatch(evaluatePlane(p, fx, fy) * w); break;
          case Interpolation::NoPerspective: varyings[i] = FloatBatch(evaluatePlane(p, fx, fy)); break;
          case Interpolation::Flat: varyings[i] = FloatBatch(p.a0); break;  // a0 of a flat plane: the value
        }
      }
    }
    Words colour = packColour(Shader::template fragment<FloatBatch>(uniforms_, varyings.data()));
    if (target_.blend.readsDestination) colour = blendColour(colour, loadBlock(colour_ + first, target_.width, covered), target_.blend);
    storeBlock(colour_ + first, target_.width, covered, colour);
    if (target_.depth.testEnable && target_.depth.writeEnable) storeBlock(target_.depthStorage + first, target_.width, covered, stored);
  }

  FragmentStage<Shader, true, Format> scalar_;
  const typename Shader::Uniforms& uniforms_;
  const FragmentTarget& target_;  // the scalar stage's: one value, derived once
  std::uint32_t* colour_;         // target_.colour as packed RGBA8, one word per pixel
};

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif  // SOFTRASTER_HAS_FAST_PATH
