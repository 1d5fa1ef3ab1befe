// RunResults: the one record of a run, and the only thing the writers in output/ read (the text
// summary, the compare command's text and JSON, JUnit, the HTML report). One SceneResult per
// scene, in suite order: its outcome, the metrics and the limits they were held to, timings,
// the images written and the error line; plus what describes the run as a whole.
// The runner (run/conformance.hpp) and the compare command fill it; the images and pixel data
// are written while the frames still exist (output/artifacts.hpp, output/report/) and only their
// paths are kept here.
// Deliberately data only: no frames, no scenes, no formatting (output/ does that), so a record
// can be written as results.json (results_file.hpp), read back and merged across shards
// (merge.hpp).
#pragma once

#include "compare/metrics.hpp"
#include "run/expectations.hpp"
#include "run/outcome.hpp"
#include "results/variant_results.hpp"
#include "run/suite.hpp"
#include "scene/tolerance.hpp"

#include <cstddef>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace crosscheck {

struct SceneImage {
  std::string kind;             // "soft", "vulkan", "diff", "soft.depth", "vulkan.depth", "depth.diff",
                                // with stencil "soft.stencil", "vulkan.stencil", "stencil.diff",
                                // with MSAA per sample S "soft.sampleS", "vulkan.sampleS", "sampleS.diff"
  std::filesystem::path file;   // relative to SceneResult::imageRoot
};

// Where a scene's wall time went, in milliseconds, as the runner measured it: loading the scene
// (and its OBJs), each renderer's whole call (softraster: framebuffer, vertices, draws, resolve;
// Vulkan: prepare, submit, read-back), comparing the frames and writing its images and pixel
// data. SceneResult::milliseconds is these plus what surrounds them.
struct SceneTimings {
  double load = 0, soft = 0, vulkan = 0, compare = 0, images = 0;
  double variants = 0;  // the report's chart: every variant's frames (0: not drawn)
};

struct SceneResult {
  SceneEntry entry;
  Outcome outcome = Outcome::Crash;
  Outcome actual = Outcome::Crash;          // before expectations: Pass, Fail, Crash, Timeout (or Skip)
  std::optional<Expectation> expectation;   // from the expectations file, if listed
  std::string error;                        // Crash and Timeout: one line

  // Known once the scene loaded.
  bool loaded = false;
  std::string description;
  std::uint32_t width = 0, height = 0;
  Tolerance tolerance;                      // the limits

  std::optional<Comparison> comparison;     // the metrics, known once both renderers produced a frame
  double softMilliseconds = 0, vulkanMilliseconds = 0;  // each renderer's timed span (render/render.hpp)
  double milliseconds = 0;                  // the whole scene: load, render, compare, write
  SceneTimings timings;                     // the steps of `milliseconds`

  std::filesystem::path imageRoot;          // where images were written (empty: none)
  std::vector<SceneImage> images;
  std::filesystem::path pixelData;          // relative to imageRoot: the report's value readout data
  std::pair<float, float> depthViewRange{0, 0};  // depth mapped to black..white in the depth views

  // The report's chart: the scene drawn with every variant (run/variants.hpp), when asked for.
  std::optional<VariantResults> variants;
  bool stabilityCase = false;               // a scene of a stability/ folder (hits counted, the report's table)
  // A known deviation's scene (run/deviations.hpp), drawn with the driver's behaviour: pixels
  // whose RGBA changes against lavapipe's when softraster follows the spec instead (none: not
  // such a scene, or not measured).
  std::optional<std::uint64_t> specDeviationPixels;
};

struct RunResults {
  std::vector<SceneResult> scenes;          // in suite order
  std::vector<SceneEntry> suite;            // the whole suite the run was a shard of (empty: not known)
  Shard shard;                              // which slice of `suite` `scenes` are (1/1: all of it)
  std::string suiteName = "crosscheck.conformance";  // JUnit's name for the run, the same for every shard
  // The run's options that change a render, as `crosscheck compare` takes them ("--softraster-fma
  // separate --set camera.yaw=90"), for the report's reproduce commands; shards must agree on them.
  std::string renderArguments;
  // The expectations file the run applied (--expectations; none: nullopt), as parsed: shards
  // must agree on it, or a scene could be expected to fail in one shard and not in another.
  std::optional<Expectations> expectations;
  std::string commandLine;                  // how this run was started (shown in the report; not in results.json)
  std::filesystem::path junitFile;          // the JUnit file the run wrote (empty: none)
  double seconds = 0;                       // wall time of the whole run
  unsigned jobs = 1;
  std::time_t finished = 0;                 // when the run ended (UTC); 0: unknown, not written
};

// Pass and ExpectedFail count as passed; Fail, Crash, Timeout and UnexpectedPass as failed; Skip
// as skipped.
struct Counts {
  std::size_t passed = 0, failed = 0, skipped = 0;
  std::size_t byOutcome[kAllOutcomes.size()] = {};
  std::size_t of(Outcome o) const { return byOutcome[static_cast<int>(o)]; }
};

Counts countResults(const std::vector<SceneResult>& scenes);

}  // namespace crosscheck
