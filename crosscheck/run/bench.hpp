// The bench runner: steady-state frame times of softraster (each method asked for: exact and
// exact-scalar by default, any of options.hpp's kMethods, a course method also with affine
// varyings) and of vkref on lavapipe for each scene, and how closely each method agrees with
// Vulkan. Per scene every renderer is made
// ready once (softraster: a SoftrasterScene, i.e. Context, framebuffer and draws; lavapipe: a
// Renderer opened and the frame prepared), then warm-up frames and timed frames are drawn with the
// renderers taking turns frame by frame (the methods in order, lavapipe, repeat), each frame timed
// with std::chrono::steady_clock. Setup (making ready plus the first frame) is timed apart. Before
// the first scene the C allocator's thresholds are fixed (settleAllocator), so a scene's times do
// not depend on the scenes run before it. After
// the timed frames each method's last frame is compared with lavapipe's (compare/compareFrames).
// The result is a BenchResults value, the only thing the bench writers (output/bench_*) read.
// Deliberately no printing, no files and no argument checks (cli/bench.cpp), and no statistics
// beyond median and minimum: the machine is assumed noisy, so the median is the headline.
#pragma once

#include "compare/metrics.hpp"
#include "scene/scene.hpp"

#include <softraster/options.hpp>
#include <vkref/renderer.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace crosscheck {

struct BenchScene;

// One softraster contender of a bench run: a method, and for a course method whether its
// varyings are affine (ContextOptions::affineVaryings).
struct BenchMethod {
  softraster::Method method = softraster::Method::Exact;
  bool affineVaryings = false;
  // "exact", "scanline", "scanline+affine": how the table and the --method list name it.
  std::string label() const;
  bool operator==(const BenchMethod&) const = default;
};

// The bench's --method value: "all" (every kMethods entry, in order) or a comma-separated list of
// method names, a course method's name optionally followed by "+affine"; nothing for an unknown
// or malformed entry (or an exact method with +affine).
std::optional<std::vector<BenchMethod>> parseBenchMethods(const std::string& text);

struct BenchOptions {
  unsigned frames = 15;  // timed frames per renderer (at least 1)
  unsigned warmup = 3;   // untimed frames per renderer before them
  // softraster's Context threads and lavapipe's LP_NUM_THREADS; 0 = every core. LP_NUM_THREADS is
  // set (setenv) before each Vulkan renderer is opened.
  unsigned threads = 0;
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;  // fmuladd and depth mode; method, affine varyings and threads are the bench's
  // The softraster methods timed, in order (each once, then lavapipe).
  std::vector<BenchMethod> methods{{softraster::Method::Exact}, {softraster::Method::ExactScalar}};
  // Called after each scene (for progress): (its position, the number of scenes, its result).
  std::function<void(std::size_t, std::size_t, const BenchScene&)> onScene;
};

// The machine the numbers come from.
struct BenchMachine {
  std::string cpu;                 // "model name" of /proc/cpuinfo ("unknown" without it)
  unsigned cores = 0;              // std::thread::hardware_concurrency()
  // Median memset bandwidth over a 1080p RGBA8 + D32 buffer that starts in no cache: the memory
  // bandwidth that memory_limit_ms is taken at.
  double memsetGigabytesPerSecond = 0;
  // The same memset repeated with the buffer in cache (where it fits: the last-level cache's speed).
  double memsetWarmGigabytesPerSecond = 0;
  // How the run set the C allocator (settleAllocator), e.g. "glibc: mmap threshold 32 MiB, trim
  // threshold 64 MiB"; runBench fills it in.
  std::string allocator;
};

// One renderer (or softraster method) on one scene.
struct BenchRun {
  std::string renderer;            // "softraster" or "lavapipe"
  std::string method;              // softraster: methodName ("exact", "scanline", ...); lavapipe: empty
  bool affineVaryings = false;     // softraster: a course method with affine varyings
  // Threads that draw: softraster's Context threads (exact-scalar and the course's methods draw
  // on the calling thread alone, so 1), lavapipe's LP_NUM_THREADS.
  unsigned threads = 0;
  std::vector<double> frameMilliseconds;  // the timed frames, in order
  double medianMilliseconds = 0, minMilliseconds = 0;
  double setupMilliseconds = 0;    // softraster: Context, framebuffer, draws and the first frame;
                                   // lavapipe: renderer open, prepare and the first submit
  // softraster only: this method's last frame against lavapipe's (empty for lavapipe itself or
  // when either failed).
  std::optional<Comparison> agreement;
  std::uint64_t pixelsDiffering = 0;  // with agreement: pixels whose colour differs from lavapipe's at all (compare.hpp)
  double ratioVsLavapipe = 0;      // lavapipe median / this median (> 1: softraster faster); 0 when unknown
  std::string error;               // one line when this renderer failed (its numbers are then partial)
  bool ok() const { return error.empty(); }
};

struct BenchScene {
  std::filesystem::path scene;     // the scene file
  std::string description;
  std::uint32_t width = 0, height = 0, samples = 1;
  std::uint64_t pixels = 0;        // width * height
  std::uint64_t triangles = 0;     // triangles assembled by the draws (line and point topologies: 0)
  std::uint64_t bytesWritten = 0;  // colour + depth bytes of one frame: pixels * samples * (4 + depth bytes)
  double memoryLimitMilliseconds = 0;  // bytesWritten at the memset bandwidth from memory
  std::vector<BenchRun> runs;      // the methods in BenchOptions::methods' order, then lavapipe
};

struct BenchResults {
  BenchMachine machine;
  unsigned frames = 0, warmup = 0;
  unsigned threads = 0;            // the option as given (0 = every core)
  bool allowAvx512 = true;         // softraster's ContextOptions::allowAvx512 (--softraster-no-avx512: false)
  std::vector<BenchScene> scenes;  // in the order given
  // Whether every renderer ran and every method agrees with lavapipe within the scene's tolerance.
  bool allAgree() const;
};

// The CPU model, the core count and the memset bandwidth, from memory and cache-warm (medians of a few runs).
BenchMachine measureMachine();

// Fixes glibc malloc's mmap and trim thresholds at the values its dynamic rule ends at on 64-bit
// (32 MiB, and twice that), for the whole process, and says what it set; elsewhere (another C
// library, or AddressSanitizer's allocator in the sanitizer job), or if glibc refuses, leaves
// the allocator alone and says so. Why: glibc starts with a 128 KiB mmap threshold and raises it
// only when a larger mmapped block is freed, so a renderer that frees and allocates a large block
// every frame pays fresh pages (page faults) for it every frame until something else has freed a
// larger one. lavapipe's frame of scenes/bench/sphere_1m.json took 122-166 ms when the scene was
// benched alone and 37-48 ms after the other bench scenes.
std::string settleAllocator();

// Triangles a scene's draws assemble (triangle topologies only).
std::uint64_t triangleCount(const Scene& scene);

// Benchmarks every scene in turn (see the top of this file); `machine` gives memory_limit_ms.
BenchResults runBench(const std::vector<Scene>& scenes, const BenchOptions& options, const BenchMachine& machine);

}  // namespace crosscheck
