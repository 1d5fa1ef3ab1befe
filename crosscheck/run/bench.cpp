// The bench runner (see bench.hpp): makes each renderer ready, alternates their frames, times
// them, and compares each softraster method's last frame with lavapipe's.
#include "run/bench.hpp"

#include "compare/compare.hpp"
#include "render/render.hpp"
#include "run/timing.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace crosscheck {
namespace {

using timing::Clock;
using timing::millisecondsSince;
using timing::median;

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string model = line.substr(colon + 1);
    model.erase(0, model.find_first_not_of(" \t"));
    return model;
  }
  return "unknown";
}

unsigned coreCount() { return std::max(1u, std::thread::hardware_concurrency()); }

// Keeps the stores into `p` from being optimised away (the memsets below are timed or needed).
void storesMustHappen([[maybe_unused]] const void* p) {
#if defined(__GNUC__)
  asm volatile("" : : "r"(p) : "memory");
#endif
}

// Bandwidth of memset over a buffer the size of a 1080p RGBA8 colour plus D32 depth image, median
// of 7 runs: from memory (each run after writing kEvictBytes elsewhere, so the buffer is in no
// cache; a frame in the bench finds much of its framebuffer out of cache, the other renderer's
// frame having run in between, though part may remain), and cache-warm (the runs back to back).
// The warm figure is the last-level cache's speed wherever the buffer fits in it: on the 2-core
// EPYC this was built on, 38-76 GB/s warm against 16-24 from memory (where a 256 or 512 MB memset
// also runs at 19-23).
struct MemsetBandwidth {
  double fromMemory = 0, warm = 0;  // GB/s
};
MemsetBandwidth memsetBandwidth() {
  constexpr std::size_t kEvictBytes = std::size_t{256} << 20;  // several times any last-level cache per core
  constexpr int kRuns = 7;
  const std::size_t bytes = std::size_t{1920} * 1080 * (4 + 4);
  std::vector<unsigned char> buffer(bytes, 1);  // touched, so the timed runs do not page-fault
  std::vector<unsigned char> evict(kEvictBytes, 1);
  const auto timedMemset = [&](int value) {
    const auto start = Clock::now();
    std::memset(buffer.data(), value, bytes);
    storesMustHappen(buffer.data());
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  const auto gigabytesPerSecond = [bytes](const std::vector<double>& seconds) {
    const double s = median(seconds);
    return s > 0 ? static_cast<double>(bytes) / s / 1e9 : 0;
  };
  std::vector<double> cold, warm;
  for (int run = 0; run < kRuns; ++run) {
    std::memset(evict.data(), run, evict.size());
    storesMustHappen(evict.data());
    cold.push_back(timedMemset(run));
  }
  for (int run = 0; run < kRuns; ++run) warm.push_back(timedMemset(run));
  return {gigabytesPerSecond(cold), gigabytesPerSecond(warm)};
}

std::uint64_t depthBytes(softraster::DepthFormat format) {
  return format == softraster::DepthFormat::D16Unorm ? 2 : 4;
}

// One renderer being benchmarked: made ready (timed as setup with its first frame), then frames.
class Contender {
 public:
  virtual ~Contender() = default;
  virtual softraster::Status frame() = 0;
  virtual softraster::Result<Frame> read() = 0;
  BenchRun run;
};

class SoftrasterContender : public Contender {
 public:
  SoftrasterContender(const Scene& scene, const softraster::ContextOptions& options) : prepared_(scene, options) {}
  softraster::Status frame() override { return prepared_.render(); }
  softraster::Result<Frame> read() override { return prepared_.frame(); }
  unsigned threads() const { return prepared_.threads(); }

 private:
  SoftrasterScene prepared_;
};

class LavapipeContender : public Contender {
 public:
  LavapipeContender(const Scene& scene, std::unique_ptr<vkref::Renderer> renderer, vkref::PreparedFrame prepared)
      : scene_(scene), renderer_(std::move(renderer)), prepared_(std::move(prepared)) {}
  ~LavapipeContender() override { prepared_ = vkref::PreparedFrame(); }  // before its renderer
  softraster::Status frame() override {
    const softraster::Status status = renderer_->submit(prepared_);
    return status.prefixed("vulkan");
  }
  softraster::Result<Frame> read() override { return readVulkan(scene_, *renderer_, prepared_); }

 private:
  const Scene& scene_;
  std::unique_ptr<vkref::Renderer> renderer_;
  vkref::PreparedFrame prepared_;
};

std::unique_ptr<Contender> makeSoftraster(const Scene& scene, const BenchOptions& options, const BenchMethod& which) {
  const softraster::Method method = which.method;
  softraster::ContextOptions context = options.softraster;
  context.method = method;
  context.affineVaryings = which.affineVaryings;
  context.threads = options.threads;
  const auto start = Clock::now();
  auto contender = std::make_unique<SoftrasterContender>(scene, context);
  const softraster::Status first = contender->frame();
  contender->run.setupMilliseconds = millisecondsSince(start);
  contender->run.renderer = "softraster";
  contender->run.method = softraster::methodName(method);
  contender->run.affineVaryings = which.affineVaryings;
  // The scalar and course methods draw on the calling thread alone, whatever the Context's thread count.
  contender->run.threads = method == softraster::Method::Exact ? contender->threads() : 1;
  if (!first) contender->run.error = first.message();
  return contender;
}

std::unique_ptr<Contender> makeLavapipe(const Scene& scene, const BenchOptions& options) {
  BenchRun run;
  run.renderer = "lavapipe";
  run.threads = options.threads != 0 ? options.threads : coreCount();
  // lavapipe reads LP_NUM_THREADS when its device is created.
  setenv("LP_NUM_THREADS", std::to_string(run.threads).c_str(), 1);
  const auto start = Clock::now();
  auto opened = openVulkan(options.device);
  auto failed = [&](const softraster::Status& status) {
    auto contender = std::make_unique<LavapipeContender>(scene, nullptr, vkref::PreparedFrame());
    contender->run = run;
    contender->run.error = status.message();
    return contender;
  };
  if (!opened) return failed(opened.status().prefixed("vulkan"));
  auto prepared = prepareVulkan(scene, **opened);
  if (!prepared) return failed(prepared.status());
  auto contender = std::make_unique<LavapipeContender>(scene, std::move(*opened), std::move(*prepared));
  const softraster::Status first = contender->frame();
  run.setupMilliseconds = millisecondsSince(start);
  contender->run = run;
  if (!first) contender->run.error = first.message();
  return contender;
}

BenchScene benchScene(const Scene& scene, const BenchOptions& options, const BenchMachine& machine) {
  BenchScene out;
  out.scene = scene.path;
  out.description = scene.description;
  out.width = scene.width;
  out.height = scene.height;
  out.samples = scene.samples;
  out.pixels = std::uint64_t{scene.width} * scene.height;
  out.triangles = triangleCount(scene);
  out.bytesWritten = out.pixels * scene.samples * (4 + depthBytes(scene.depthFormat));
  if (machine.memsetGigabytesPerSecond > 0) {
    out.memoryLimitMilliseconds = static_cast<double>(out.bytesWritten) / (machine.memsetGigabytesPerSecond * 1e9) * 1e3;
  }

  std::vector<std::unique_ptr<Contender>> contenders;
  for (const BenchMethod& method : options.methods) contenders.push_back(makeSoftraster(scene, options, method));
  contenders.push_back(makeLavapipe(scene, options));

  // Frame by frame in turn, so that a noisy spell of the machine hits every renderer alike.
  for (unsigned i = 0; i < options.warmup + options.frames; ++i) {
    for (auto& contender : contenders) {
      if (!contender->run.ok()) continue;
      const auto start = Clock::now();
      const softraster::Status status = contender->frame();
      const double milliseconds = millisecondsSince(start);
      if (!status) {
        contender->run.error = status.message();
        continue;
      }
      if (i >= options.warmup) contender->run.frameMilliseconds.push_back(milliseconds);
    }
  }
  for (auto& contender : contenders) {
    BenchRun& run = contender->run;
    run.medianMilliseconds = median(run.frameMilliseconds);
    if (!run.frameMilliseconds.empty()) {
      run.minMilliseconds = *std::min_element(run.frameMilliseconds.begin(), run.frameMilliseconds.end());
    }
  }

  // Agreement of each method's last frame with lavapipe's.
  Contender& lavapipe = *contenders.back();
  std::optional<Frame> reference;
  if (lavapipe.run.ok()) {
    auto read = lavapipe.read();
    if (read) {
      reference = std::move(*read);
    } else {
      lavapipe.run.error = read.error();
    }
  }
  for (std::size_t i = 0; i + 1 < contenders.size(); ++i) {
    BenchRun& run = contenders[i]->run;
    if (lavapipe.run.ok() && run.ok() && run.medianMilliseconds > 0) {
      run.ratioVsLavapipe = lavapipe.run.medianMilliseconds / run.medianMilliseconds;
    }
    if (!run.ok() || !reference) continue;
    auto frame = contenders[i]->read();
    if (!frame) {
      run.error = frame.error();
      continue;
    }
    run.agreement = compareFrames(*frame, *reference, scene);
    run.pixelsDiffering = colourDifferingPixels(*frame, *reference);
  }
  if (lavapipe.run.ok()) lavapipe.run.ratioVsLavapipe = 1;
  for (auto& contender : contenders) out.runs.push_back(std::move(contender->run));
  return out;
}

}  // namespace

