// softraster's draw loop timed with Google Benchmark, one translation unit with two shading models
// (vertex_color, and Blinn-Phong per pixel for one quad; D32_SFLOAT), so it builds in a minute
// where crosscheck bench needs every model.
// For profiling and tuning the exact method's fast path between full benches: frames of
// the shapes crosscheck bench's scenes stress (a full-screen quad: pixels; spheres of 100k and 1M
// triangles: the front end and the band queue, the 1M one also with back faces culled; the 100k
// sphere in polygon mode line: lines; stacked quads: overdraw, and with 4x MSAA the per-sample
// walk; 20k small triangles in 10 draws: the walk of a triangle of a few blocks), at 1 and 2
// threads. The three whose time is most per primitive also run cold (`...Cold`: the caches
// filled with other data before each frame, as the bench's alternating frames leave them).
// SmallTrianglesOneDraw and ...HundredDraws: the same triangles in 1 and in 100 draws, what
// cutting a frame into draws costs; ...InAPass: the 10 and the 100 draws as one softraster::Pass.
// PhongQuad: a full-screen quad lit per pixel, the cost of a real fragment shader;
// BlinnPhongFragmentAlone: that shader alone, one block or two per call. FullScreenQuadAvx2 and
// PhongQuadAvx2: those two with AVX-512 not allowed (ContextOptions::allowAvx512).
//   softraster_benchmarks --benchmark_filter=Sphere --benchmark_repetitions=5
// Deliberately not a replacement for `crosscheck bench`: no lavapipe beside it, no agreement
// check; times are the machine's (shared and noisy: compare medians, side by side). "CPU" is the
// whole process's (every thread's), so a thread count's overhead shows even on a loaded machine.
#include "lit.hpp"
#include "vertex_color.hpp"

#include <softraster/detail/fast/batch.hpp>
#include <softraster/pass.hpp>
#include <softraster/pipeline.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <utility>
#include <vector>

