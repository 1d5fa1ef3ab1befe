// The conformance runner: renders every scene of a suite with softraster and with Vulkan
// (lavapipe), compares them within the scene's tolerance and gives each scene an Outcome.
// Scenes run on `jobs` threads, each with its own vkref::Renderer; results come back in suite
// order whatever order they finished in. A scene that cannot be loaded, a renderer that returns
// an error, a validation message (with validation on) or an exception becomes Crash with one
// line of error, and the run goes on.
// Its scenes' records are RunResults::scenes (results/results.hpp).
// Deliberately in-process: a renderer that crashes the process (a signal) ends the run; there is
// no subprocess isolation, no retry and no timeout per scene.
#pragma once

#include "render/render.hpp"
#include "results/results.hpp"
#include "run/expectations.hpp"
#include "run/suite.hpp"
#include "scene/scene.hpp"

#include <softraster/pipeline.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstddef>
#include <functional>
#include <vector>

namespace crosscheck {

// What one scene's frames are handed to, on the worker thread, before they are dropped (to write
// images or report data). An error makes the scene Crash with that line.
using FrameSink = std::function<softraster::Status(SceneResult& result, const Scene& scene, const Frame& soft,
                                                   const Frame& vulkan)>;

struct ConformanceOptions {
  unsigned jobs = 1;
  const Expectations* expectations = nullptr;
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
  FrameSink onFrames;
  // Called once per finished scene, under the runner's lock, in the order scenes finish:
  // (position in the suite, its result, scenes finished so far). The reference stays valid until
  // runConformance returns.
  std::function<void(std::size_t position, const SceneResult& result, std::size_t done)> onFinished;
  // The softraster renderer; empty means renderSoftraster with `softraster`. Tests replace it.
  std::function<softraster::Result<Frame>(const Scene&)> renderSoft;
};

// One SceneResult per scene of `suite`, in suite order (RunResults::scenes).
std::vector<SceneResult> runConformance(const std::vector<SceneEntry>& suite, const ConformanceOptions& options);

}  // namespace crosscheck
