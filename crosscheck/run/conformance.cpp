// The conformance runner (see conformance.hpp).
#include "run/conformance.hpp"

#include "compare/compare.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

namespace crosscheck {
namespace {

using Clock = std::chrono::steady_clock;

// One worker's Vulkan renderer, opened when the worker starts (so no scene's time includes it);
// a failure to open is remembered, and every scene of this worker reports it.
struct VulkanSlot {
  std::optional<softraster::Result<std::unique_ptr<vkref::Renderer>>> opened;

  const softraster::Result<std::unique_ptr<vkref::Renderer>>& get(const vkref::DeviceOptions& options) {
    if (!opened) opened = openVulkan(options);
    return *opened;
  }
};

// Renders and compares one scene; returns Pass, Fail or Crash (with result.error set).
Outcome runScene(SceneResult& result, const ConformanceOptions& options, VulkanSlot& vulkan) {
  const auto crash = [&](std::string message) {
    result.error = std::move(message);
    return Outcome::Crash;
  };
  const auto scene = loadScene(result.entry.path);
  if (!scene) return crash(scene.error());
  result.loaded = true;
  result.description = scene->description;
  result.width = scene->width;
  result.height = scene->height;
  result.tolerance = scene->tolerance;

  const auto soft = options.renderSoft ? options.renderSoft(*scene) : renderSoftraster(*scene, options.softraster);
  if (!soft) return crash(soft.error());
  result.softMilliseconds = soft->milliseconds;

  const auto& opened = vulkan.get(options.device);
  if (!opened) return crash("vulkan: " + opened.error());
  vkref::Renderer* renderer = opened->get();
  const std::size_t messagesBefore = options.device.validation ? renderer->validationMessages().size() : 0;
  const auto reference = renderVulkan(*scene, *renderer);
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

  result.comparison = compareFrames(*soft, *reference, *scene);
  if (options.onFrames) {
    if (const softraster::Status written = options.onFrames(result, *scene, *soft, *reference); !written) {
      return crash(written.message());
    }
  }
  return result.comparison->passed() ? Outcome::Pass : Outcome::Fail;
}

SceneResult runOne(const SceneEntry& entry, const ConformanceOptions& options, VulkanSlot& vulkan) {
  const auto start = Clock::now();
  SceneResult result;
  result.entry = entry;
  const Expectation* expected = options.expectations ? options.expectations->find(entry.name) : nullptr;
  if (expected) result.expectation = *expected;
  if (expected && expected->outcome == Outcome::Skip) {
    result.actual = result.outcome = Outcome::Skip;
    return result;
  }
  try {
    result.actual = runScene(result, options, vulkan);
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
  result.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  return result;
}

}  // namespace

std::vector<SceneResult> runConformance(const std::vector<SceneEntry>& suite, const ConformanceOptions& options) {
  std::vector<SceneResult> results(suite.size());
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  std::size_t done = 0;
  const std::size_t jobs = std::clamp<std::size_t>(options.jobs, 1, std::max<std::size_t>(suite.size(), 1));
  // The thread rule (docs/architecture.md): N jobs share the cores, so each job's softraster
  // Context draws with cores / N threads (at least one) unless a count was asked for.
  ConformanceOptions perJob = options;
  if (perJob.softraster.threads == 0) {
    const std::size_t cores = std::max(1u, std::thread::hardware_concurrency());
    perJob.softraster.threads = static_cast<unsigned>(std::max<std::size_t>(1, cores / jobs));
  }
  const auto worker = [&] {
    VulkanSlot vulkan;
    vulkan.get(options.device);  // a failure is reported per scene
    for (std::size_t i = next++; i < suite.size(); i = next++) {
      SceneResult result = runOne(suite[i], perJob, vulkan);
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

}  // namespace crosscheck
