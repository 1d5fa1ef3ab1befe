// The speed-vs-accuracy chart as inline SVG: for each scene two scatter panels, frame time (median
// ms, log scale) against the error against Vulkan (coverage mismatches in pixels; colour max |Δ|
// in 8-bit steps; both on a log scale with 0 at the bottom: log10(1 + v)), one marker per method
// and option (a shape and colour per label, the same in every panel, and a legend), lavapipe's
// median frame time as a dashed vertical line, the Pareto front (no other point is both faster
// and closer) as a line through its points, and a <title> tooltip on every marker with the
// label and its numbers; plus one overview panel over all scenes: speed relative to lavapipe
// (lavapipe median / median, log scale, > 1: faster) against coverage mismatches, one marker per
// scene and variant (scenes without lavapipe's time are left out of it). A point whose median is
// 0 or that has no agreement numbers is not drawn; it is named under its panel.
// Input is a ChartSet, made from a bench JSON (crosscheck bench --json: chartFromBenchJson) or
// from a run's results (the report's variant runs: chartFromResults). The SVG needs no script,
// font or network: a browser and a paper's toolchain read it alike.
// Deliberately no interactivity beyond the tooltips, and no charting library.
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace crosscheck {

struct ChartPoint {
  std::string label;                       // the method and option ("exact", "exact 1/z")
  double milliseconds = 0;                 // median frame time
  std::optional<double> coverageMismatches;  // against Vulkan; absent: not compared
  std::optional<double> colourMaxDelta;
  std::string error;                       // a failed variant: not drawn, listed under the panel
  bool drawable() const { return error.empty() && milliseconds > 0 && coverageMismatches && colourMaxDelta; }
};

struct ChartScene {
  std::string name;
  double lavapipeMilliseconds = 0;         // 0: unknown (no reference line)
  std::vector<ChartPoint> points;
};

struct ChartSet {
  std::string title;
  std::vector<ChartScene> scenes;
};

// The indices of the points on the Pareto front when both coordinates are minimised, in order
// of x: a point is on it unless another is at least as good in both and better in one (equal
// points are all on it).
std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points);

// Ticks of a log axis over [lo, hi] (0 < lo <= hi): the powers of ten inside it, with 2 and 5
// times them when it spans fewer than two decades, and at least the two ends' decades.
std::vector<double> logTicks(double lo, double hi);

// The error panels' axis: ticks 0, 1, 10, 100, ... up to the first power of ten >= hi.
std::vector<double> countTicks(double hi);

enum class ChartMetric { CoverageMismatches, ColourMaxDelta };

// One scene's panel, an <svg> element of its own (width x height px).
std::string scenePanelSvg(const ChartScene& scene, ChartMetric metric, const std::vector<std::string>& labels);
// The overview panel over every scene.
std::string overviewPanelSvg(const ChartSet& set, const std::vector<std::string>& labels);
// The legend: one row per label.
std::string legendSvg(const std::vector<std::string>& labels);
// Every label in order of first appearance (the style of a label is its position here).
std::vector<std::string> chartLabels(const ChartSet& set);

// The whole chart as a standalone SVG document (title, legend, overview, then each scene's two
// panels side by side).
std::string chartDocument(const ChartSet& set);

// A bench JSON's scenes as a ChartSet (a softraster result's label is its "method", and
// its "label" where the bench writes one). The error is one line: "FILE: what is wrong".
softraster::Result<ChartSet> chartFromBenchJson(std::string_view text, const std::string& file);

// The scenes of a run that carry variant runs (SceneResult::variants), as a ChartSet.
ChartSet chartFromResults(const RunResults& results);

}  // namespace crosscheck
