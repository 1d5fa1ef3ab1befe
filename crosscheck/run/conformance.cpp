// The conformance runner (see conformance.hpp): one scene's run (runOne), and the two ways of
// running a suite, in worker processes (run/worker_processes.hpp; each scene's SceneResult comes
// back as CBOR of results/results_json.hpp's JSON) or on threads of this process. A known
// deviation's scene (run/deviations.hpp) is drawn once more with the spec's behaviour and the
// pixels that changes are counted.
#include "run/conformance.hpp"

#include "compare/compare.hpp"
#include "results/results_json.hpp"
#include "run/deviations.hpp"
#include "run/variants.hpp"
#include "run/worker_processes.hpp"
#include "run/timing.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <thread>

namespace crosscheck {
namespace {

using timing::Clock;

// One worker's Vulkan renderer, opened when the worker starts (so no scene's time includes it);
// a failure to open is remembered, and every scene of this worker reports it.
struct VulkanSlot {
  std::optional<softraster::Result<std::unique_ptr<vkref::Renderer>>> opened;

  const softraster::Result<std::unique_ptr<vkref::Renderer>>& get(const vkref::DeviceOptions& options) {
    if (!opened) opened = openVulkan(options);
    return *opened;
  }
};

using timing::millisecondsSince;

// Renders and compares one scene; returns Pass, Fail or Crash (with result.error set). Each step's
// wall time goes into result.timings as it ends, so a step that fails is timed too.
Outcome runScene(SceneResult& result, const ConformanceOptions& options, VulkanSlot& vulkan) {
  const auto crash = [&](std::string message) {
    result.error = std::move(message);
    return Outcome::Crash;
  };
  auto step = Clock::now();
  const auto scene = loadScene(result.entry.path, options.overrides);
  result.timings.load = millisecondsSince(step);
  if (!scene) return crash(scene.error());
  result.loaded = true;
  result.stabilityCase = isStabilityCase(result.entry);
  result.description = scene->description;
  result.width = scene->width;
  result.height = scene->height;
  result.tolerance = scene->tolerance;

  step = Clock::now();
  const auto soft = options.renderSoft ? options.renderSoft(*scene) : renderSoftraster(*scene, options.softraster);
  result.timings.soft = millisecondsSince(step);
  if (!soft) return crash(soft.error());
  result.softMilliseconds = soft->milliseconds;

  const auto& opened = vulkan.get(options.device);
  if (!opened) return crash("vulkan: " + opened.error());
  vkref::Renderer* renderer = opened->get();
  const std::size_t messagesBefore = options.device.validation ? renderer->validationMessages().size() : 0;
  step = Clock::now();
  const auto reference = renderVulkan(*scene, *renderer);
  result.timings.vulkan = millisecondsSince(step);
  if (!reference) return crash(reference.error());
  result.vulkanMilliseconds = reference->milliseconds;
  if (options.device.validation) {
    const auto messages = renderer->validationMessages();
    if (messages.size() > messagesBefore) {
      const std::size_t more = messages.size() - messagesBefore - 1;
      return crash("vulkan validation: " + messages[messagesBefore] +
                   (more ? " (and " + std::to_string(more) + " more)" : ""));
    }
  }

  step = Clock::now();
  result.comparison = compareFrames(*soft, *reference, *scene);
  result.timings.compare = millisecondsSince(step);
  if (options.onFrames) {
    step = Clock::now();
    const softraster::Status written = options.onFrames(result, *scene, *soft, *reference);
    result.timings.images = millisecondsSince(step);
    if (!written) return crash(written.message());
  }
  if (deviationShownBy(result.entry.name) && options.softraster.deviations == softraster::Deviations::Driver &&
      !options.renderSoft) {
    // A known deviation's scene: how many pixels the spec's behaviour changes against lavapipe.
    softraster::ContextOptions spec = options.softraster;
    spec.deviations = softraster::Deviations::Spec;
    const auto specFrame = renderSoftraster(*scene, spec);
    if (!specFrame) return crash("spec mode: " + specFrame.error());
    std::uint64_t differing = 0;
    for (std::size_t i = 0; i + 3 < specFrame->rgba.size() && i + 3 < reference->rgba.size(); i += 4) {
      differing += std::memcmp(&specFrame->rgba[i], &reference->rgba[i], 4) != 0;
    }
    result.specDeviationPixels = differing;
  }
  if (options.chartFrames > 0) {
    step = Clock::now();
    VariantOptions chart;
    chart.frames = options.chartFrames;
    chart.countHits = result.stabilityCase;
    result.variants = runVariants(*scene, chartVariants(options.softraster), *renderer, chart);
    result.timings.variants = millisecondsSince(step);
  }
  return result.comparison->passed() ? Outcome::Pass : Outcome::Fail;
}

const Expectation* expectationOf(const SceneEntry& entry, const ConformanceOptions& options) {
  return options.expectations ? options.expectations->find(entry.name) : nullptr;
}

bool isSkipped(const SceneEntry& entry, const ConformanceOptions& options) {
  const Expectation* expected = expectationOf(entry, options);
  return expected && expected->outcome == Outcome::Skip;
}

// A scene that did not produce a result of its own (Skip, or a worker that crashed or timed out).
SceneResult resultWithout(const SceneEntry& entry, const ConformanceOptions& options, Outcome actual, std::string error,
                          double milliseconds) {
  SceneResult result;
  result.entry = entry;
  const Expectation* expected = expectationOf(entry, options);
  if (expected) result.expectation = *expected;
  result.actual = actual;
  result.error = std::move(error);
  std::replace(result.error.begin(), result.error.end(), '\n', ' ');
  result.outcome = applyExpectation(actual, expected);
  result.milliseconds = milliseconds;
  return result;
}

// Runs one scene (or skips it). *outOfMemory is set when an allocation failed: the process's
// state may be spoiled, so a worker ends after such a scene.
SceneResult runOne(const SceneEntry& entry, const ConformanceOptions& options, VulkanSlot& vulkan, bool* outOfMemory) {
  const auto start = Clock::now();
  SceneResult result;
  result.entry = entry;
  const Expectation* expected = expectationOf(entry, options);
  if (expected) result.expectation = *expected;
  if (expected && expected->outcome == Outcome::Skip) {
    result.actual = result.outcome = Outcome::Skip;
    return result;
  }
  try {
    result.actual = runScene(result, options, vulkan);
  } catch (const std::bad_alloc&) {
    result.error = options.memoryLimitMegabytes && workerMemoryLimitWorks() && options.isolation == Isolation::Processes
                       ? "out of memory: over the worker's memory limit of " +
                             std::to_string(options.memoryLimitMegabytes) + " MB (--memory-limit)"
                       : std::string("out of memory (std::bad_alloc)");
    result.actual = Outcome::Crash;
    *outOfMemory = true;
  } catch (const std::exception& e) {
    result.error = std::string("exception: ") + e.what();
    result.actual = Outcome::Crash;
  } catch (...) {
    result.error = "exception of unknown type";
    result.actual = Outcome::Crash;
  }
  // An error message is one line.
  std::replace(result.error.begin(), result.error.end(), '\n', ' ');
  result.outcome = applyExpectation(result.actual, expected);
  result.milliseconds = millisecondsSince(start);
  return result;
}

// The thread rule (docs/architecture.md): N jobs share the cores, so each job's softraster
// Context draws with cores / N threads (at least one) unless a count was asked for.
ConformanceOptions perJobOptions(const ConformanceOptions& options, std::size_t jobs) {
  ConformanceOptions perJob = options;
  if (perJob.softraster.threads == 0) {
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    perJob.softraster.threads = static_cast<unsigned>(std::max<std::size_t>(1, cores / jobs));
  }
  return perJob;
}

std::vector<SceneResult> runOnThreads(const std::vector<SceneEntry>& suite, const ConformanceOptions& options) {
  std::vector<SceneResult> results(suite.size());
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::size_t done = 0;
  const std::size_t jobs = jobsFor(suite, options);
  const ConformanceOptions perJob = perJobOptions(options, jobs);
  const auto worker = [&] {
    VulkanSlot vulkan;
    vulkan.get(options.device);  // a failure is reported per scene
    for (std::size_t i = next++; i < suite.size(); i = next++) {
      bool outOfMemory = false;
      SceneResult result = runOne(suite[i], perJob, vulkan, &outOfMemory);
      const std::lock_guard guard(lock);
      results[i] = std::move(result);
      ++done;
      if (options.onFinished) options.onFinished(i, results[i], done);
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (std::size_t t = 1; t < jobs; ++t) helpers.emplace_back(worker);
    worker();
  }  // joins the helpers
  return results;
}

std::vector<SceneResult> runInProcesses(const std::vector<SceneEntry>& suite, const ConformanceOptions& options) {
  std::vector<SceneResult> results(suite.size());
  std::size_t done = 0;
  const auto finished = [&](std::size_t i, SceneResult result) {
    results[i] = std::move(result);
    ++done;
    if (options.onFinished) options.onFinished(i, results[i], done);
  };
  // Skipped scenes never reach a worker.
  std::vector<std::size_t> toRun;
  for (std::size_t i = 0; i < suite.size(); ++i) {
    if (isSkipped(suite[i], options)) {
      finished(i, resultWithout(suite[i], options, Outcome::Skip, "", 0));
    } else {
      toRun.push_back(i);
    }
  }
  const std::size_t jobs = jobsFor(suite, options);
  const ConformanceOptions perJob = perJobOptions(options, jobs);

  // In a worker: its own Vulkan renderer (and, in runScene, its own softraster Context).
  std::unique_ptr<VulkanSlot> vulkan;
  WorkerProgram program;
  program.start = [&] {
    vulkan = std::make_unique<VulkanSlot>();
    vulkan->get(perJob.device);  // a failure is reported per scene
  };
  program.run = [&](std::size_t i, bool* endWorker) {
    const SceneResult result = runOne(suite[i], perJob, *vulkan, endWorker);
    const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(sceneResultToJson(result));
    return std::string(bytes.begin(), bytes.end());
  };
  program.finish = [&] { vulkan.reset(); };

  WorkerLimits limits;
  limits.timeoutSeconds = options.timeoutSeconds;
  limits.memoryLimitMegabytes = options.memoryLimitMegabytes;
  const auto onEnd = [&](std::size_t i, TaskEnd end) {
    switch (end.kind) {
      case TaskEnd::Kind::Replied: {
        softraster::Result<SceneResult> result = softraster::Status::error("results JSON: not CBOR");
        try {
          result = sceneResultFromJson(nlohmann::json::from_cbor(end.reply));
        } catch (const nlohmann::json::exception& e) {
          result = softraster::Status::error(std::string("results JSON: ") + e.what());
        }
        if (result) {
          result->entry = suite[i];  // the parent's own, byte for byte
          finished(i, std::move(*result));
        } else {
          finished(i, resultWithout(suite[i], options, Outcome::Crash,
                                    "worker sent a result that cannot be read: " + result.error(), end.milliseconds));
        }
        break;
      }
      case TaskEnd::Kind::Crashed:
        finished(i, resultWithout(suite[i], options, Outcome::Crash, end.error, end.milliseconds));
        break;
      case TaskEnd::Kind::TimedOut:
        finished(i, resultWithout(suite[i], options, Outcome::Timeout, end.error + " (--timeout)", end.milliseconds));
        break;
    }
  };
  runInWorkerProcesses(toRun, static_cast<unsigned>(jobs), limits, program, onEnd, options.onWorkerError);
  return results;
}

}  // namespace

std::size_t jobsFor(const std::vector<SceneEntry>& suite, const ConformanceOptions& options) {
  const auto running = static_cast<std::size_t>(
      std::count_if(suite.begin(), suite.end(), [&](const SceneEntry& entry) { return !isSkipped(entry, options); }));
  return std::clamp<std::size_t>(options.jobs, 1, std::max<std::size_t>(running, 1));
}

std::vector<SceneResult> runConformance(const std::vector<SceneEntry>& suite, const ConformanceOptions& options) {
  return options.isolation == Isolation::Processes ? runInProcesses(suite, options) : runOnThreads(suite, options);
}

}  // namespace crosscheck
