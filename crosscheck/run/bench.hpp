// The bench runner: steady-state frame times of softraster (each method) and of vkref on lavapipe
// for each scene, and how closely each method agrees with Vulkan. Per scene every renderer is made
// ready once (softraster: a SoftrasterScene, i.e. Context, framebuffer and draws; lavapipe: a
// Renderer opened and the frame prepared), then warm-up frames and timed frames are drawn with the
// renderers taking turns frame by frame (exact, exact-scalar, lavapipe, repeat), each frame timed
// with std::chrono::steady_clock. Setup (making ready plus the first frame) is timed apart. After
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

struct BenchOptions {
  unsigned frames = 15;  // timed frames per renderer (at least 1)
  unsigned warmup = 3;   // untimed frames per renderer before them
  // softraster's Context threads and lavapipe's LP_NUM_THREADS; 0 = every core. LP_NUM_THREADS is
  // set (setenv) before each Vulkan renderer is opened.
  unsigned threads = 0;
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;  // fmuladd and depth mode; method and threads are the bench's
  // Called after each scene (for progress): (its position, the number of scenes, its result).
  std::function<void(std::size_t, std::size_t, const BenchScene&)> onScene;
};

// The machine the numbers come from.
struct BenchMachine {
  std::string cpu;                 // "model name" of /proc/cpuinfo ("unknown" without it)
  unsigned cores = 0;              // std::thread::hardware_concurrency()
  double memsetGigabytesPerSecond = 0;  // median memset bandwidth over a 1080p RGBA8 + D32 buffer
};

// One renderer (or softraster method) on one scene.
struct BenchRun {
  std::string renderer;            // "softraster" or "lavapipe"
  std::string method;              // softraster: "exact" or "exact-scalar"; lavapipe: empty
  // Threads that draw: softraster's Context threads (exact-scalar draws on the calling thread
  // alone, so 1), lavapipe's LP_NUM_THREADS.
  unsigned threads = 0;
  std::vector<double> frameMilliseconds;  // the timed frames, in order
  double medianMilliseconds = 0, minMilliseconds = 0;
  double setupMilliseconds = 0;    // softraster: Context, framebuffer, draws and the first frame;
                                   // lavapipe: renderer open, prepare and the first submit
  // softraster only: this method's last frame against lavapipe's (empty for lavapipe itself or
  // when either failed).
  std::optional<Comparison> agreement;
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
  double memoryLimitMilliseconds = 0;  // bytesWritten at the memset bandwidth
  std::vector<BenchRun> runs;      // exact, exact-scalar, lavapipe
};

struct BenchResults {
  BenchMachine machine;
  unsigned frames = 0, warmup = 0;
  unsigned threads = 0;            // the option as given (0 = every core)
  std::vector<BenchScene> scenes;  // in the order given
  // Whether every renderer ran and every method agrees with lavapipe within the scene's tolerance.
  bool allAgree() const;
};

// The CPU model, the core count and the memset bandwidth (median of a few runs).
BenchMachine measureMachine();

// Triangles a scene's draws assemble (triangle topologies only).
std::uint64_t triangleCount(const Scene& scene);

// Benchmarks every scene in turn (see the top of this file); `machine` gives memory_limit_ms.
BenchResults runBench(const std::vector<Scene>& scenes, const BenchOptions& options, const BenchMachine& machine);

}  // namespace crosscheck
