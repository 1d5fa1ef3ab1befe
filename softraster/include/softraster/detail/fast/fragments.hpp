// The fast path's fragment stage: the same contract as the scalar FragmentStage
// (fragment/shade.hpp), with single-sample triangles, lines and points (their quads: four edges)
// walked and shaded in 4x2 blocks of SIMD lanes (fast/batch.hpp) and the shader's fragment
// function run over FloatBatch:
//   - a bounding box (clipped to the draw region) of one block, or (but for kBlockPairs shaders)
//     of up to three blocks across and three down (kSmallBlocks), has each block tested and
//     shaded directly, without the walk's set-up, and the planes are made only when a lane is
//     covered (most triangles of a dense mesh);
//   - a larger one is walked block by block; where
//     no edge value can wrap around 64 bits, each row of blocks is first cut exactly (integer
//     division) into the blocks wholly outside an edge (skipped) and those wholly inside every
//     edge (every lane covered, no per-lane test); other blocks take their coverage from the
//     64-bit edge functions at their eight pixel centres; in a cut row, the run of blocks inside
//     every edge and the box's columns goes to the block with no per-block test;
//   - what a block reads of the target (pointers, width, the depth state, flags) is made once per
//     stage and copied into a local per primitive (a block's stores could alias it where it
//     lies) and branched on per block, branches the predictor learns (one block loop per
//     stage, not one per state, keeps a shader's compile time down); the common state (depth
//     tested and written, no stencil, blending or discards: BlockTarget::plain) tests one flag
//     before and after the shader instead of each feature's (the shader is still inlined once);
//     a block wholly inside the box reads and writes with plain loads and stores;
//   - depth per lane at the integer pixel coordinates (no incremental stepping: the plane is
//     evaluated per pixel exactly as the scalar path does), the depth test before shading;
//   - varyings with the real 1/w division, the shader on the batch, UNORM8 conversion, blending
//     (every factor and op, in 8-bit integer SIMD on the packed pixels) and the write mask,
//     masked stores of the lanes that are covered and pass the depth test;
//   - a shader that takes FloatBatchPair (kBlockPairs, shader.hpp), in the common state, is shaded
//     two blocks at a time: a walked block that passes the depth test waits for the next one, and
//     the two are shaded in one call and written (the walk's last block alone); where the CPU
//     has AVX-512 (F, VL, BW, DQ) four blocks wait and are shaded as two FloatBatch16 chains
//     (shadeTwoPairsWide: each of the shader's operations one 16-lane instruction for a pair,
//     the two pairs' chains interleaved), the walk's last two as one FloatBatch16
//     (shadePairWide) and a last odd one alone; the same bits per lane;
//   - with AVX-512, other shaders (kWideRuns: not kQuads, no built-ins, not kBlockPairs) in the
//     common state draw a triangle's runs of whole blocks inside every edge (along a row) two
//     blocks at a time, as one 8x2 rectangle of 16 lanes (shadeRunWide: the depth test,
//     varyings, shader, packing and writes of a whole block, each operation one 16-lane
//     instruction; an odd last block goes the usual way). The same bits per lane.
// Pixels of one triangle are independent, and triangles are drawn one after another, so the
// result is the scalar path's, bit for bit (tests/crosscheck/fast_path_test.cpp checks it).
// 4x MSAA triangles take the same blocks with coverage, depth and the writes per sample (each
// pair of adjacent pixels' eight samples one vector, as they lie in memory) and the shader once
// per pixel at its centre, as the scalar shadeSamples does. The stencil test and update run on
// the lanes (fast/stencil.hpp) after the depth test, per pixel or per sample, with the
// primitive's face; a fragment failing either test is not shaded. A shader with the fragment
// built-ins (shader.hpp) is shaded first, before the tests, and its discarded lanes (all samples
// of such a pixel) are dropped from coverage, as the scalar stage does; so is any shader with
// alpha to coverage on, whose alpha drops lanes or samples (fragment/coverage.hpp). The sample
// mask narrows MSAA coverage first; alpha to one sets the alpha to 1 before packing. Lines and
// points with 4x MSAA go to the scalar stage it holds, and so do the triangles of a shader with
// the built-ins under sample shading (shaded sample by sample).
// A primitive's box of at least a tile's pixels first meets the tiles' depth bounds
// (fast/depth_tiles.hpp): the tiles where no fragment could pass are not walked.
// Threads are the band queue's (fast/bands.hpp), which gives each thread a stage of its own.
// Deliberately absent: AVX-512 beyond the block pairs' shading and the runs of whole blocks
// (edge tests, partial blocks, stencil, blending, MSAA and the 2x2 quads are AVX2).
#pragma once

#include <softraster/detail/fast/batch.hpp>
#include <softraster/detail/fast/depth_tiles.hpp>
#include <softraster/detail/fast/stencil.hpp>
#include <softraster/detail/fast/wide_batch.hpp>
#include <softraster/detail/instruction_set.hpp>

#if SOFTRASTER_HAS_FAST_PATH

#include <softraster/detail/fragment/shade.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/options.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <utility>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster::detail::fast {

