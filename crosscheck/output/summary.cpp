// Conformance text output (see summary.hpp).
#include "output/summary.hpp"

#include "output/metric_text.hpp"

#include <algorithm>
#include <cstdio>

namespace crosscheck {
namespace {

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string padded(std::string_view text, std::size_t width) {
  std::string s(text);
  if (s.size() < width) s.append(width - s.size(), ' ');
  return s;
}

std::string timing(const SceneResult& r) {
  return format("soft %.2f ms", r.softMilliseconds) + format(", vulkan %.2f ms", r.vulkanMilliseconds);
}

// Where a scene's time went (SceneTimings), with each renderer's timed span beside its whole call;
// empty when no step ran (a skipped scene, or one whose worker died or timed out).
std::string steps(const SceneResult& r) {
  const SceneTimings& t = r.timings;
  if (t.load == 0 && t.soft == 0 && t.vulkan == 0 && t.compare == 0 && t.images == 0) return "";
  const bool rendered = r.actual == Outcome::Pass || r.actual == Outcome::Fail;
  std::string text = format(": load %.2f", t.load) + format(", softraster %.2f", t.soft);
  if (rendered) text += format(" (draw %.2f)", r.softMilliseconds);
  text += format(", vulkan %.2f", t.vulkan);
  if (rendered) text += format(" (submit %.2f)", r.vulkanMilliseconds);
  return text + format(", compare %.2f", t.compare) + format(", images %.2f", t.images);
}

// One Comparison::failures entry with the metric that drove it next to its threshold.
std::string explainFailure(const std::string& failure, const SceneResult& r) {
  if (!r.comparison) return failure;
  const Comparison& c = *r.comparison;
  if (failure.rfind("colour_pixels_over", 0) == 0) {
    const int worst = *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end());
    return failure + " (colour max " + kAbsDelta + " " + std::to_string(worst) + " " + c.colourUnit + ", threshold " +
           std::to_string(r.tolerance.colourThreshold) + ")";
  }
  if (failure.rfind("depth_pixels_over", 0) == 0) {
    return failure + " (depth max " + kAbsDelta + " " + depthText(c.depthMaxDelta) + ", threshold " +
           depthText(r.tolerance.depthThreshold) + ")";
  }
  return failure;
}

std::string reasonSuffix(const SceneResult& r) {
  if (!r.expectation || r.expectation->reason.empty()) return "";
  return " [" + r.expectation->reason + "]";
}

}  // namespace

std::string resultDetail(const SceneResult& r) {
  switch (r.actual) {
    case Outcome::Crash:
    case Outcome::Timeout: return r.error;
    case Outcome::Skip: return "skipped by expectations";
    case Outcome::Pass:
      if (r.outcome == Outcome::UnexpectedPass) {
        return "expected " + std::string(outcomeName(r.expectation->outcome)) + " (line " +
               std::to_string(r.expectation->line) + "), but passed";
      }
      return "";
    case Outcome::Fail: {
      std::string detail;
      if (r.comparison) {
        for (const std::string& f : r.comparison->failures) detail += (detail.empty() ? "" : "; ") + explainFailure(f, r);
      }
      return detail;
    }
    default: return "";
  }
}

std::string resultLine(const SceneResult& r) {
  std::string line = padded(outcomeName(r.outcome), 15) + r.entry.name;
  const std::string detail = resultDetail(r);
  if (!detail.empty()) line += ": " + detail;
  line += reasonSuffix(r);
  if (r.actual == Outcome::Pass || r.actual == Outcome::Fail) line += "  (" + timing(r) + ")";
  return line;
}

std::string progressLine(std::size_t done, std::size_t total, std::size_t failures, double elapsedSeconds) {
  return "[" + std::to_string(done) + "/" + std::to_string(total) + "] failures: " + std::to_string(failures) +
         format(" elapsed: %.1fs", elapsedSeconds);
}

std::string summaryText(const RunResults& run, std::size_t slowest) {
  const std::vector<SceneResult>& results = run.scenes;
  std::string text;
  const auto section = [&](const std::string& heading, const auto& keep) {
    std::string lines;
    std::size_t n = 0;
    for (const SceneResult& r : results) {
      if (!keep(r)) continue;
      ++n;
      lines += "  " + padded(outcomeName(r.outcome), 15) + r.entry.name + ": " + resultDetail(r) + reasonSuffix(r) + "\n";
    }
    if (n) text += heading + " (" + std::to_string(n) + "):\n" + lines;
  };
  section("Failures", [](const SceneResult& r) { return isUnexpected(r.outcome); });
  section("Expected failures and skips", [](const SceneResult& r) {
    return r.outcome == Outcome::ExpectedFail || r.outcome == Outcome::Skip;
  });

  std::vector<const SceneResult*> ran;
  for (const SceneResult& r : results) {
    if (r.outcome != Outcome::Skip) ran.push_back(&r);
  }
  std::stable_sort(ran.begin(), ran.end(), [](const auto* a, const auto* b) { return a->milliseconds > b->milliseconds; });
  if (ran.size() > slowest) ran.resize(slowest);
  if (!ran.empty() && slowest > 0) {
    text += "Slowest scenes:\n";
    for (const SceneResult* r : ran) {
      text += "  " + padded(r->entry.name, 24) + format(" %9.2f ms", r->milliseconds) + steps(*r) + "\n";
    }
  }
  return text;
}

std::string countsLine(const Counts& counts) {
  std::string line = std::to_string(counts.passed) + " passed, " + std::to_string(counts.failed) + " failed";
  if (counts.skipped) line += ", " + std::to_string(counts.skipped) + " skipped";
  return line;
}

}  // namespace crosscheck
