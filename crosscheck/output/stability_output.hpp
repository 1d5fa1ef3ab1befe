// The stability run as a terminal table (one row per case and variant: Pass/Fail, pixels that
// differ from lavapipe, coverage mismatches, colour max |Δ|, cracks, double hits, median frame
// time; a failed variant's error under its row) and as JSON:
//   {"frames", "reference": "exact", "reference_passes", "cases": [{"name", "scene", "description",
//    "error", "variants": {frames, lavapipe_milliseconds, lavapipe_error, runs: [...]}
//    }]}
// with each run as results.json's variant runs (docs/results-json.md) plus "passed".
// Reads a StabilityResults value (run/stability.hpp) only.
#pragma once

#include "run/stability.hpp"

#include <string>

namespace crosscheck {

std::string stabilityTable(const StabilityResults& results);
std::string stabilityJson(const StabilityResults& results);

}  // namespace crosscheck