std::string BenchMethod::label() const {
  return std::string(softraster::methodName(method)) + (affineVaryings ? "+affine" : "");
}

std::optional<std::vector<BenchMethod>> parseBenchMethods(const std::string& text) {
  std::vector<BenchMethod> methods;
  if (text == "all") {
    for (softraster::Method m : softraster::kMethods) methods.push_back({m});
    return methods;
  }
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    BenchMethod method;
    constexpr std::string_view kAffine = "+affine";
    if (item.size() > kAffine.size() && item.compare(item.size() - kAffine.size(), kAffine.size(), kAffine) == 0) {
      method.affineVaryings = true;
      item.resize(item.size() - kAffine.size());
    }
    const auto parsed = softraster::methodFromName(item);
    if (!parsed || (method.affineVaryings && !softraster::isCourseMethod(*parsed))) return std::nullopt;
    method.method = *parsed;
    if (std::find(methods.begin(), methods.end(), method) == methods.end()) methods.push_back(method);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return methods;
}

bool BenchResults::allAgree() const {
  for (const BenchScene& scene : scenes) {
    for (const BenchRun& run : scene.runs) {
      if (!run.ok()) return false;
      if (run.renderer == "softraster" && (!run.agreement || !run.agreement->passed())) return false;
    }
  }
  return true;
}

