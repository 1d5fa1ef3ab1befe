// The fast path's fragment stage: the same contract as the scalar FragmentStage
// (fragment/shade.hpp), with filled single-sample triangles walked and shaded in 4x2 blocks of
// SIMD lanes (fast/batch.hpp) and the shader's fragment function run over FloatBatch:
//   - the triangle's bounding box (clipped to the draw region) is walked block by block; where no
//     edge value can wrap around 64 bits, a block's corners decide it first (skipped when wholly
//     outside an edge, every lane covered when wholly inside), else its coverage comes from the
//     64-bit edge functions at its eight pixel centres;
//   - the depth state (test, compare op, write) picks the block loop's instantiation once per
//     triangle; a block wholly inside the box reads and writes with plain loads and stores;
//   - depth per lane at the integer pixel coordinates (no incremental stepping: the plane is
//     evaluated per pixel exactly as the scalar path does), the depth test before shading;
//   - varyings with the real 1/w division, the shader on the batch, UNORM8 conversion, blending,
//     masked stores of the lanes that are covered and pass the depth test.
// Pixels of one triangle are independent, and triangles are drawn one after another, so the
// result is the scalar path's, bit for bit (tests/softraster/fast_path_test.cpp checks it).
// Lines, points and 4x MSAA go to the scalar stage it holds.
// Threads are the band queue's (fast/bands.hpp), which gives each thread a stage of its own.
// Deliberately absent: a per-tile depth range, AVX-512.
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
#include <cmath>
#include <cstdint>
#include <utility>

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

  static constexpr bool kAnyPerspective = [] {
    for (const Interpolation i : kInterpolation) {
      if (i == Interpolation::Perspective) return true;
    }
    return false;
  }();

  [[SOFTRASTER_FAST_TARGET]] void shadeTriangle(const EdgeFunction (&edges)[3], const PixelRect& bounds,
                                                const TriangleInterpolants<N>& t) const {
    const PixelRect box = intersect(bounds, target_.region);
    if (box.empty()) return;
    BlockPlanes planes;
    planes.depth = batchPlane(t.depth);
    planes.depthOffset = broadcast(t.depthOffset);
    planes.oneOverW = batchPlane(t.oneOverW);
    for (int i = 0; i < N; ++i) planes.varyings[static_cast<std::size_t>(i)] = batchPlane(t.varyings[static_cast<std::size_t>(i)]);
    // The depth state picks the block loop's instantiation once per triangle, not per block.
    if (!target_.depth.testEnable) return walk<CompareOp::Always, false, false>(edges, box, planes);
    if (target_.depth.writeEnable) return walkTested<true>(edges, box, planes);
    return walkTested<false>(edges, box, planes);
  }

  template <bool Write>
  [[SOFTRASTER_FAST_TARGET]] void walkTested(const EdgeFunction (&edges)[3], const PixelRect& box,
                                             const BlockPlanes& planes) const {
    switch (target_.depth.compareOp) {
      case CompareOp::Never: return;  // no fragment passes: nothing is written
      case CompareOp::Less: return walk<CompareOp::Less, true, Write>(edges, box, planes);
      case CompareOp::Equal: return walk<CompareOp::Equal, true, Write>(edges, box, planes);
      case CompareOp::LessOrEqual: return walk<CompareOp::LessOrEqual, true, Write>(edges, box, planes);
      case CompareOp::Greater: return walk<CompareOp::Greater, true, Write>(edges, box, planes);
      case CompareOp::NotEqual: return walk<CompareOp::NotEqual, true, Write>(edges, box, planes);
      case CompareOp::GreaterOrEqual: return walk<CompareOp::GreaterOrEqual, true, Write>(edges, box, planes);
      case CompareOp::Always: return walk<CompareOp::Always, true, Write>(edges, box, planes);
    }
  }

  // The bounding box block by block. Where no edge value over the box can wrap around 64 bits,
  // a block's corners decide it first: wholly outside one edge (skipped) or wholly inside all
  // three (every lane covered, no per-lane test); other blocks test their eight lanes.
  template <CompareOp Op, bool Test, bool Write>
  [[SOFTRASTER_FAST_TARGET, gnu::flatten, gnu::noinline]] void walk(const EdgeFunction (&edges)[3], const PixelRect& box,
                                                                   const BlockPlanes& planes) const {
    const BlockEdges lanes = blockEdges(edges);
    std::int64_t rowStart[3], stepX[3], stepY[3], lowest[3], highest[3];
    bool corners = true;
    for (int i = 0; i < 3; ++i) {
      const std::int64_t dx = edges[i].dcdx, dy = edges[i].dcdy;
      rowStart[i] = edges[i].c + dy * box.y0 - dx * box.x0;
      stepX[i] = kBatchWidth * dx;
      stepY[i] = kBatchHeight * dy;
      // The lowest and highest of a block's lane offsets (-dx * column + dy * row).
      lowest[i] = std::min<std::int64_t>(0, -(kBatchWidth - 1) * dx) + std::min<std::int64_t>(0, dy);
      highest[i] = std::max<std::int64_t>(0, -(kBatchWidth - 1) * dx) + std::max<std::int64_t>(0, dy);
      // Every lane value is c + dy * y - dx * x for x, y in the box and one block past it.
      const double reach = std::fabs(static_cast<double>(edges[i].c)) +
                           std::fabs(static_cast<double>(dy)) * (box.y1 + kBatchHeight) +
                           std::fabs(static_cast<double>(dx)) * (box.x1 + kBatchWidth);
      corners &= reach < 0x1p61;
    }
    for (int py = box.y0; py <= box.y1; py += kBatchHeight) {
      const unsigned rows = py + 1 <= box.y1 ? 0xffu : 0x0fu;
      std::int64_t value[3] = {rowStart[0], rowStart[1], rowStart[2]};
      for (int px = box.x0; px <= box.x1; px += kBatchWidth,
               value[0] -= stepX[0], value[1] -= stepX[1], value[2] -= stepX[2]) {
        const int columns = std::min(kBatchWidth, box.x1 - px + 1);
        const unsigned inBox = rows & (((1u << columns) - 1u) * 0x11u);
        unsigned covered;
        if (corners) {
          if (value[0] + highest[0] <= 0 || value[1] + highest[1] <= 0 || value[2] + highest[2] <= 0) continue;
          const bool inside = value[0] + lowest[0] > 0 && value[1] + lowest[1] > 0 && value[2] + lowest[2] > 0;
          covered = inside ? inBox : insideBits(lanes, value) & inBox;
        } else {
          covered = insideBits(lanes, value) & inBox;
        }
        if (covered != 0) shadeBlock<Op, Test, Write>(px, py, covered, inBox == 0xffu, planes);
      }
      for (int i = 0; i < 3; ++i) rowStart[i] += stepY[i];
    }
  }

  // Varying I of a block, as interpolateVaryings<true> computes it per pixel.
  template <std::size_t I>
  [[SOFTRASTER_FAST_TARGET]] static FloatBatch varyingOf(const BlockPlanes& t, Floats fx, Floats fy, Floats w) {
    const BatchPlane& p = t.varyings[I];
    if constexpr (kInterpolation[I] == Interpolation::Perspective) {
      return FloatBatch(evaluatePlane(p, fx, fy) * w);
    } else if constexpr (kInterpolation[I] == Interpolation::NoPerspective) {
      return FloatBatch(evaluatePlane(p, fx, fy));
    } else {
      return FloatBatch(p.a0);  // a0 of a flat plane: the value
    }
  }

  template <std::size_t... I>
  [[SOFTRASTER_FAST_TARGET]] static void interpolateBlock(std::index_sequence<I...>, const BlockPlanes& t, Floats fx,
                                                          Floats fy, FloatBatch* out) {
    Floats w{};
    if constexpr (kAnyPerspective) w = broadcast(1.0f) / evaluatePlane(t.oneOverW, fx, fy);
    ((out[I] = varyingOf<I>(t, fx, fy, w)), ...);
  }

  // Depth test, shading and writes of the lanes `covered` of the block whose lane 0 is (px, py);
  // `whole`: all eight lanes are inside the box (so inside the image), read and written plainly.
  template <CompareOp Op, bool Test, bool Write>
  [[SOFTRASTER_FAST_TARGET]] void shadeBlock(int px, int py, unsigned covered, bool whole, const BlockPlanes& t) const {
    const Floats fx = broadcast(static_cast<float>(px)) + kLaneX;
    const Floats fy = broadcast(static_cast<float>(py)) + kLaneY;
    const std::size_t first = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
    Words stored{}, current{};
    Mask passes = ~Mask{};
    if constexpr (Test) {
      if constexpr (Op != CompareOp::Always || Write) {
        current = whole ? loadFullBlock(target_.depthStorage + first, target_.width)
                        : loadBlock(target_.depthStorage + first, target_.width, covered);
      }
      if (target_.inverseZ) {  // the course's 1/z buffer: larger is nearer, so compare the other way round
        stored = reinterpret_cast<Words>(evaluatePlane(t.oneOverW, fx, fy));
        passes = depthTestPasses<Format, Op>(current, stored);
      } else {
        const Floats z = evaluatePlane(t.depth, fx, fy) + t.depthOffset;
        stored = depthToStorage<Format>(clampDepth(z, target_.depthRange));
        passes = depthTestPasses<Format, Op>(stored, current);
      }
      if constexpr (Op != CompareOp::Always) {
        covered &= maskBits(passes);
        if (covered == 0) return;
      }
    }
    std::array<FloatBatch, (N == 0 ? 1 : N)> varyings{};
    if constexpr (N > 0) interpolateBlock(std::make_index_sequence<N>{}, t, fx, fy, varyings.data());
    Words colour = packColour(Shader::template fragment<FloatBatch>(uniforms_, varyings.data()));
    if (target_.blend.enable) colour = blendColour(colour, loadBlock(colour_ + first, target_.width, covered), target_.blend);
    if (covered == 0xffu) {
      storeFullBlock(colour_ + first, target_.width, colour);
    } else {
      storeBlock(colour_ + first, target_.width, covered, colour);
    }
    if constexpr (Write) {
      if (whole) {  // lanes that fail keep the value just read: one plain store
        const Words written = reinterpret_cast<Words>(laneMask(covered));
        storeFullBlock(target_.depthStorage + first, target_.width, (stored & written) | (current & ~written));
      } else {
        storeBlock(target_.depthStorage + first, target_.width, covered, stored);
      }
    }
  }

  FragmentStage<Shader, true, Format> scalar_;
  const typename Shader::Uniforms& uniforms_;
  const FragmentTarget& target_;  // the scalar stage's: one value, derived once
  std::uint32_t* colour_;         // target_.colour as packed RGBA8, one word per pixel
};

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif  // SOFTRASTER_HAS_FAST_PATH
