// A run against a baseline (an earlier run's results.json, `report --baseline DIR`): per scene,
// matched by name, whether it is a new failure (unexpected now, and not in the baseline or as
// expected there), fixed (unexpected in the baseline, and now passed: Pass or ExpectedFail) and
// which of the metrics the report's summary table shows changed (both runs compared the frames and
// a value differs at all: the renderers are deterministic, so any change is a change); plus the
// baseline's scenes this run does not have.
// Deliberately by scene name only (a scene moved to another folder is the same scene), no
// timings (they vary between machines and runs) and no text: the report marks what is here.
#pragma once

#include "results/results.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace crosscheck {

struct MetricChange {
  std::string metric;           // the summary table's column: "coverage mismatches", "PSNR", ...
  double before = 0, after = 0;
};

struct SceneVersusBaseline {
  bool inBaseline = false;
  Outcome before = Outcome::Pass;        // the baseline's outcome, when inBaseline
  bool newFailure = false, fixed = false;
  std::vector<MetricChange> changes;     // empty: the same metrics (or one of the runs has none)
};

struct BaselineComparison {
  std::vector<SceneVersusBaseline> scenes;  // one per scene of the run, in its order
  std::vector<std::string> gone;            // names of the baseline's scenes that this run does not have
  std::size_t newFailures = 0, fixed = 0, changed = 0, added = 0;  // added: scenes not in the baseline
};

BaselineComparison compareWithBaseline(const RunResults& run, const RunResults& baseline);

}  // namespace crosscheck