namespace {

using Shader = shaders::VertexColor;
using PhongShader = shaders::BlinnPhongPixel;
constexpr std::uint32_t kWidth = 1920, kHeight = 1080;

template <class S>
struct MeshOf {
  std::vector<typename S::Vertex> vertices;
  std::vector<std::uint32_t> indices;
};
using Mesh = MeshOf<Shader>;

// A sphere of about `triangles` triangles in clip space (x, y in [-0.9, 0.9] scaled to the
// aspect ratio, z in [0.1, 0.9]), latitude by longitude, coloured by position.
Mesh sphere(std::uint32_t triangles) {
  const auto rings = static_cast<std::uint32_t>(std::sqrt(triangles / 4.0));
  const std::uint32_t segments = 2 * rings;
  Mesh m;
  for (std::uint32_t r = 0; r <= rings; ++r) {
    const double theta = std::numbers::pi * r / rings;
    for (std::uint32_t s = 0; s <= segments; ++s) {
      const double phi = 2 * std::numbers::pi * s / segments;
      const float x = static_cast<float>(std::sin(theta) * std::cos(phi)), y = static_cast<float>(std::cos(theta));
      const float z = static_cast<float>(std::sin(theta) * std::sin(phi));
      m.vertices.push_back({{0.9f * x * kHeight / kWidth, 0.9f * y, 0.5f + 0.4f * z},
                            {0.5f + 0.5f * x, 0.5f + 0.5f * y, 0.5f + 0.5f * z, 1.0f}});
    }
  }
  for (std::uint32_t r = 0; r < rings; ++r) {
    for (std::uint32_t s = 0; s < segments; ++s) {
      const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      m.indices.insert(m.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return m;
}

// `count` full-screen quads, back to front (z from 0.9 down) or front to back.
Mesh quads(std::uint32_t count, bool backToFront) {
  Mesh m;
  for (std::uint32_t q = 0; q < count; ++q) {
    const float z = backToFront ? 0.9f - 0.08f * q : 0.1f + 0.08f * q;
    const float c = static_cast<float>(q) / static_cast<float>(count);
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    for (const auto& [x, y] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {-1.0f, 1.0f}, {1.0f, 1.0f}}) {
      m.vertices.push_back({{x, y, z}, {c, 0.5f * (x + 1.0f), 0.5f * (y + 1.0f), 1.0f}});
    }
    m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base + 1, base + 2, base + 3});
  }
  return m;
}

// `count` scattered triangles of about 10 pixels at random depths, both windings, coloured at
// random, in `draws` meshes of their own (as scenes/bench/small_triangles_1080p.json): a fixed
// linear congruential sequence.
std::vector<Mesh> smallTriangles(std::uint32_t count, std::uint32_t draws) {
  std::uint64_t state = 12345;
  const auto next = [&state] {  // in [0, 1)
    state = state * 6364136223846793005u + 1442695040888963407u;
    return static_cast<float>(state >> 40) / static_cast<float>(1u << 24);
  };
  std::vector<Mesh> meshes(draws);
  for (std::uint32_t t = 0; t < count; ++t) {
    Mesh& m = meshes[t % draws];
    const float cx = -0.95f + 1.9f * next(), cy = -0.95f + 1.9f * next(), z = 0.05f + 0.9f * next();
    const float angle = 6.2831853f * next(), flip = next() < 0.5f ? 1.0f : -1.0f;
    const softraster::Vec4 colour{next(), next(), next(), 1.0f};
    for (int k = 0; k < 3; ++k) {
      const float a = angle + flip * 2.0943951f * static_cast<float>(k);  // radius ~2.8 px: ~10 px
      m.vertices.push_back({{cx + 0.0029f * std::cos(a), cy + 0.0052f * std::sin(a), z}, colour});
      m.indices.push_back(static_cast<std::uint32_t>(m.indices.size()));
    }
  }
  return meshes;
}

// How drawFrames draws: its triangles filled or as lines, the samples, the culling, and whether
// each frame starts cold.
struct FrameOptions {
  softraster::PolygonMode mode = softraster::PolygonMode::Fill;
  std::uint32_t samples = 1;
  softraster::CullMode cull = softraster::CullMode::None;
  // Before each frame (untimed), write a buffer far larger than the last-level cache, so the frame
  // finds neither the framebuffer nor the vertices in any cache: as in `crosscheck bench`, where
  // lavapipe's frame runs between two of softraster's. Warm frames hide the wait on memory that
  // a small primitive's first depth read has there (20k small triangles: 3.4-3.7 ms warm,
  // 4.7 ms in the bench, 2 threads).
  bool cold = false;
  // ContextOptions::allowAvx512: off, the fast path is AVX2 only even where the CPU has AVX-512
  // (FullScreenQuadAvx2: no 16-lane runs of whole blocks; PhongQuadAvx2: long shaders' blocks two
  // at a time in 8 lanes).
  bool allowAvx512 = true;
  // The meshes drawn as one softraster::Pass (pass.hpp) instead of draw by draw.
  bool pass = false;
};

// Writes one byte in every 64 of `buffer`: each of its cache lines once.
void writeEveryLine(std::vector<unsigned char>& buffer) {
  for (std::size_t i = 0; i < buffer.size(); i += 64) buffer[i] = static_cast<unsigned char>(buffer[i] + 1);
  benchmark::DoNotOptimize(buffer.data());
  benchmark::ClobberMemory();
}

// One frame per iteration: clear, then each mesh as one indexed draw (depth LESS).
template <class S>
void drawFrames(benchmark::State& bench, std::span<const MeshOf<S>> meshes, const typename S::Uniforms& uniforms,
                const FrameOptions& how) {
  softraster::ContextOptions options;
  options.threads = static_cast<unsigned>(bench.range(0));
  options.allowAvx512 = how.allowAvx512;
  const softraster::Context context(options);
  auto framebuffer = softraster::Framebuffer::create(kWidth, kHeight, softraster::DepthFormat::D32Sfloat, how.samples);
  if (!framebuffer) {
    bench.SkipWithError(framebuffer.error().c_str());
    return;
  }
  softraster::PipelineState state;
  state.rasterization.cullMode = how.cull;
  state.rasterization.polygonMode = how.mode;
  std::size_t triangles = 0;
  for (const MeshOf<S>& mesh : meshes) triangles += mesh.indices.size() / 3;
  std::vector<unsigned char> evict(how.cold ? std::size_t{256} << 20 : 0);
  softraster::Pass pass(context);
  for (auto _ : bench) {
    if (how.cold) {
      bench.PauseTiming();
      writeEveryLine(evict);
      bench.ResumeTiming();
    }
    framebuffer->clear({0, 0, 0, 1}, 1.0f);
    if (how.pass) pass.begin(*framebuffer);
    for (const MeshOf<S>& mesh : meshes) {
      const softraster::Status status =
          how.pass ? pass.drawIndexed<S, softraster::DepthFormat::D32Sfloat>(state, uniforms, mesh.vertices, mesh.indices)
                   : context.drawIndexed<S, softraster::DepthFormat::D32Sfloat>(state, uniforms, mesh.vertices,
                                                                                mesh.indices, *framebuffer);
      if (!status) {
        bench.SkipWithError(status.message().c_str());
        return;
      }
    }
    pass.end();
    benchmark::DoNotOptimize(framebuffer->colour().data());
    benchmark::ClobberMemory();
  }
  bench.counters["triangles"] = static_cast<double>(triangles);
}
// vertex_color's meshes, in clip space.
void drawFrames(benchmark::State& bench, std::span<const Mesh> meshes, const FrameOptions& how = {}) {
  Shader::Uniforms uniforms;
  uniforms.modelViewProjection = softraster::Mat4::identity();
  drawFrames<Shader>(bench, meshes, uniforms, how);
}
void drawFrames(benchmark::State& bench, const Mesh& mesh, const FrameOptions& how = {}) {
  drawFrames(bench, std::span(&mesh, 1), how);
}

// The meshes several benchmarks draw, each made once (on first use).
const Mesh& sphere100k() {
  static const Mesh mesh = sphere(100'000);
  return mesh;
}
const Mesh& sphere1M() {
  static const Mesh mesh = sphere(1'000'000);
  return mesh;
}
const std::vector<Mesh>& smallTriangles20k() {
  static const std::vector<Mesh> meshes = smallTriangles(20'000, 10);
  return meshes;
}

void Sphere100k(benchmark::State& bench) {
  drawFrames(bench, sphere100k());
}
void WireframeSphere100k(benchmark::State& bench) {
  drawFrames(bench, sphere100k(), {.mode = softraster::PolygonMode::Line});
}
void Sphere1M(benchmark::State& bench) {
  drawFrames(bench, sphere1M());
}
void Sphere1MCulled(benchmark::State& bench) {  // as scenes/bench/sphere_1m.json: back faces culled
  drawFrames(bench, sphere1M(), {.cull = softraster::CullMode::Back});
}
void FullScreenQuad(benchmark::State& bench) {
  static const Mesh mesh = quads(1, true);
  drawFrames(bench, mesh);
}
// The same with AVX-512 not allowed: the quad's blocks one at a time in AVX2.
void FullScreenQuadAvx2(benchmark::State& bench) {
  static const Mesh mesh = quads(1, true);
  drawFrames(bench, mesh, {.allowAvx512 = false});
}
void QuadStackBackToFront(benchmark::State& bench) {
  static const Mesh mesh = quads(10, true);
  drawFrames(bench, mesh);
}
void QuadStackFrontToBack(benchmark::State& bench) {
  static const Mesh mesh = quads(10, false);
  drawFrames(bench, mesh);
}
void QuadStackBackToFrontMsaa(benchmark::State& bench) {
  static const Mesh mesh = quads(4, true);
  drawFrames(bench, mesh, {.samples = 4});
}
// The same 20k small triangles in one draw and in 100 draws: what cutting a frame into draws
// costs. Each draw is finished before the next starts, so with two threads a band sees one
// draw's triangles at a time, and its rows leave the core's cache between draws; a draw under
// 512 primitives also runs its front end on the calling thread alone.
void SmallTrianglesOneDraw(benchmark::State& bench) {
  static const std::vector<Mesh> meshes = smallTriangles(20'000, 1);
  drawFrames(bench, meshes);
}
void SmallTrianglesHundredDraws(benchmark::State& bench) {
  static const std::vector<Mesh> meshes = smallTriangles(20'000, 100);
  drawFrames(bench, meshes);
}
void SmallTriangles(benchmark::State& bench) {
  drawFrames(bench, smallTriangles20k());
}
// The same draws as one pass: each band sees every draw's triangles at once.
void SmallTrianglesInAPass(benchmark::State& bench) {
  drawFrames(bench, smallTriangles20k(), {.pass = true});
}
void SmallTrianglesHundredDrawsInAPass(benchmark::State& bench) {
  static const std::vector<Mesh> meshes = smallTriangles(20'000, 100);
  drawFrames(bench, meshes, {.pass = true});
}
// Cold frames (FrameOptions::cold) of the scenes whose time is most per primitive.
void SmallTrianglesCold(benchmark::State& bench) {
  drawFrames(bench, smallTriangles20k(), {.cold = true});
}
void Sphere100kCold(benchmark::State& bench) {
  drawFrames(bench, sphere100k(), {.cold = true});
}
void WireframeSphere100kCold(benchmark::State& bench) {
  drawFrames(bench, sphere100k(), {.mode = softraster::PolygonMode::Line, .cold = true});
}
// The single-draw meshes as crosscheck draws them: cold, and in a pass, whose front end keeps
// its records across rounds until the pass's flush budget (fast/deferred_draws.hpp).
void Sphere100kColdInAPass(benchmark::State& bench) {
  drawFrames(bench, sphere100k(), {.cold = true, .pass = true});
}
void WireframeSphere100kColdInAPass(benchmark::State& bench) {
  drawFrames(bench, sphere100k(), {.mode = softraster::PolygonMode::Line, .cold = true, .pass = true});
}
void Sphere1MCulledColdInAPass(benchmark::State& bench) {
  drawFrames(bench, sphere1M(), {.cull = softraster::CullMode::Back, .cold = true, .pass = true});
}

// A full-screen quad lit per pixel with Blinn-Phong, the shape of
// scenes/bench/phong_quad_1080p.json (its material: shininess 32): the shader's arithmetic on
// every pixel. Clip space is the lighting space here, so the eye
// looks from the origin at a plane facing it, with the light in front of it.
void drawPhongQuad(benchmark::State& bench, const FrameOptions& how) {
  static const MeshOf<PhongShader> mesh = [] {
    MeshOf<PhongShader> m;
    for (const auto& [x, y] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {-1.0f, 1.0f}, {1.0f, 1.0f}}) {
      m.vertices.push_back({{x, y, 0.5f}, {0.0f, 0.0f, -1.0f}, {0.5f + 0.4f * x, 0.5f + 0.4f * y, 0.6f, 1.0f}});
    }
    m.indices = {0, 2, 1, 1, 2, 3};
    return m;
  }();
  PhongShader::Uniforms u;
  u.modelViewProjection = softraster::Mat4::identity();
  u.modelToLighting = softraster::Mat4::identity();
  u.normalToLighting = softraster::Mat4::identity();
  u.lightPosition = {0.4f, -0.3f, -0.1f, 1.0f};
  u.lightPower = {1.0f, 0.95f, 0.9f, 0.0f};
  u.indirect = {0.1f, 0.1f, 0.1f, 0.0f};
  u.specular = {0.6f, 0.6f, 0.6f, 32.0f};
  drawFrames<PhongShader>(bench, std::span(&mesh, 1), u, how);
}
void PhongQuad(benchmark::State& bench) { drawPhongQuad(bench, {}); }
// The same with AVX-512 not allowed: the blocks two at a time in AVX2 (the same on a CPU without it).
void PhongQuadAvx2(benchmark::State& bench) { drawPhongQuad(bench, {.allowAvx512 = false}); }

// The Blinn-Phong fragment function alone, the PhongQuad's shader without the walk: 512 blocks
// of that quad's varyings (about 160 KB, in the core's caches), shaded a block per call
// (FloatBatch) or two (FloatBatchPair, kBlockPairs; or FloatBatch16 where the CPU has AVX-512,
// BlinnPhongFragmentAloneWide), on the calling thread. Its time per block
// (the counter) is the arithmetic's floor for a frame of the quad at 8 lanes: lavapipe spends
// about 108 ns of CPU per block on the scene, so 3x lavapipe leaves 36 ns for everything.
// Flattened into an AVX2 + FMA function, as the fast path runs a shader. One thread only.
constexpr int kShadedBlocks = 512;

[[gnu::target("avx2,fma"), gnu::flatten, gnu::noinline]] void shadeBlocks(const PhongShader::Uniforms& u,
                                                                         const std::vector<float>& in,
                                                                         std::vector<float>& out, bool pairs) {
  using softraster::FloatBatch;
  using softraster::FloatBatchPair;
  constexpr int kLanes = softraster::kBatchLanes, kIn = PhongShader::kVaryings;
  const auto load = [&](int block, int i) { return FloatBatch::load(in.data() + (block * kIn + i) * kLanes); };
  const auto store = [&](int block, const softraster::Vec4T<FloatBatch>& c) {
    c.x.store(out.data() + (block * 4 + 0) * kLanes);
    c.y.store(out.data() + (block * 4 + 1) * kLanes);
    c.z.store(out.data() + (block * 4 + 2) * kLanes);
    c.w.store(out.data() + (block * 4 + 3) * kLanes);
  };
  if (pairs) {
    for (int b = 0; b < kShadedBlocks; b += 2) {
      FloatBatchPair v[kIn];
      for (int i = 0; i < kIn; ++i) v[i] = FloatBatchPair(load(b, i), load(b + 1, i));
      const softraster::Vec4T<FloatBatchPair> c = PhongShader::fragment<FloatBatchPair>(u, v);
      store(b, {c.x.low, c.y.low, c.z.low, c.w.low});
      store(b + 1, {c.x.high, c.y.high, c.z.high, c.w.high});
    }
  } else {
    for (int b = 0; b < kShadedBlocks; ++b) {
      FloatBatch v[kIn];
      for (int i = 0; i < kIn; ++i) v[i] = load(b, i);
      store(b, PhongShader::fragment<FloatBatch>(u, v));
    }
  }
}

// The same blocks two at a time as one FloatBatch16 (block b's lanes, then block b + 1's), as the
// fast path shades a pair where the CPU has AVX-512 (shadePairWide); AVX-512 code, flattened.
[[SOFTRASTER_WIDE_TARGET, gnu::flatten, gnu::noinline]] void shadeBlocksWide(const PhongShader::Uniforms& u,
                                                                          const std::vector<float>& in, std::vector<float>& out) {
  using softraster::FloatBatch16;
  constexpr int kLanes = softraster::kBatchLanes, kIn = PhongShader::kVaryings;
  const auto load = [&](int block, int i) {
    return softraster::joinHalves({softraster::FloatBatch::load(in.data() + (block * kIn + i) * kLanes),
                                   softraster::FloatBatch::load(in.data() + ((block + 1) * kIn + i) * kLanes)});
  };
  const auto store = [&](int block, int channel, const FloatBatch16& f) {
    const softraster::FloatBatchPair p = softraster::splitHalves(f);
    p.low.store(out.data() + (block * 4 + channel) * kLanes);
    p.high.store(out.data() + ((block + 1) * 4 + channel) * kLanes);
  };
  for (int b = 0; b < kShadedBlocks; b += 2) {
    FloatBatch16 v[kIn];
    for (int i = 0; i < kIn; ++i) v[i] = load(b, i);
    const softraster::Vec4T<FloatBatch16> c = PhongShader::fragment<FloatBatch16>(u, v);
    store(b, 0, c.x);
    store(b, 1, c.y);
    store(b, 2, c.z);
    store(b, 3, c.w);
  }
}

// blocks_per_call: 1 (FloatBatch) or 2 (FloatBatchPair); BlinnPhongFragmentAloneWide: 2 as one
// FloatBatch16.
void shadeBlocksAlone(benchmark::State& bench, bool pairs, bool wide) {
  PhongShader::Uniforms u;
  u.lightPosition = {0.4f, -0.3f, -0.1f, 1.0f};
  u.lightPower = {1.0f, 0.95f, 0.9f, 0.0f};
  u.indirect = {0.1f, 0.1f, 0.1f, 0.0f};
  u.specular = {0.6f, 0.6f, 0.6f, 32.0f};
  // The quad's varyings (PhongQuad: position, normal, colour) at the pixels of a few rows of 4x2
  // blocks across the middle of the frame.
  constexpr int kLanes = softraster::kBatchLanes, kIn = PhongShader::kVaryings;
  std::vector<float> in(static_cast<std::size_t>(kShadedBlocks * kIn * kLanes));
  std::vector<float> out(static_cast<std::size_t>(kShadedBlocks * 4 * kLanes));
  for (int b = 0; b < kShadedBlocks; ++b) {
    for (int lane = 0; lane < kLanes; ++lane) {
      const int px = (4 * b) % static_cast<int>(kWidth) + lane % 4;
      const int py = 500 + lane / 4 + 2 * ((4 * b) / static_cast<int>(kWidth));
      const float x = -1.0f + 2.0f * (static_cast<float>(px) + 0.5f) / kWidth;
      const float y = -1.0f + 2.0f * (static_cast<float>(py) + 0.5f) / kHeight;
      const float v[kIn] = {x, y, 0.5f, 0.0f, 0.0f, -1.0f, 0.5f + 0.4f * x, 0.5f + 0.4f * y, 0.6f, 1.0f};
      for (int i = 0; i < kIn; ++i) in[static_cast<std::size_t>((b * kIn + i) * kLanes + lane)] = v[i];
    }
  }
  for (auto _ : bench) {
    if (wide) {
      shadeBlocksWide(u, in, out);
    } else {
      shadeBlocks(u, in, out, pairs);
    }
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  // CPU seconds per block, printed with an SI prefix (53n: 53 ns).
  bench.counters["per_block"] = benchmark::Counter(static_cast<double>(bench.iterations()) * kShadedBlocks,
                                                   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BlinnPhongFragmentAlone(benchmark::State& bench) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    bench.SkipWithError("no AVX2 + FMA");
    return;
  }
  shadeBlocksAlone(bench, bench.range(0) == 2, false);
}

void BlinnPhongFragmentAloneWide(benchmark::State& bench) {
  if (!softraster::detail::fast::cpuShadesWidePairs()) {
    bench.SkipWithError("no AVX-512 F, VL, BW and DQ");
    return;
  }
  shadeBlocksAlone(bench, true, true);
}

}  // namespace

// Every benchmark: one frame per iteration, at 1 and 2 threads, real time beside the whole
// process's CPU time.
#define FRAME_BENCHMARK(name) \
  BENCHMARK(name)->ArgName("threads")->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()

FRAME_BENCHMARK(Sphere100k);
FRAME_BENCHMARK(WireframeSphere100k);
FRAME_BENCHMARK(Sphere1M);
FRAME_BENCHMARK(Sphere1MCulled);
FRAME_BENCHMARK(FullScreenQuad);
FRAME_BENCHMARK(FullScreenQuadAvx2);
FRAME_BENCHMARK(QuadStackBackToFront);
FRAME_BENCHMARK(QuadStackBackToFrontMsaa);
FRAME_BENCHMARK(SmallTriangles);
FRAME_BENCHMARK(QuadStackFrontToBack);
FRAME_BENCHMARK(SmallTrianglesCold);
FRAME_BENCHMARK(Sphere100kCold);
FRAME_BENCHMARK(WireframeSphere100kCold);
FRAME_BENCHMARK(SmallTrianglesOneDraw);
FRAME_BENCHMARK(SmallTrianglesHundredDraws);
FRAME_BENCHMARK(PhongQuad);
FRAME_BENCHMARK(PhongQuadAvx2);
// Blocks per call: 1 (FloatBatch) or 2 (FloatBatchPair).
BENCHMARK(BlinnPhongFragmentAlone)->ArgName("blocks_per_call")->Arg(1)->Arg(2);
BENCHMARK(BlinnPhongFragmentAloneWide);
FRAME_BENCHMARK(SmallTrianglesInAPass);
FRAME_BENCHMARK(SmallTrianglesHundredDrawsInAPass);
FRAME_BENCHMARK(Sphere100kColdInAPass);
FRAME_BENCHMARK(WireframeSphere100kColdInAPass);
FRAME_BENCHMARK(Sphere1MCulledColdInAPass);

BENCHMARK_MAIN();
