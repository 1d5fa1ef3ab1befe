// The conformance runner: renders every scene of a suite with softraster and with Vulkan
// (lavapipe), compares them within the scene's tolerance and gives each scene an Outcome.
// Scenes run on `jobs` threads, each with its own vkref::Renderer; results come back in suite
// order whatever order they finished in. A scene that cannot be loaded, a renderer that returns
// an error, a validation message (with validation on) or an exception becomes Crash with one
// line of error, and the run goes on.
// Deliberately in-process: a renderer that crashes the process (a signal) ends the run; there is
// no subprocess isolation, no retry and no timeout per scene.
#pragma once

#include "compare/compare.hpp"
#include "run/expectations.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"
#include "run/outcome.hpp"
#include "run/suite.hpp"

#include <softraster/pipeline.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace crosscheck {

struct SceneImage {
  std::string kind;             // "soft", "vulkan", "diff", "soft.depth", "vulkan.depth", "depth.diff"
  std::filesystem::path file;   // relative to SceneResult::imageRoot
};

struct SceneResult {
  SceneEntry entry;
  Outcome outcome = Outcome::Crash;
  Outcome actual = Outcome::Crash;            // before expectations: Pass, Fail, Crash (or Skip)
  std::optional<Expectation> expectation;   // from the expectations file, if listed
  std::string error;                        // Crash: one line

  // Known once the scene loaded.
  bool loaded = false;
  std::string description;
  std::uint32_t width = 0, height = 0;
  Tolerance tolerance;

  std::optional<Comparison> comparison;     // known once both renderers produced a frame
  double softMilliseconds = 0, vulkanMilliseconds = 0;  // the render calls themselves
  double milliseconds = 0;                  // the whole scene: load, render, compare, write

  std::filesystem::path imageRoot;          // where images were written (empty: none)
  std::vector<SceneImage> images;
  std::filesystem::path pixelData;          // relative to imageRoot: the report's value readout data
  std::pair<float, float> depthViewRange{0, 0};  // depth mapped to black..white in the depth views
};

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

std::vector<SceneResult> runConformance(const std::vector<SceneEntry>& suite, const ConformanceOptions& options);

// Pass and ExpectedFail count as passed; Fail, Crash and UnexpectedPass as failed; Skip as skipped.
struct Counts {
  std::size_t passed = 0, failed = 0, skipped = 0;
  std::size_t byOutcome[6] = {};
  std::size_t of(Outcome s) const { return byOutcome[static_cast<int>(s)]; }
};

Counts countResults(const std::vector<SceneResult>& results);

// "N passed, N failed", plus ", N skipped" when some were.
std::string countsLine(const Counts& counts);

}  // namespace crosscheck