// A block pair's fragment function over FloatBatch16, compiled for AVX-512 (cpuShadesWidePairs):
// block a's lanes are 0-7 and block b's 8-15, each operation one instruction for both blocks.
// Its inputs and output are the pair's halves in memory (a call between AVX2 and AVX-512 code
// passes no vector in a register).
template <class Shader, std::size_t... I>
[[SOFTRASTER_WIDE_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] void shadePairWide(const typename Shader::Uniforms& uniforms,
                                                                              const FloatBatchPair* varyings, FloatBatchPair* colour,
                                                                              std::index_sequence<I...>) {
  const std::array<FloatBatch16, sizeof...(I)> wide{joinHalves(varyings[I])...};
  const Vec4T<FloatBatch16> c = Shader::template fragment<FloatBatch16>(uniforms, wide.data());
  colour[0] = splitHalves(c.x);
  colour[1] = splitHalves(c.y);
  colour[2] = splitHalves(c.z);
  colour[3] = splitHalves(c.w);
}

// Two pairs (four blocks) as the halves of one FloatBatch16Pair, compiled for AVX-512: two
// 16-lane chains of the shader's arithmetic interleaved, which 32 zmm registers hold (one chain
// alone leaves the divisions' and roots' latency exposed). As shadePairWide for each pair.
template <class Shader, std::size_t... I>
[[SOFTRASTER_WIDE_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] void shadeTwoPairsWide(const typename Shader::Uniforms& uniforms,
                                                                                  const FloatBatchPair* first, const FloatBatchPair* second,
                                                                                  FloatBatchPair* colourFirst, FloatBatchPair* colourSecond,
                                                                                  std::index_sequence<I...>) {
  const std::array<FloatBatch16Pair, sizeof...(I)> wide{FloatBatch16Pair(joinHalves(first[I]), joinHalves(second[I]))...};
  const Vec4T<FloatBatch16Pair> c = Shader::template fragment<FloatBatch16Pair>(uniforms, wide.data());
  colourFirst[0] = splitHalves(c.x.low);
  colourFirst[1] = splitHalves(c.y.low);
  colourFirst[2] = splitHalves(c.z.low);
  colourFirst[3] = splitHalves(c.w.low);
  colourSecond[0] = splitHalves(c.x.high);
  colourSecond[1] = splitHalves(c.y.high);
  colourSecond[2] = splitHalves(c.z.high);
  colourSecond[3] = splitHalves(c.w.high);
}

template <class Shader, DepthFormat Format>
class FastFragmentStage {
 public:
  static constexpr int N = Shader::kVaryings;
  static constexpr bool kQuads = ShadesQuads<Shader>;  // shaded in aligned 2x2 quads (a shader that samples textures)
  static constexpr InstructionSet kInstructionSet = InstructionSet::Avx2Fma;
  static constexpr bool kKeepsDepthTiles = true;  // a single-sample draw keeps the tiles' depth bounds (fast/depth_tiles.hpp)

  FastFragmentStage(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                    const Viewport& viewport, const PixelRect& region, bool inverseZ, const ContextOptions& options = {})
      : scalar_(state, uniforms, framebuffer, viewport, region, inverseZ, options),
        uniforms_(uniforms),
        target_(scalar_.target()),
        colour_(reinterpret_cast<std::uint32_t*>(target_.colour)),
        depthTiles_(framebuffer, target_, inverseZ, kBuiltins || target_.coverage.shadesFirst(), kWritesDepth),
        widePairs_(kBlockPairs && options.allowAvx512 && cpuShadesWidePairs()),
        wideRuns_(kWideRuns && options.allowAvx512 && cpuShadesWidePairs()),
        blockTarget_(makeBlockTarget()) {}

  // target_ refers into scalar_, so a copy would point at another stage's target.
  FastFragmentStage(const FastFragmentStage&) = delete;
  FastFragmentStage& operator=(const FastFragmentStage&) = delete;

  // A triangle (E = 3) or a line's or a point's quad (E = 4): the same walk and shading.
  template <int E>
  void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    shadePrimitive(edges, bounds, t);
  }

  // 4x MSAA Bresenham lines: the scalar stage.
  void shadeBroadcast(const EdgeFunction (&edges)[4], const PixelRect& bounds, const TriangleInterpolants<N>& t) const {
    scalar_.shadeBroadcast(edges, bounds, t);
  }

  template <int E>
  void shadeSamples(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t,
                    unsigned regionPlanes = MsaaRegionEdges::kBothPlanes) const {
    if constexpr (E == 4) {  // a line's or a point's quad: the scalar stage
      scalar_.shadeSamples(edges, bounds, t, regionPlanes);
    } else {
      if constexpr (kBuiltins) {
        if (ShadesPerSample<Shader> || target_.coverage.perSample) {  // the scalar stage shades sample by sample
          scalar_.shadeSamples(edges, bounds, t);
          return;
        }
      }
      shadeSampledTriangle(edges, bounds, t);
    }
  }

 private:
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  // A triangle's interpolants with every coefficient in every lane.
  struct BlockPlanes {
    BatchPlane depth;
    Floats depthOffset;
    BatchPlane oneOverW;
    std::array<BatchPlane, (N == 0 ? 1 : N)> varyings;
    bool frontFacing;  // the stencil face
  };

  // What a block reads of target_, copied into a local of the walk: a block's vector stores may
  // alias anything reached through a reference, so a field read through target_ (and the
  // reference itself) would be loaded again after every block.
  struct BlockTarget {
    DepthState depth;
    DepthRange depthRange;
    std::size_t width;
    std::uint32_t* colour;  // packed RGBA8, one word per pixel (or per sample)
    std::uint32_t* depthStorage;
    bool inverseZ;
    bool stencil;           // the stencil test is on
    bool readsDestination;  // blending, or a partial write mask
    bool shadesFirst;       // shaded before the tests: the built-ins, or alpha to coverage
    bool alphaToOne;
    bool swapRedBlue;
    // Depth tested and written, from the planes, and nothing else that reads the framebuffer or
    // drops lanes: no stencil, blending, partial write mask, 1/z buffer or shading first.
    bool plain;
    unsigned sampleMask;            // 4x MSAA: bit s keeps sample s
    int partialColumn, partialRow;  // 4x MSAA: MsaaRegionEdges's
  };

  BlockTarget makeBlockTarget() const {
    return {.depth = target_.depth,
            .depthRange = target_.depthRange,
            .width = target_.width,
            .colour = colour_,
            .depthStorage = target_.depthStorage,
            .inverseZ = target_.inverseZ,
            .stencil = target_.stencil.enable,
            .readsDestination = target_.blend.readsDestination,
            .shadesFirst = kBuiltins || target_.coverage.shadesFirst(),
            .alphaToOne = target_.coverage.alphaToOne,
            .swapRedBlue = target_.blend.swapRedBlue,
            .plain = target_.depth.testEnable && target_.depth.writeEnable && !target_.inverseZ && !target_.stencil.enable &&
                     !target_.blend.readsDestination && !(kBuiltins || target_.coverage.shadesFirst()),
            .sampleMask = target_.coverage.sampleMask,
            .partialColumn = target_.msaa.partialColumn,
            .partialRow = target_.msaa.partialRow};
  }

  static constexpr bool kAnyPerspective = [] {
    for (const Interpolation i : kInterpolation) {
      if (i == Interpolation::Perspective) return true;
    }
    return false;
  }();

  [[SOFTRASTER_FAST_TARGET]] static BlockPlanes blockPlanes(const TriangleInterpolants<N>& t) {
    BlockPlanes planes;
    planes.depth = batchPlane(t.depth);
    planes.depthOffset = broadcast(t.depthOffset);
    planes.oneOverW = batchPlane(t.oneOverW);
    for (int i = 0; i < N; ++i) planes.varyings[static_cast<std::size_t>(i)] = batchPlane(t.varyings[static_cast<std::size_t>(i)]);
    planes.frontFacing = t.frontFacing;
    return planes;
  }

  // Whether a block's corners may decide it: no edge value c + dcdy * y - dcdx * x over the box
  // and one block past it can wrap around 64 bits (sample offsets stay inside that block).
  // A line's or a point's quad (four edges) is first checked in integers, which answers for every
  // one in the viewport bounds: |c| <= 2^59, |dcdx| and |dcdy| <= 2^43 and the box's far corner
  // (not negative: it lies in the region) below 2^16 bound every value by 3 * 2^59 < 2^61;
  // otherwise, and for triangles, in doubles. Callgrind, one frame of the 100k-triangle wireframe
  // at 1 thread (softraster_benchmarks): 562M instructions with the doubles alone, 547M with the
  // integers first; for three edges GCC vectorises the doubles, which cost about 8 fewer a walk.
  template <int E>
  static bool cornersDecide(const EdgeFunction (&edges)[E], const PixelRect& box) {
    if constexpr (E == 4) {
      const auto magnitude = [](std::int64_t v) { return static_cast<std::uint64_t>(v ^ (v >> 63)); };  // |v|, or |v| - 1 below 0
      std::uint64_t c = 0, steps = 0;
      for (int i = 0; i < E; ++i) {
        c |= magnitude(edges[i].c);
        steps |= magnitude(edges[i].dcdx) | magnitude(edges[i].dcdy);
      }
      const auto far = static_cast<std::uint32_t>(box.x1 + kBatchWidth) | static_cast<std::uint32_t>(box.y1 + kBatchHeight);
      if ((c >> 59) == 0 && (steps >> 43) == 0 && (far >> 16) == 0) return true;
    }
    bool decide = true;
    for (int i = 0; i < E; ++i) {
      const double reach = std::fabs(static_cast<double>(edges[i].c)) +
                           std::fabs(static_cast<double>(edges[i].dcdy)) * (box.y1 + kBatchHeight) +
                           std::fabs(static_cast<double>(edges[i].dcdx)) * (box.x1 + kBatchWidth);
      decide &= reach < 0x1p61;
    }
    return decide;
  }

  template <int E>
  [[SOFTRASTER_FAST_TARGET]] void shadePrimitive(const EdgeFunction (&edges)[E], const PixelRect& bounds,
                                                 const TriangleInterpolants<N>& t) const {
    const PixelRect box = intersect(bounds, target_.region);
    if (box.empty()) return;
    // Nothing passes (but with the stencil on, failing fragments still update it).
    if (target_.depth.testEnable && target_.depth.compareOp == CompareOp::Never && !target_.stencil.enable) return;
    if constexpr (!kQuads) {
      // (The depth tiles never skip a box this small: under a tile's pixels, shade() walks it whole.)
      const int width = box.x1 - box.x0 + 1, height = box.y1 - box.y0 + 1;
      const bool oneBlock = width <= kBatchWidth && height <= kBatchHeight;
      if (oneBlock || (!kBlockPairs && width <= kSmallBlocks * kBatchWidth && height <= kSmallBlocks * kBatchHeight)) {
        walkSmallBox(edges, box, t);
        return;
      }
    }
    const BlockPlanes planes = blockPlanes(t);
    depthTiles_.shade(edges, box, t.depth, t.depthOffset, [&](const PixelRect& part) { walk(edges, part, planes); });
  }

  // walkSmallBox takes boxes of up to kSmallBlocks blocks across and down (one block for a
  // kBlockPairs shader, whose blocks the walk shades in pairs).
  static constexpr int kSmallBlocks = 3;

  // A small box (shadePrimitive): each block from its top-left corner, its lanes tested as
  // walkBlocks tests a block it cannot decide at its corners (the same blocks, lanes and order),
  // without the walk's set-up; the planes are made, and the target copied, only once a lane is
  // covered.
  template <int E>
  [[SOFTRASTER_FAST_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] void walkSmallBox(const EdgeFunction (&edges)[E],
                                                                                  const PixelRect& box,
                                                                                  const TriangleInterpolants<N>& t) const {
    const BlockEdges<E> lanes = blockEdges(edges);
    struct Block {
      int px, py;
      unsigned covered, inBox;
    };
    Block blocks[kSmallBlocks * kSmallBlocks];
    int count = 0;
    // The edge values at each block's lane 0, c + dcdy * py - dcdx * px, stepped from the box's
    // corner (integers: the same values), each in every lane of a vector. Kept in vectors: as
    // integers, GCC copied them in pairs with 16-byte loads of two 8-byte stores, which the CPU
    // cannot forward (a tenth of this function's time on a million small triangles).
    __m256i rowValue[E], stepX[E], stepY[E];
    for (int i = 0; i < E; ++i) {
      rowValue[i] = _mm256_set1_epi64x(edges[i].c + edges[i].dcdy * box.y0 - edges[i].dcdx * box.x0);
      stepX[i] = _mm256_set1_epi64x(kBatchWidth * edges[i].dcdx);
      stepY[i] = _mm256_set1_epi64x(kBatchHeight * edges[i].dcdy);
    }
    for (int py = box.y0; py <= box.y1; py += kBatchHeight) {
      const unsigned rows = py + 1 <= box.y1 ? 0x11u : 0x01u;
      __m256i value[E];
      for (int i = 0; i < E; ++i) value[i] = rowValue[i];
      for (int px = box.x0; px <= box.x1; px += kBatchWidth) {
        const unsigned inBox = ((1u << std::min(kBatchWidth, box.x1 - px + 1)) - 1u) * rows;
        const unsigned covered = insideBits(lanes, value) & inBox;
        if (covered != 0) blocks[count++] = {px, py, covered, inBox};
        for (int i = 0; i < E; ++i) value[i] = _mm256_sub_epi64(value[i], stepX[i]);
      }
      for (int i = 0; i < E; ++i) rowValue[i] = _mm256_add_epi64(rowValue[i], stepY[i]);
    }
    if (count == 0) return;
    const BlockPlanes planes = blockPlanes(t);
    const BlockTarget to = blockTarget_;  // as in walk()
    for (int k = 0; k < count; ++k) {
      const Block& b = blocks[k];
      shadeBlock(b.px, b.py, b.covered, b.inBox == 0xffu, planes, to);
    }
  }

  static constexpr std::int64_t kCutBlocks = 4;  // rows of more blocks than this are cut by division

  // The k with a - k * step > 0, intersected into [first, last] (integers: exact).
  static void positiveRun(std::int64_t a, std::int64_t step, std::int64_t& first, std::int64_t& last) {
    if (step == 0) {
      if (a <= 0) last = -1;
    } else if (step > 0) {
      last = std::min(last, a > 0 ? (a - 1) / step : std::int64_t{-1});
    } else {
      first = std::max(first, a > 0 ? std::int64_t{0} : -a / -step + 1);
    }
  }

  // edge(0), ..., edge(E - 1) in the lanes of a vector, `fourth` in lane 3 when E is 3.
  template <int E, class Edge>
  [[SOFTRASTER_FAST_TARGET]] static __m256i edgeLanes(Edge&& edge, std::int64_t fourth) {
    return _mm256_set_epi64x(E == 4 ? edge(E - 1) : fourth, edge(2), edge(1), edge(0));
  }

  // Whether every lane of values + offsets is positive.
  [[SOFTRASTER_FAST_TARGET]] static bool allPositive(__m256i values, __m256i offsets) {
    const __m256i positive = _mm256_cmpgt_epi64(_mm256_add_epi64(values, offsets), _mm256_setzero_si256());
    return _mm256_movemask_pd(_mm256_castsi256_pd(positive)) == 0xf;
  }

  // The bounding box block by block, calling block(px, py, inBox, inside, value) for each block
  // not wholly outside an edge: inBox its lanes inside the box, inside whether every lane (and
  // sample) is inside all E edges, value the edge values at lane 0. lowest and highest: the
  // least and greatest offset from lane 0 of any lane (or sample) of a block, per edge.
  // Where no edge value can wrap around 64 bits (cornersDecide), each row of more than
  // kCutBlocks blocks is cut exactly, by integer division, into the run of blocks not wholly
  // outside any edge and, inside it, the run wholly inside all of them; a narrower row decides
  // each block at its corners; elsewhere every block is visited and its lanes tested.
  // run(px, py, count), where given: offered each run of two or more blocks of a cut row that
  // are whole (both rows and four columns in the box) and inside every edge, from (px, py);
  // returns how many of them it drew (0: none), and the rest go to `block` as before.
  struct NoRuns {
    std::int64_t operator()(int, int, std::int64_t) const { return 0; }
  };

  template <int E, class Block, class Run = NoRuns>
  [[SOFTRASTER_FAST_TARGET]] static void walkBlocks(const EdgeFunction (&edges)[E], const PixelRect& box,
                                                    const std::int64_t (&lowest)[E], const std::int64_t (&highest)[E],
                                                    Block&& block, Run&& run = {}) {
    constexpr bool kRuns = !std::is_same_v<std::remove_cvref_t<Run>, NoRuns>;
    // A shader that samples textures is shaded in whole 2x2 quads at even coordinates (as
    // lavapipe's are): the walk starts at the quad-aligned corner, and lanes outside the box are
    // helpers (shaded for the derivatives, never written).
    const PixelRect keep = box;
    const PixelRect walked = kQuads ? PixelRect{box.x0 & ~1, box.y0 & ~1, box.x1, box.y1} : box;
    // Locals, not `edges`: the block's vector stores may alias any memory a reference reaches, so
    // values read through `edges` would be read again after every block.
    std::int64_t rowStart[E], stepX[E], stepY[E];
    for (int i = 0; i < E; ++i) {
      rowStart[i] = edges[i].c + edges[i].dcdy * walked.y0 - edges[i].dcdx * walked.x0;
      stepX[i] = kBatchWidth * edges[i].dcdx;
      stepY[i] = kBatchHeight * edges[i].dcdy;
    }
    const bool corners = cornersDecide(edges, walked);
    // Along a row the E edge values at the block's lane 0 are the lanes of one vector, which a
    // triangle fills with a fourth edge every block is inside (value 0, step 0, offsets 2^62);
    // it is stored whole for the block: an array updated edge by edge and read back as a vector
    // stalled store forwarding once per row (a tenth of the walk of small triangles).
    constexpr std::int64_t kInside = std::int64_t{1} << 62;
    const __m256i stepLanes = edgeLanes<E>([&](int i) { return stepX[i]; }, 0);
    const __m256i highestLanes = edgeLanes<E>([&](int i) { return highest[i]; }, kInside);
    const __m256i lowestLanes = edgeLanes<E>([&](int i) { return lowest[i]; }, kInside);
    const std::int64_t blocks = (walked.x1 - walked.x0) / kBatchWidth + 1;
    // Six divisions per row pay off over a wide row; a narrow one tests each block's corners.
    const bool cut = corners && blocks > kCutBlocks;
    // The blocks whose four columns lie inside the box: in a cut row, those of them wholly inside
    // every edge go straight to `block`, without the per-block tests below (most blocks of a
    // large primitive; the tests were an eighth of a full-screen quad's instructions).
    const std::int64_t columnsFirst = (keep.x0 - walked.x0 + kBatchWidth - 1) / kBatchWidth;
    const std::int64_t columnsLast = keep.x1 - walked.x0 >= kBatchWidth - 1 ? (keep.x1 - walked.x0 - (kBatchWidth - 1)) / kBatchWidth : -1;
    for (int py = walked.y0; py <= walked.y1; py += kBatchHeight) {
      const unsigned rows = (py >= keep.y0 ? 0x0fu : 0u) | (py + 1 <= keep.y1 ? 0xf0u : 0u);
      std::int64_t first = 0, last = blocks - 1, innerFirst = 1, innerLast = 0;
      if (cut) {
        innerFirst = 0, innerLast = blocks - 1;
        for (int i = 0; i < E; ++i) {
          positiveRun(rowStart[i] + highest[i], stepX[i], first, last);
          positiveRun(rowStart[i] + lowest[i], stepX[i], innerFirst, innerLast);
        }
      }
      const std::int64_t plainFirst = std::max(innerFirst, columnsFirst), plainLast = std::min(innerLast, columnsLast);
      __m256i values = edgeLanes<E>([&](int i) { return rowStart[i] - first * stepX[i]; }, 0);
      alignas(32) std::int64_t value[4];
      for (std::int64_t k = first; k <= last; ++k) {
        const int px = walked.x0 + static_cast<int>(k) * kBatchWidth;
        if (k >= plainFirst && k <= plainLast) {  // inside the box's columns and every edge
          if constexpr (kRuns) {
            if (rows == 0xffu && k < plainLast) {  // two or more whole blocks: `run` may take them
              const std::int64_t taken = run(px, py, plainLast - k + 1);
              if (taken > 0) {
                k += taken - 1;
                values = edgeLanes<E>([&](int i) { return rowStart[i] - (k + 1) * stepX[i]; }, 0);
                continue;
              }
            }
          }
          block(px, py, rows, true, reinterpret_cast<const std::int64_t(&)[E]>(value));
          values = _mm256_sub_epi64(values, stepLanes);
          continue;
        }
        unsigned inBox = rows;
        if (px < keep.x0 || px + kBatchWidth - 1 > keep.x1) {  // a block at the box's left or right edge
          const int columns = std::min(kBatchWidth, keep.x1 - px + 1);
          const unsigned left = px < keep.x0 ? (1u << (keep.x0 - px)) - 1u : 0u;  // helper columns left of the box
          inBox = rows & ((((1u << columns) - 1u) & ~left) * 0x11u);
        }
        bool inside = k >= innerFirst && k <= innerLast;
        bool outside = false;
        if (corners && !cut) {
          outside = !allPositive(values, highestLanes);
          inside = allPositive(values, lowestLanes);
        }
        _mm256_store_si256(reinterpret_cast<__m256i*>(value), values);
        if (!outside) block(px, py, inBox, inside, reinterpret_cast<const std::int64_t(&)[E]>(value));
        values = _mm256_sub_epi64(values, stepLanes);
      }
      for (int i = 0; i < E; ++i) rowStart[i] += stepY[i];
    }
  }

  // A block between its tests and its writes: where it lies, the lanes covered and those left
  // after the tests, and the lanes' depth (new and stored).
  struct PendingBlock {
    Floats fx, fy;      // the lanes' pixel coordinates
    std::size_t first;  // lane 0's index in the framebuffer
    bool whole;         // all eight lanes inside the box (so inside the image): plain loads and stores
    unsigned rasterized, covered;  // the lanes tested (after any discards), and those that passed
    Words stored, current;         // the lanes' new depth, and the depth they hold
    Mask passes;                   // the depth test's result per lane
  };
  // (No default member initializers: a walk's blocks waiting to be shaded are left uninitialised
  // until blockAt's are copied in.)

  [[SOFTRASTER_FAST_TARGET]] static PendingBlock blockAt(int px, int py, unsigned covered, bool whole, const BlockTarget& to) {
    PendingBlock b;
    b.fx = broadcast(static_cast<float>(px)) + kLaneX;
    b.fy = broadcast(static_cast<float>(py)) + kLaneY;
    b.first = static_cast<std::size_t>(py) * to.width + static_cast<std::size_t>(px);
    b.whole = whole;
    b.rasterized = covered;
    b.covered = covered;
    b.stored = Words{};
    b.current = Words{};
    b.passes = ~Mask{};  // every lane passes until a depth test says otherwise
    return b;
  }

  // The plain state's depth test (BlockTarget::plain): false when no lane passes.
  [[SOFTRASTER_FAST_TARGET]] static bool testPlainBlock(const BlockPlanes& t, const BlockTarget& to, PendingBlock& b) {
    b.current = b.whole ? loadFullBlock(to.depthStorage + b.first, to.width) : loadBlock(to.depthStorage + b.first, to.width, b.covered);
    b.stored = depthToStorage<Format>(clampDepth(evaluatePlane(t.depth, b.fx, b.fy) + t.depthOffset, to.depthRange));
    b.passes = depthTestPasses<Format>(to.depth.compareOp, b.stored, b.current);
    b.covered &= maskBits(b.passes);  // all lanes pass Always
    return b.covered != 0;
  }

  // The colour of the lanes left.
  [[SOFTRASTER_FAST_TARGET]] static void storeColour(const PendingBlock& b, Words colour, const BlockTarget& to) {
    if (b.covered == 0xffu) {
      storeFullBlock(to.colour + b.first, to.width, colour);
    } else {
      storeBlock(to.colour + b.first, to.width, b.covered, colour);
    }
  }

  // The depth of the lanes left (where depth is tested and written).
  [[SOFTRASTER_FAST_TARGET]] static void storeDepth(const PendingBlock& b, const BlockTarget& to) {
    if (b.whole) {  // lanes that fail keep the value just read: one plain store
      // A block covered whole, without the stencil: the lanes written are those that pass.
      const Mask written = b.rasterized == 0xffu && !to.stencil ? b.passes : laneMask(b.covered);
      storeFullBlock(to.depthStorage + b.first, to.width, selectLanes(written, b.stored, b.current));
    } else {
      storeBlock(to.depthStorage + b.first, to.width, b.covered, b.stored);
    }
  }

  template <int E>
  [[SOFTRASTER_FAST_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] void walk(const EdgeFunction (&edges)[E], const PixelRect& box,
                                                                   const BlockPlanes& planes) const {
    const BlockEdges<E> lanes = blockEdges(edges);
    const BlockTarget to = blockTarget_;  // a local, which no store to the framebuffer can change
    if constexpr (!kQuads) {
      // A box of one block (a part of a larger box the depth tiles cut; shadePrimitive gives small
      // boxes to walkSmallBox): its lanes tested as walkBlocks tests a block it cannot decide at
      // its corners, without setting up the walk.
      if (box.x1 - box.x0 < kBatchWidth && box.y1 - box.y0 < kBatchHeight) {
        std::int64_t value[E];
        for (int i = 0; i < E; ++i) value[i] = edges[i].c + edges[i].dcdy * box.y0 - edges[i].dcdx * box.x0;
        const unsigned columns = (1u << (box.x1 - box.x0 + 1)) - 1u;
        const unsigned inBox = columns * (box.y1 > box.y0 ? 0x11u : 0x01u);
        const unsigned covered = insideBits(lanes, value) & inBox;
        if (covered != 0) shadeBlock(box.x0, box.y0, covered, inBox == 0xffu, planes, to);
        return;
      }
    }
    std::int64_t lowest[E], highest[E];  // of a block's lane offsets, -dcdx * column + dcdy * row
    for (int i = 0; i < E; ++i) {
      const std::int64_t dx = edges[i].dcdx, dy = edges[i].dcdy;
      lowest[i] = std::min<std::int64_t>(0, -(kBatchWidth - 1) * dx) + std::min<std::int64_t>(0, dy);
      highest[i] = std::max<std::int64_t>(0, -(kBatchWidth - 1) * dx) + std::max<std::int64_t>(0, dy);
    }
    if constexpr (kBlockPairs) {
      if (to.plain) {  // the blocks that pass the depth test are shaded two (AVX-512: four) at a time
        PendingBlock waiting[3];
        int count = 0;
        const int group = widePairs_ ? 4 : 2;
        walkBlocks(edges, box, lowest, highest,
                   [&](int px, int py, unsigned inBox, bool inside, const std::int64_t (&value)[E]) {
                     const unsigned covered = inside ? inBox : insideBits(lanes, value) & inBox;
                     if (covered == 0) return;
                     PendingBlock b = blockAt(px, py, covered, inBox == 0xffu, to);
                     if (!testPlainBlock(planes, to, b)) return;
                     if (count + 1 < group) {
                       waiting[count++] = b;
                     } else {
                       if (group == 4) {
                         shadeFourBlocks(waiting[0], waiting[1], waiting[2], b, planes, to);
                       } else {
                         shadeBlockPair(waiting[0], b, planes, to);
                       }
                       count = 0;
                     }
                   });
        // The walk's last blocks: a pair, then one alone.
        if (count >= 2) shadeBlockPair(waiting[0], waiting[1], planes, to);
        if (count % 2 == 1) {
          const PendingBlock& last = waiting[count - 1];
          storeColour(last, shadeLanes(planes, last.fx, last.fy, to), to);
          storeDepth(last, to);
        }
        return;
      }
    }
    const auto block = [&](int px, int py, unsigned inBox, bool inside, const std::int64_t (&value)[E]) {
      const unsigned covered = inside ? inBox : insideBits(lanes, value) & inBox;
      if (covered != 0) shadeBlock(px, py, covered, inBox == 0xffu, planes, to);
    };
#if defined(SOFTRASTER_WIDE_TARGET)
    // Triangles only: a line's quad one pixel wide has no run of whole blocks, and the run's
    // branch in walkBlocks' loop spilled its invariants (the wireframe sphere's frame in
    // crosscheck bench went from 5.8 to 7.2 ms at 2 threads with it).
    if constexpr (kWideRuns && E == 3) {
      if (to.plain && wideRuns_) {
        walkBlocks(edges, box, lowest, highest, block,
                   [&](int px, int py, std::int64_t count) { return shadeRunWide(planes, to, px, py, count); });
        return;
      }
    }
#endif
    walkBlocks(edges, box, lowest, highest, block);
  }

#if defined(SOFTRASTER_WIDE_TARGET)
  // varyingOf over 16 lanes (interpolateVaryings<true> per pixel).
  template <std::size_t I>
  [[SOFTRASTER_WIDE_TARGET]] static FloatBatch16 varyingWide(const WidePlane& p, WideFloats fx, WideFloats fy, WideFloats w) {
    if constexpr (kInterpolation[I] == Interpolation::Perspective) {
      return FloatBatch16(evaluateWide(p, fx, fy) * w);
    } else if constexpr (kInterpolation[I] == Interpolation::NoPerspective) {
      return FloatBatch16(evaluateWide(p, fx, fy));
    } else {
      return FloatBatch16(p.a0);  // a0 of a flat plane: the value
    }
  }
  template <std::size_t... I>
  [[SOFTRASTER_WIDE_TARGET]] static void interpolateWide(std::index_sequence<I...>, const std::array<WidePlane, (N == 0 ? 1 : N)>& planes,
                                                         WideFloats fx, WideFloats fy, WideFloats w, FloatBatch16* out) {
    ((out[I] = varyingWide<I>(planes[I], fx, fy, w)), ...);
  }

  // Whole blocks of the plain state inside every edge (a run along a row, `count` of them from
  // (px, py)), two at a time as one 8x2 rectangle of 16 lanes in AVX-512: each lane's depth test,
  // varyings, shading, packing and writes as shadeBlock's for a whole block (the same operations
  // in the same order). Returns the blocks drawn: `count` rounded down to even (the walk draws an
  // odd last one).
  [[SOFTRASTER_WIDE_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] std::int64_t shadeRunWide(const BlockPlanes& t, const BlockTarget& target,
                                                                                     int px, int py, std::int64_t count) const {
    const BlockTarget to = target;  // a local, which no store to the framebuffer can change (as walk's)
    const std::int64_t pairs = count / 2;
    const WidePlane depth = widen(t.depth), oneOverW = widen(t.oneOverW);
    const WideFloats depthOffset = widen(t.depthOffset);
    std::array<WidePlane, (N == 0 ? 1 : N)> varyingPlanes;
    for (int i = 0; i < N; ++i) varyingPlanes[static_cast<std::size_t>(i)] = widen(t.varyings[static_cast<std::size_t>(i)]);
    const WideFloats fy = static_cast<float>(py) + kWideLaneY;
    for (std::int64_t p = 0; p < pairs; ++p) {
      const int x = px + static_cast<int>(p) * 2 * kBatchWidth;
      const WideFloats fx = static_cast<float>(x) + kWideLaneX;
      const std::size_t first = static_cast<std::size_t>(py) * to.width + static_cast<std::size_t>(x);
      std::uint32_t* depthRow = to.depthStorage + first;
      const __m512i current = loadWideRows(depthRow, depthRow + to.width);
      const WideWords stored = depthToStorageWide<Format>(clampDepthWide(evaluateWide(depth, fx, fy) + depthOffset, to.depthRange));
      const unsigned passes = depthTestPassesWide<Format>(to.depth.compareOp, stored, reinterpret_cast<WideWords>(current));
      if (passes == 0) continue;
      std::array<FloatBatch16, (N == 0 ? 1 : N)> varyings;
      if constexpr (N > 0) {
        WideFloats w{};
        if constexpr (kAnyPerspective) w = 1.0f / evaluateWide(oneOverW, fx, fy);
        interpolateWide(std::make_index_sequence<N>{}, varyingPlanes, fx, fy, w, varyings.data());
      }
      Vec4T<FloatBatch16> c = Shader::template fragment<FloatBatch16>(uniforms_, varyings.data());
      if (to.alphaToOne) c.w = FloatBatch16(1.0f);
      const __m512i colour = packColourWide(c, to.swapRedBlue);
      std::uint32_t* colourRow = to.colour + first;
      if (passes == 0xffffu) {
        storeWideRow(colourRow, colour, 0);
        storeWideRow(colourRow + to.width, colour, 1);
      } else {
        storeWideRow(colourRow, colour, 0, passes & 0xffu);
        storeWideRow(colourRow + to.width, colour, 1, passes >> 8);
      }
      // Lanes that fail keep the value just read: plain stores, as storeDepth's for a whole block.
      const __m512i depthOut = _mm512_mask_blend_epi32(static_cast<__mmask16>(passes), current, reinterpret_cast<__m512i>(stored));
      storeWideRow(depthRow, depthOut, 0);
      storeWideRow(depthRow + to.width, depthOut, 1);
    }
    return pairs * 2;
  }
#endif

  // Two blocks of the plain state that passed the depth test (testPlainBlock), shaded as one
  // FloatBatchPair and written: what shadeBlock does for each, the two shaders' chains of
  // arithmetic interleaved (the Blinn-Phong quad: 12-17% off its frame); where the CPU has
  // AVX-512, as one FloatBatch16 (shadePairWide: the walk's last pair; the others go four
  // blocks at a time, shadeFourBlocks).
  [[SOFTRASTER_FAST_TARGET]] void shadeBlockPair(const PendingBlock& a, const PendingBlock& b, const BlockPlanes& t, const BlockTarget& to) const {
    const std::array<FloatBatchPair, (N == 0 ? 1 : N)> varyings = interpolatePair(std::make_index_sequence<(N == 0 ? 1 : N)>{}, t, a, b);
    writePair(a, b, widePairs_ ? shadeWide(varyings.data()) : Shader::template fragment<FloatBatchPair>(uniforms_, varyings.data()), to);
  }

  // Four blocks of the plain state that passed the depth test, two pairs shaded in one
  // shadeTwoPairsWide call (AVX-512) and written as shadeBlockPair writes a pair.
  [[SOFTRASTER_FAST_TARGET]] void shadeFourBlocks(const PendingBlock& a, const PendingBlock& b, const PendingBlock& c,
                                                  const PendingBlock& d, const BlockPlanes& t, const BlockTarget& to) const {
    const std::array<FloatBatchPair, (N == 0 ? 1 : N)> first = interpolatePair(std::make_index_sequence<(N == 0 ? 1 : N)>{}, t, a, b);
    const std::array<FloatBatchPair, (N == 0 ? 1 : N)> second = interpolatePair(std::make_index_sequence<(N == 0 ? 1 : N)>{}, t, c, d);
    FloatBatchPair colourFirst[4], colourSecond[4];
    shadeTwoPairsWide<Shader>(uniforms_, first.data(), second.data(), colourFirst, colourSecond,
                              std::make_index_sequence<(N == 0 ? 1 : N)>{});
    writePair(a, b, {colourFirst[0], colourFirst[1], colourFirst[2], colourFirst[3]}, to);
    writePair(c, d, {colourSecond[0], colourSecond[1], colourSecond[2], colourSecond[3]}, to);
  }

  // A shaded pair's colour and depth, written.
  [[SOFTRASTER_FAST_TARGET]] static void writePair(const PendingBlock& a, const PendingBlock& b, Vec4T<FloatBatchPair> c, const BlockTarget& to) {
    if (to.alphaToOne) c.w = FloatBatchPair(1.0f);
    storeColour(a, packColour(Vec4T<FloatBatch>{c.x.low, c.y.low, c.z.low, c.w.low}, to.swapRedBlue), to);
    storeColour(b, packColour(Vec4T<FloatBatch>{c.x.high, c.y.high, c.z.high, c.w.high}, to.swapRedBlue), to);
    storeDepth(a, to);
    storeDepth(b, to);
  }

  // The pair's colour from shadePairWide (AVX-512).
  [[SOFTRASTER_FAST_TARGET]] Vec4T<FloatBatchPair> shadeWide(const FloatBatchPair* varyings) const {
    FloatBatchPair colour[4];
    shadePairWide<Shader>(uniforms_, varyings, colour, std::make_index_sequence<(N == 0 ? 1 : N)>{});
    return {colour[0], colour[1], colour[2], colour[3]};
  }

  // interpolateBlock for two blocks: their varyings as the pair's halves. The array is built from
  // them directly; default-constructed and then filled, its twenty vectors were first zeroed on
  // the stack (a fifth more instructions in the lit room's walk).
  template <std::size_t... I>
  [[SOFTRASTER_FAST_TARGET]] static std::array<FloatBatchPair, sizeof...(I)> interpolatePair(std::index_sequence<I...>, const BlockPlanes& t,
                                                                                      const PendingBlock& a, const PendingBlock& b) {
    Floats wa{}, wb{};
    if constexpr (kAnyPerspective) {
      wa = broadcast(1.0f) / evaluatePlane(t.oneOverW, a.fx, a.fy);
      wb = broadcast(1.0f) / evaluatePlane(t.oneOverW, b.fx, b.fy);
    }
    if constexpr (N == 0) {
      return {};
    } else {
      return {FloatBatchPair(varyingOf<I>(t, a.fx, a.fy, wa), varyingOf<I>(t, b.fx, b.fy, wb))...};
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
  // The common state (BlockTarget::plain) takes a path of its own before and after the shader,
  // with a branch or two where the general path tests each feature; the shader is inlined once.
  [[SOFTRASTER_FAST_TARGET]] void shadeBlock(int px, int py, unsigned covered, bool whole, const BlockPlanes& t,
                                             const BlockTarget& to) const {
    const bool plain = kPlainBlocks && to.plain;
    PendingBlock b = blockAt(px, py, covered, whole, to);
    Words shaded{};
    [[maybe_unused]] Floats fragDepth{};
    const bool shadedFirst = to.shadesFirst;
    if (plain) {
      if (!testPlainBlock(t, to, b)) return;
    } else {
      if (shadedFirst) {  // discarded lanes, and those alpha to coverage drops, test and write nothing (as the scalar stage)
        std::uint32_t kept = 0xffu;
        shaded = shadeFirst<1>(t, b.fx, b.fy, b.fx, b.fy, kept, fragDepth);
        b.covered &= kept;
        if (b.covered == 0) return;
        b.rasterized = b.covered;
      }
      if (!depthAndStencil(t, b.fx, b.fy, b.first, whole, fragDepth, to, b.covered, b.stored, b.current, b.passes)) return;
    }
    Words colour = shaded;
    if constexpr (!kBuiltins) {  // (a shader with the built-ins is always shaded first)
      if (!shadedFirst) colour = shadeLanes(t, b.fx, b.fy, to);
    }
    if (!plain && to.readsDestination) {
      colour = blendColour(colour, loadBlock(to.colour + b.first, to.width, b.covered), target_.blend);
    }
    storeColour(b, colour, to);
    if (plain || (to.depth.testEnable && to.depth.writeEnable)) storeDepth(b, to);
  }

  // shadeBlock's depth and stencil tests outside the plain state: false when no lane is left to
  // shade (the stencil, tested and updated for every lane `covered` holds on entry, is written first).
  [[SOFTRASTER_FAST_TARGET]] bool depthAndStencil(const BlockPlanes& t, Floats fx, Floats fy, std::size_t first, bool whole,
                                                  [[maybe_unused]] Floats fragDepth, const BlockTarget& to,
                                                  unsigned& covered, Words& stored, Words& current, Mask& passes) const {
    const unsigned rasterized = covered;
    if (to.depth.testEnable) {
      if (to.depth.compareOp != CompareOp::Always || to.depth.writeEnable) {
        current = whole ? loadFullBlock(to.depthStorage + first, to.width)
                        : loadBlock(to.depthStorage + first, to.width, covered);
      }
      if (to.inverseZ) {  // the course's 1/z buffer: larger is nearer, so compare the other way round
        stored = reinterpret_cast<Words>(evaluatePlane(t.oneOverW, fx, fy));
        passes = depthTestPasses<Format>(to.depth.compareOp, current, stored);
      } else {
        Floats z = fragDepth;
        if constexpr (!kWritesDepth) z = evaluatePlane(t.depth, fx, fy) + t.depthOffset;
        stored = depthToStorage<Format>(clampDepth(z, to.depthRange));
        passes = depthTestPasses<Format>(to.depth.compareOp, stored, current);
      }
      if (to.depth.compareOp != CompareOp::Always) {
        covered &= maskBits(passes);
        if (covered == 0 && !to.stencil) return false;
      }
    }
    if (to.stencil) {
      const StencilFace& face = target_.stencil.face(t.frontFacing);
      const std::size_t width = to.width;
      const auto offset = [width](int lane) { return static_cast<std::size_t>(lane / 4) * width + static_cast<std::size_t>(lane % 4); };
      std::uint8_t* at = target_.stencilStorage + first;
      const Words s = loadStencil(at, rasterized, offset);
      const Mask stencilPasses = stencilTestLanes(face, s);
      storeStencil(at, rasterized, stencilUpdateLanes(face, s, stencilPasses, passes), offset);
      covered &= maskBits(stencilPasses);
      if (covered == 0) return false;
    }
    return true;
  }

  // 4x MSAA. A block is the same 4x2 pixels, seen two ways: the shader's lanes (one per pixel,
  // shaded once at the pixel centre) and four "pairs" of samples as they lie in memory (two
  // adjacent pixels of a row, four samples each: 8 consecutive words), pair = 2 * row + k for
  // pixels 2k and 2k+1. Coverage, depth and the writes work on pairs; each plane is evaluated
  // per sample at (px + sx, py + sy) as the scalar path does.
  struct SampleEdges {
    __m256i offset[3][4][2];  // edge, pair, half (pixel 2k or 2k+1): -dcdx * column + dcdy * row + sample offset
    std::int64_t lowest[3], highest[3];  // of all 32 offsets of an edge
  };

  [[SOFTRASTER_FAST_TARGET]] static SampleEdges sampleEdges(const EdgeFunction (&edges)[3]) {
    SampleEdges e;
    for (int i = 0; i < 3; ++i) {
      std::int64_t sampleOffset[4];
      for (int s = 0; s < 4; ++s) {
        sampleOffset[s] = (kFixedSamplePositions4x[s][1] * edges[i].dcdy - kFixedSamplePositions4x[s][0] * edges[i].dcdx) >>
                          kSubpixelBits;
      }
      e.lowest[i] = INT64_MAX;
      e.highest[i] = INT64_MIN;
      for (int pair = 0; pair < 4; ++pair) {
        for (int half = 0; half < 2; ++half) {
          const int column = 2 * (pair & 1) + half, row = pair >> 1;
          std::int64_t lane[4];
          for (int s = 0; s < 4; ++s) {
            lane[s] = -edges[i].dcdx * column + edges[i].dcdy * row + sampleOffset[s];
            e.lowest[i] = std::min(e.lowest[i], lane[s]);
            e.highest[i] = std::max(e.highest[i], lane[s]);
          }
          e.offset[i][pair][half] = _mm256_set_epi64x(lane[3], lane[2], lane[1], lane[0]);
        }
      }
    }
    return e;
  }

  // Bit 8 * pair + 4 * half + s: sample s of the pair's pixel `half` strictly inside all three edges.
  [[SOFTRASTER_FAST_TARGET]] static std::uint32_t sampleInsideBits(const SampleEdges& e, const std::int64_t (&first)[3]) {
    const __m256i zero = _mm256_setzero_si256();
    std::uint32_t bits = 0;
    for (int pair = 0; pair < 4; ++pair) {
      for (int half = 0; half < 2; ++half) {
        __m256i inside = _mm256_set1_epi64x(-1);
        for (int i = 0; i < 3; ++i) {
          const __m256i value = _mm256_add_epi64(_mm256_set1_epi64x(first[i]), e.offset[i][pair][half]);
          inside = _mm256_and_si256(inside, _mm256_cmpgt_epi64(value, zero));
        }
        bits |= static_cast<std::uint32_t>(_mm256_movemask_pd(_mm256_castsi256_pd(inside))) << (8 * pair + 4 * half);
      }
    }
    return bits;
  }

  // Nibble l of the result: all four samples of lane l where bit l of `pixels` is set.
  static constexpr std::array<std::uint32_t, 256> kSpreadToSamples = [] {
    std::array<std::uint32_t, 256> table{};
    for (unsigned b = 0; b < 256; ++b) {
      for (unsigned l = 0; l < 8; ++l) table[b] |= ((b >> l) & 1u) * (0xfu << (4 * l));
    }
    return table;
  }();

  [[SOFTRASTER_FAST_TARGET]] void shadeSampledTriangle(const EdgeFunction (&edges)[3], const PixelRect& bounds,
                                                       const TriangleInterpolants<N>& t) const {
    if (intersect(bounds, target_.msaa.drawRegion).empty()) return;  // lavapipe culls it
    const PixelRect box = intersect(bounds, target_.region);
    if (box.empty()) return;
    // Nothing passes (but with the stencil on, failing fragments still update it).
    if (target_.depth.testEnable && target_.depth.compareOp == CompareOp::Never && !target_.stencil.enable) return;
    const BlockPlanes planes = blockPlanes(t);
    walkSamples(edges, box, planes);
  }

  // The bounding box block by block, as walk() does, with the coverage of every sample.
  [[SOFTRASTER_FAST_TARGET, SOFTRASTER_FLATTEN, gnu::noinline]] void walkSamples(const EdgeFunction (&edges)[3],
                                                                          const PixelRect& box,
                                                                          const BlockPlanes& planes) const {
    const SampleEdges samples = sampleEdges(edges);
    const BlockTarget to = blockTarget_;  // as in walk()
    walkBlocks(edges, box, samples.lowest, samples.highest,
               [&](int px, int py, unsigned inBox, bool inside, const std::int64_t (&value)[3]) {
                 const std::uint32_t inBoxSamples = kSpreadToSamples[inBox];
                 const std::uint32_t covered = (inside ? inBoxSamples : sampleInsideBits(samples, value) & inBoxSamples) &
                                               allowedBlockSamples(px, py, to);
                 if (covered != 0) shadeSampleBlock(px, py, covered, inBox == 0xffu, planes, to);
               });
  }

  // The samples of the block whose lane 0 is (px, py) that lavapipe's scissor planes let through
  // (bit 4 * lane + s; MsaaRegionEdges): all but in the region's partial column and row.
  std::uint32_t allowedBlockSamples(int px, int py, const BlockTarget& to) const {
    const bool column = to.partialColumn >= px && to.partialColumn < px + kBatchWidth;
    const bool row = to.partialRow >= py && to.partialRow < py + kBatchHeight;
    if (!column && !row) return ~0u;
    const MsaaRegionEdges& m = target_.msaa;
    std::uint32_t allowed = 0;
    for (int lane = 0; lane < kBatchWidth * kBatchHeight; ++lane) {
      allowed |= m.allowedSamples(px + lane % kBatchWidth, py + lane / kBatchWidth) << (4 * lane);
    }
    return allowed;
  }

  // Depth test per sample, shading once per pixel and the writes of the samples `covered` (bit
  // 4 * lane + s) of the block whose lane 0 is (px, py), as the scalar shadeSamples does them.
  [[SOFTRASTER_FAST_TARGET]] void shadeSampleBlock(int px, int py, std::uint32_t covered, bool whole,
                                                   const BlockPlanes& t, const BlockTarget& to) const {
    static constexpr Floats kSampleX = {kSamplePositions4x[0][0], kSamplePositions4x[1][0], kSamplePositions4x[2][0],
                                        kSamplePositions4x[3][0], kSamplePositions4x[0][0], kSamplePositions4x[1][0],
                                        kSamplePositions4x[2][0], kSamplePositions4x[3][0]};
    static constexpr Floats kSampleY = {kSamplePositions4x[0][1], kSamplePositions4x[1][1], kSamplePositions4x[2][1],
                                        kSamplePositions4x[3][1], kSamplePositions4x[0][1], kSamplePositions4x[1][1],
                                        kSamplePositions4x[2][1], kSamplePositions4x[3][1]};
    static constexpr Floats kHalfX = {0, 0, 0, 0, 1, 1, 1, 1};  // the pair's pixel of each lane
    const std::size_t width = to.width;
    const std::size_t firstPixel = static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px);
    const Floats x0 = broadcast(static_cast<float>(px)), y0 = broadcast(static_cast<float>(py));
    __m256i shaded{};
    [[maybe_unused]] Floats fragDepth{};
    covered &= to.sampleMask * 0x11111111u;  // the sample mask, on every lane's nibble
    if (covered == 0) return;
    const bool shadedFirst = to.shadesFirst;
    if (shadedFirst) {  // at the pixel centres; a discard drops every sample of its pixel, alpha to coverage some
      const Floats cx = (x0 + kLaneX) + broadcast(0.5f), cy = (y0 + kLaneY) + broadcast(0.5f);
      std::uint32_t kept = covered;  // gl_SampleMaskIn: each lane's covered samples
      shaded = reinterpret_cast<__m256i>(shadeFirst<4>(t, x0 + kLaneX, y0 + kLaneY, cx, cy, kept, fragDepth));
      covered &= kept;
      if (covered == 0) return;
    }
    std::uint32_t passed = covered;
    // The pair loops are unrolled (GCC 12 at -O2 kept them loops, with these arrays in memory:
    // a third of a 4x MSAA block's instructions).
    Words stored[4]{}, current[4]{};
    Mask passes[4]{};
    if (to.depth.testEnable) {
      passed = 0;
#pragma GCC unroll 4
      for (int pair = 0; pair < 4; ++pair) {
        const unsigned bits = (covered >> (8 * pair)) & 0xffu;
        if (bits == 0) continue;
        const int row = pair >> 1, column = 2 * (pair & 1);
        const std::uint32_t* depth = to.depthStorage + 4 * (firstPixel + static_cast<std::size_t>(row) * width + column);
        if (to.depth.compareOp != CompareOp::Always || to.depth.writeEnable) current[pair] = whole ? loadWords(depth) : loadWords(depth, bits);
        // The sample's position as the scalar path forms it: float(pixel) + sample offset.
        const Floats fx = (x0 + broadcast(static_cast<float>(column)) + kHalfX) + kSampleX;
        const Floats fy = (y0 + broadcast(static_cast<float>(row))) + kSampleY;
        Floats z;
        if constexpr (kWritesDepth) {  // gl_FragDepth: the pixel's one value on each of its samples
          const int lane = 4 * row + column;
          z = reinterpret_cast<Floats>(_mm256_permutevar8x32_ps(
              reinterpret_cast<__m256>(fragDepth), _mm256_setr_epi32(lane, lane, lane, lane, lane + 1, lane + 1, lane + 1, lane + 1)));
        } else {
          z = evaluatePlane(t.depth, fx, fy) + t.depthOffset;
        }
        stored[pair] = depthToStorage<Format>(clampDepth(z, to.depthRange));
        passes[pair] = depthTestPasses<Format>(to.depth.compareOp, stored[pair], current[pair]);
        passed |= (bits & maskBits(passes[pair])) << (8 * pair);
      }
      if (passed == 0 && !to.stencil) return;
    }
    if (to.stencil) {  // per sample, the depth test's result in `passed`
      const StencilFace& face = target_.stencil.face(t.frontFacing);
      const auto offset = [](int lane) { return static_cast<std::size_t>(lane); };
      std::uint32_t stencilPassed = 0;
      for (int pair = 0; pair < 4; ++pair) {
        const unsigned bits = (covered >> (8 * pair)) & 0xffu;
        if (bits == 0) continue;
        const int row = pair >> 1, column = 2 * (pair & 1);
        std::uint8_t* at = target_.stencilStorage + 4 * (firstPixel + static_cast<std::size_t>(row) * width + column);
        const Words s = loadStencil(at, bits, offset);
        const Mask stencilPasses = stencilTestLanes(face, s);
        storeStencil(at, bits, stencilUpdateLanes(face, s, stencilPasses, laneMask((passed >> (8 * pair)) & 0xffu)), offset);
        stencilPassed |= maskBits(stencilPasses) << (8 * pair);
      }
      passed &= stencilPassed;
      if (passed == 0) return;
    }
    // Shaded once per pixel, at its centre.
    __m256i colour = shaded;
    if constexpr (!kBuiltins) {
      if (!shadedFirst) {
        colour = reinterpret_cast<__m256i>(shadeLanes(t, (x0 + kLaneX) + broadcast(0.5f), (y0 + kLaneY) + broadcast(0.5f), to));
      }
    }
#pragma GCC unroll 4
    for (int pair = 0; pair < 4; ++pair) {
      const unsigned bits = (passed >> (8 * pair)) & 0xffu;
      if (bits == 0) continue;
      const int row = pair >> 1, column = 2 * (pair & 1);
      const std::size_t first = 4 * (firstPixel + static_cast<std::size_t>(row) * width + column);
      const int lane = 4 * row + column;  // the shader's lane of the pair's first pixel
      Words c = reinterpret_cast<Words>(
          _mm256_permutevar8x32_epi32(colour, _mm256_setr_epi32(lane, lane, lane, lane, lane + 1, lane + 1, lane + 1, lane + 1)));
      if (to.readsDestination) c = blendColour(c, loadWords(to.colour + first, bits), target_.blend);
      storeWords(to.colour + first, bits, c);
      if (to.depth.testEnable && to.depth.writeEnable) {
        if (whole) {  // samples that fail keep the value just read: one plain store
          // A pair covered whole, without the stencil: the samples written are those that pass.
          const Mask written = ((covered >> (8 * pair)) & 0xffu) == 0xffu && !to.stencil ? passes[pair] : laneMask(bits);
          storeWords(to.depthStorage + first, 0xffu, selectLanes(written, stored[pair], current[pair]));
        } else {
          storeWords(to.depthStorage + first, bits, stored[pair]);
        }
      }
    }
  }

  // The lanes' packed colour, their varyings at (fx, fy), with alpha to one (the path where
  // nothing is shaded before the tests).
  [[SOFTRASTER_FAST_TARGET]] Words shadeLanes(const BlockPlanes& t, Floats fx, Floats fy, const BlockTarget& to) const {
    std::array<FloatBatch, (N == 0 ? 1 : N)> varyings{};
    if constexpr (N > 0) interpolateBlock(std::make_index_sequence<N>{}, t, fx, fy, varyings.data());
    Vec4T<FloatBatch> c = Shader::template fragment<FloatBatch>(uniforms_, varyings.data());
    if (to.alphaToOne) c.w = FloatBatch(1.0f);
    return packColour(c, to.swapRedBlue);
  }

  // The lanes shaded before the tests (a shader with the fragment built-ins, or alpha to
  // coverage): their packed colour, their gl_FragDepth in `fragDepth`, and `kept` narrowed to what
  // survives: with Samples 1 bit per lane (the lanes not discarded, whose alpha covers them and
  // whose gl_SampleMask has bit 0), with 4 bit 4 * lane + s (every sample of a discarded lane
  // dropped; alpha to coverage and gl_SampleMask per sample); with 4 `kept` comes in as the
  // lanes' covered samples, their gl_SampleMaskIn (1 with one sample). (px, py): the lanes' pixel
  // coordinates; (sx, sy): where the planes are evaluated (the same, or the MSAA pixel centres).
  template <int Samples>
  [[SOFTRASTER_FAST_TARGET]] Words shadeFirst(const BlockPlanes& t, Floats px, Floats py, Floats sx, Floats sy,
                                              std::uint32_t& kept, Floats& fragDepth) const {
    std::array<FloatBatch, (N == 0 ? 1 : N)> varyings{};
    if constexpr (N > 0) interpolateBlock(std::make_index_sequence<N>{}, t, sx, sy, varyings.data());
    Vec4T<FloatBatch> c;
    if constexpr (kBuiltins) {
      FragmentBuiltins<FloatBatch> builtins;
      builtins.fragCoord = {FloatBatch(px + broadcast(0.5f)), FloatBatch(py + broadcast(0.5f)),
                            FloatBatch(evaluatePlane(t.depth, sx, sy) + t.depthOffset),
                            FloatBatch(evaluatePlane(t.oneOverW, sx, sy))};
      builtins.frontFacing = t.frontFacing;
      if constexpr (Samples == 4) {
        static constexpr IntBatch::Native kNibble = {0, 4, 8, 12, 16, 20, 24, 28};
        builtins.sampleMaskIn = IntBatch((IntBatch::Native{} + static_cast<std::int32_t>(kept)) >> kNibble & 0xf);
      }
      c = Shader::template fragment<FloatBatch>(uniforms_, varyings.data(), builtins);
      const unsigned survivors = ~maskBits(builtins.discard.native()) & 0xffu;
      kept &= Samples == 4 ? kSpreadToSamples[survivors] : survivors;
      if constexpr (kWritesSampleMask) {
        const IntBatch::Native out = builtins.sampleMask.native();
        if constexpr (Samples == 4) {
          std::uint32_t samples = 0;
          for (int lane = 0; lane < kBatchLanes; ++lane) {
            samples |= (static_cast<std::uint32_t>(out[lane]) & 0xfu) << (4 * lane);
          }
          kept &= samples;
        } else {
          kept &= maskBits((out & 1) != 0);
        }
      }
      fragDepth = builtins.fragDepth.native();
    } else {
      c = Shader::template fragment<FloatBatch>(uniforms_, varyings.data());
    }
    if (target_.coverage.alphaToCoverage) kept &= alphaToCoverageBits<Samples>(c.w.native());
    if (target_.coverage.alphaToOne) c.w = FloatBatch(1.0f);
    return packColour(c, target_.blend.swapRedBlue);
  }

  // alphaToCoverageSamples (fragment/coverage.hpp) on the lanes: bit per lane with one sample,
  // bit 4 * lane + s with four; unordered like it (~(alpha <= t): a NaN alpha keeps every sample).
  template <int Samples>
  [[SOFTRASTER_FAST_TARGET]] static std::uint32_t alphaToCoverageBits(Floats alpha) {
    if constexpr (Samples == 1) {
      return maskBits(~(alpha <= broadcast(0.5f)));
    } else {
      std::uint32_t bits = 0;
      for (unsigned s = 0; s < 4; ++s) {
        const float threshold = 0.25f * static_cast<float>(s);  // 0, 0.25, 0.5, 0.75, as alphaToCoverageSamples
        bits |= kSpreadToSamples[maskBits(~(alpha <= broadcast(threshold)))] & (0x11111111u << s);
      }
      return bits;
    }
  }

  static constexpr bool kBuiltins = UsesFragmentBuiltins<Shader>;
  static constexpr bool kWritesDepth = WritesFragDepth<Shader>;
  static constexpr bool kPlainBlocks = !kBuiltins;  // BlockTarget::plain can hold
  static constexpr bool kBlockPairs = kPlainBlocks && !kQuads && ShadesBlockPairs<Shader>;
  // Runs of whole blocks go 16 lanes at a time with AVX-512 (shadeRunWide): the shaders that are
  // not shaded in pairs (short ones, where the walk's own work is most of a block's).
  static constexpr bool kWideRuns = kPlainBlocks && !kQuads && !kBlockPairs;
  static constexpr bool kWritesSampleMask = WritesSampleMask<Shader>;

  FragmentStage<Shader, true, Format> scalar_;
  const typename Shader::Uniforms& uniforms_;
  const FragmentTarget& target_;  // the scalar stage's: one value, derived once
  std::uint32_t* colour_;         // target_.colour as packed RGBA8, one word per pixel
  DepthTiles<depthAspect(Format)> depthTiles_;  // skips the tiles no fragment could pass
  bool widePairs_;  // block pairs shaded as FloatBatch16 (AVX-512: cpuShadesWidePairs, and allowAvx512)
  bool wideRuns_;   // runs of whole blocks 16 lanes at a time (AVX-512, the same conditions)
  BlockTarget blockTarget_;  // makeBlockTarget(): target_ does not change
};

}  // namespace softraster::detail::fast

#pragma GCC diagnostic pop

#endif  // SOFTRASTER_HAS_FAST_PATH