BenchMachine measureMachine() {
  BenchMachine machine;
  machine.cpu = cpuModel();
  machine.cores = coreCount();
  const MemsetBandwidth memset = memsetBandwidth();
  machine.memsetGigabytesPerSecond = memset.fromMemory;
  machine.memsetWarmGigabytesPerSecond = memset.warm;
  return machine;
}

std::string settleAllocator() {
#if defined(__SANITIZE_ADDRESS__)
  return "AddressSanitizer's allocator: its own (mallopt does not reach it)";
#elif defined(__GLIBC__)
  constexpr int kMebibyte = 1 << 20;
  constexpr int kMmapThreshold = 32 * kMebibyte, kTrimThreshold = 2 * kMmapThreshold;
  if (mallopt(M_MMAP_THRESHOLD, kMmapThreshold) == 1 && mallopt(M_TRIM_THRESHOLD, kTrimThreshold) == 1) {
    return "glibc: mmap threshold " + std::to_string(kMmapThreshold / kMebibyte) + " MiB, trim threshold " +
           std::to_string(kTrimThreshold / kMebibyte) + " MiB";
  }
  return "glibc: its defaults (mallopt refused the thresholds)";
#else
  return "not glibc: the allocator's defaults";
#endif
}

std::uint64_t triangleCount(const Scene& scene) {
  using softraster::Topology;
  std::uint64_t triangles = 0;
  for (const Draw& draw : scene.draws) {
    const std::uint64_t n = draw.indexed ? draw.indices.size() : draw.mesh.vertexCount();
    switch (draw.state.topology) {
      case Topology::TriangleList: triangles += n / 3; break;
      case Topology::TriangleStrip:
      case Topology::TriangleFan: triangles += n >= 3 ? n - 2 : 0; break;
      default: break;
    }
  }
  return triangles;
}

BenchResults runBench(const std::vector<Scene>& scenes, const BenchOptions& options, const BenchMachine& machine) {
  BenchResults results;
  results.machine = machine;
  results.machine.allocator = settleAllocator();
  results.frames = options.frames;
  results.warmup = options.warmup;
  results.threads = options.threads;
  results.allowAvx512 = options.softraster.allowAvx512;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    results.scenes.push_back(benchScene(scenes[i], options, machine));
    if (options.onScene) options.onScene(i, scenes.size(), results.scenes.back());
  }
  return results;
}

}  // namespace crosscheck
