// The stability runner: each case of a stability suite (scenes/stability/: a triangle across the
// near plane, slivers, NaN vertices, ...) drawn with every variant of run/variants.hpp, each
// against lavapipe: pixels that differ, coverage mismatches, colour max |Δ|, cracks and double
// hits (variants.hpp's HitCounts) and the frame time. A variant passes a case when it drew it,
// every pixel equals lavapipe's and its hit counts match lavapipe's (no crack, no double hit).
// The cases run in this process, one Vulkan renderer for all; a variant's error or exception is
// its failing row (runVariants), a case that cannot be loaded is the case's error, and the run
// always goes on.
// Deliberately no expectations file: `exact` must pass every case (the exit status), every other
// variant is measured, not judged.
#pragma once

#include "results/variant_results.hpp"
#include "run/suite.hpp"

#include <softraster/options.hpp>
#include <vkref/renderer.hpp>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace crosscheck {

// What `crosscheck stability` runs with no argument: suite.hpp's kDefaultStabilitySceneDir.

// The variant every case must pass: the lavapipe-exact method with Vulkan's depth.
inline constexpr std::string_view kStabilityReference = "exact";

struct StabilityCase {
  SceneEntry entry;
  std::string description;
  std::string error;                  // the case could not be loaded or lavapipe failed: one line
  VariantResults variants;
};

struct StabilityOptions {
  unsigned frames = 3;                // timed frames per variant
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;  // threads and fmuladd; method and depth are the variants'
  std::function<void(std::size_t position, std::size_t count, const StabilityCase&)> onCase;
};

struct StabilityResults {
  unsigned frames = 0;
  std::vector<StabilityCase> cases;
  // Whether kStabilityReference passed every case.
  bool referencePasses() const;
};

// Whether a variant's row is a pass (see the top of this file).
bool variantPasses(const VariantRun& run);

// The error is one line when no Vulkan renderer can be opened (nothing can be compared).
softraster::Result<StabilityResults> runStability(const std::vector<SceneEntry>& cases, const StabilityOptions& options);

}  // namespace crosscheck
