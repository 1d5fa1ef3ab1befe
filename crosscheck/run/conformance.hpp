// The conformance runner: renders every scene of a suite with softraster and with Vulkan
// (lavapipe), compares them within the scene's tolerance and gives each scene an Outcome.
// Scenes run in `jobs` worker processes (run/worker_processes.hpp), each with its own
// vkref::Renderer and softraster Context; results come back in suite order whatever order they
// finished in. A scene that cannot be loaded, a renderer that returns an error, a validation
// message (with validation on) or an exception becomes Crash with one line of error; so does a
// worker that dies under a scene (a signal, an abort, an allocation over the memory limit), and
// a scene with no result within the timeout is Timeout (its worker is killed). The run goes on
// with a new worker.
// Isolation::Threads runs the same scenes on threads of the calling process instead, for tests
// that watch a renderer from the caller: no timeout, no memory limit, and a crash ends it all.
// Its scenes' records are RunResults::scenes (results/results.hpp), each with the wall time of
// its steps (SceneTimings: load, each renderer, compare, the FrameSink's images).
// Deliberately no retry: a scene that crashed once is a Crash, not a flake to run again.
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
#include <string>
#include <vector>

namespace crosscheck {

// What one scene's frames are handed to, in the worker, before they are dropped (to write images
// or report data; what it records in the SceneResult travels back with it). An error makes the
// scene Crash with that line.
using FrameSink = std::function<softraster::Status(SceneResult& result, const Scene& scene, const Frame& soft,
                                                   const Frame& vulkan)>;

enum class Isolation { Processes, Threads };

// Each worker's address space by default, in MB: far above what any scene needs (an 8192x8192
// 4x MSAA frame needs about 7 GB, both renderers together), low enough that a runaway
// allocation fails at once instead of swapping.
inline constexpr std::size_t kDefaultMemoryLimitMegabytes = 16384;

struct ConformanceOptions {
  unsigned jobs = 1;                           // at most; jobsFor says how many run
  std::vector<std::string> overrides;          // --set assignments applied to every scene (loadScene)
  Isolation isolation = Isolation::Processes;
  double timeoutSeconds = 0;                   // per scene (Processes only); 0: none
  std::size_t memoryLimitMegabytes = kDefaultMemoryLimitMegabytes;  // per worker (Processes only); 0: none
  const Expectations* expectations = nullptr;
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
  FrameSink onFrames;
  // The report's chart: after the comparison (and onFrames), draw the scene with every variant of
  // run/variants.hpp, this many timed frames each, into SceneResult::variants; 0: not drawn.
  // Scenes of a folder named "stability" also count hits (cracks, double hits).
  unsigned chartFrames = 0;
  // Called once per finished scene, in the calling process (under the runner's lock with
  // Threads), in the order scenes finish: (position in the suite, its result, scenes finished so
  // far). The reference stays valid until runConformance returns.
  std::function<void(std::size_t position, const SceneResult& result, std::size_t done)> onFinished;
  // A worker's problem that is no scene's (it exited abnormally after its last scene: a
  // sanitizer's leak report, say), one line; may be empty (then it is not reported).
  std::function<void(const std::string& error)> onWorkerError;
  // The softraster renderer, called in the worker; empty means renderSoftraster with
  // `softraster`. Tests replace it.
  std::function<softraster::Result<Frame>(const Scene&)> renderSoft;
};

// One SceneResult per scene of `suite`, in suite order (RunResults::scenes). With Processes the
// calling process must have no other threads and no Vulkan renderer open (workers are forked).
std::vector<SceneResult> runConformance(const std::vector<SceneEntry>& suite, const ConformanceOptions& options);

// How many jobs runConformance uses for `suite`: options.jobs, but no more than the scenes that
// run (those the expectations do not skip), and at least one.
std::size_t jobsFor(const std::vector<SceneEntry>& suite, const ConformanceOptions& options);

}  // namespace crosscheck
