// Counting a run's outcomes (see results.hpp).
#include "results/results.hpp"

namespace crosscheck {

Counts countResults(const std::vector<SceneResult>& scenes) {
  Counts counts;
  for (const SceneResult& r : scenes) {
    ++counts.byOutcome[static_cast<int>(r.outcome)];
    if (r.outcome == Outcome::Skip) {
      ++counts.skipped;
    } else if (isUnexpected(r.outcome)) {
      ++counts.failed;
    } else {
      ++counts.passed;
    }
  }
  return counts;
}

}  // namespace crosscheck
