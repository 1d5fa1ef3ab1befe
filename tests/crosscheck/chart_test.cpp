// The speed-vs-accuracy chart (output/chart_svg.hpp): the Pareto front of hand-made points, the
// log axis's ticks, one marker per drawn result in the SVG of a hand-made bench JSON with the
// front known, tooltips, the reference line, and the bench JSON's errors naming the file.
// (The SVG's well-formedness is checked by an XML parser in bench_cli_test.sh's chart cases.)
#include "output/chart_svg.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <string>

namespace {

using namespace crosscheck;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(Chart, ParetoFrontMinimisesBoth) {
  // (time, error): b is faster than a but worse; c is dominated by a; d equals a; e is the slowest
  // and exact; f is dominated by e.
  const std::vector<std::pair<double, double>> points{{2, 10}, {1, 50}, {3, 20}, {2, 10}, {8, 0}, {9, 0}};
  EXPECT_EQ(paretoFront(points), (std::vector<std::size_t>{1, 0, 3, 4}));
  EXPECT_EQ(paretoFront({}), std::vector<std::size_t>{});
  EXPECT_EQ(paretoFront({{5, 5}}), std::vector<std::size_t>{0});
}

TEST(Chart, LogTicks) {
  EXPECT_EQ(logTicks(0.1, 1000), (std::vector<double>{0.1, 1, 10, 100, 1000}));
  EXPECT_EQ(logTicks(1, 10), (std::vector<double>{1, 2, 5, 10}));  // one decade: 2 and 5 too
  EXPECT_EQ(logTicks(0.01, 1), (std::vector<double>{0.01, 0.1, 1}));  // two decades: powers only
  EXPECT_EQ(logTicks(0.1, 1), (std::vector<double>{0.1, 0.2, 0.5, 1}));
  EXPECT_EQ(countTicks(0), (std::vector<double>{0, 1}));
  EXPECT_EQ(countTicks(250), (std::vector<double>{0, 1, 10, 100, 1000}));
}

// Two scenes: in "quad", exact (1 ms, 0 mismatches) and fast (0.5 ms, 30 mismatches) are on the
// front, slow (2 ms, 10 mismatches) is not; in "room", broken failed and is not drawn.
const char* const kBench = R"({
  "machine": {"cpu": "Test CPU", "cores": 2, "memset_gb_per_s": 10},
  "frames": 3, "warmup": 1, "threads": 2,
  "scenes": [
    {"scene": "scenes/bench/quad.json", "results": [
      {"renderer": "softraster", "method": "exact", "median_ms": 1.0, "coverage_mismatches": 0, "colour_max_delta": 0, "error": null},
      {"renderer": "softraster", "method": "fast", "median_ms": 0.5, "coverage_mismatches": 30, "colour_max_delta": 255, "error": null},
      {"renderer": "softraster", "method": "slow", "median_ms": 2.0, "coverage_mismatches": 10, "colour_max_delta": 3, "error": null},
      {"renderer": "lavapipe", "median_ms": 4.0, "coverage_mismatches": null, "colour_max_delta": null, "error": null}]},
    {"scene": "scenes/bench/room.json", "results": [
      {"renderer": "softraster", "method": "exact", "median_ms": 3.0, "coverage_mismatches": 0, "colour_max_delta": 0, "error": null},
      {"renderer": "softraster", "method": "broken", "median_ms": 0, "coverage_mismatches": null, "colour_max_delta": null, "error": "it broke"},
      {"renderer": "lavapipe", "median_ms": 6.0, "error": null}]}
  ]})";

TEST(Chart, FromBenchJson) {
  const auto set = chartFromBenchJson(kBench, "bench.json");
  ASSERT_TRUE(set) << set.error();
  ASSERT_EQ(set->scenes.size(), 2u);
  EXPECT_EQ(set->scenes[0].name, "quad");
  EXPECT_EQ(set->scenes[0].lavapipeMilliseconds, 4.0);
  EXPECT_EQ(set->scenes[0].points.size(), 3u);
  EXPECT_EQ(set->scenes[1].points[1].error, "it broke");
  EXPECT_EQ(chartLabels(*set), (std::vector<std::string>{"exact", "fast", "slow", "broken"}));
  EXPECT_NE(set->title.find("Test CPU"), std::string::npos);
}

TEST(Chart, DocumentHasAMarkerPerResultAndTheFront) {
  const auto set = chartFromBenchJson(kBench, "bench.json");
  ASSERT_TRUE(set);
  const std::string svg = chartDocument(*set);
  // Per scene two panels (coverage, colour): quad 3 drawn points each, room 1; the overview one
  // per drawn scene x method: 4. Legend markers are another class.
  EXPECT_EQ(count(svg, "<g class=\"marker\""), 2 * 3 + 2 * 1 + 4u);
  EXPECT_EQ(count(svg, "class=\"legend-marker\""), 4u);
  EXPECT_EQ(count(svg, "<title>"), count(svg, "<g class=\"marker\"") + count(svg, "class=\"legend-marker\"") +
                                       count(svg, "class=\"lavapipe\"") + count(svg, "class=\"pareto\""));
  // quad, coverage: exact and fast on the front, slow not.
  const std::string panel = scenePanelSvg(set->scenes[0], ChartMetric::CoverageMismatches, chartLabels(*set));
  EXPECT_NE(panel.find("data-label=\"exact\" data-pareto=\"1\""), std::string::npos);
  EXPECT_NE(panel.find("data-label=\"fast\" data-pareto=\"1\""), std::string::npos);
  EXPECT_NE(panel.find("data-label=\"slow\" data-pareto=\"0\""), std::string::npos);
  EXPECT_NE(panel.find("class=\"pareto\" data-points=\"2\""), std::string::npos);
  // The x axis spans 0.1..10 ms (0.5 to 4 with lavapipe): whole decades, no 2 and 5.
  std::regex tick("class=\"xtick\" data-value=\"([^\"]+)\"");
  std::vector<std::string> ticks;
  for (auto it = std::sregex_iterator(panel.begin(), panel.end(), tick); it != std::sregex_iterator(); ++it) {
    ticks.push_back((*it)[1]);
  }
  EXPECT_EQ(ticks, (std::vector<std::string>{"0.1", "1", "10"}));
  // The y axis: 0, 1, 10, 100 (30 mismatches at most).
  EXPECT_NE(panel.find("class=\"ytick\" data-value=\"100\""), std::string::npos);
  EXPECT_EQ(panel.find("class=\"ytick\" data-value=\"1000\""), std::string::npos);
  // Tooltips with the numbers; the reference line; the failed method named, not drawn.
  EXPECT_NE(panel.find("<title>fast: 0.5 ms (8x as fast as lavapipe), 30 coverage mismatches, colour max |Δ| 255"),
            std::string::npos);
  EXPECT_NE(panel.find("<title>lavapipe: 4 ms (median)</title>"), std::string::npos);
  const std::string room = scenePanelSvg(set->scenes[1], ChartMetric::ColourMaxDelta, chartLabels(*set));
  EXPECT_NE(room.find("not drawn: broken: it broke"), std::string::npos);
  // colour panel of quad: exact (1, 0) and fast (0.5, 255) on the front; slow (2, 3) not.
  const std::string colour = scenePanelSvg(set->scenes[0], ChartMetric::ColourMaxDelta, chartLabels(*set));
  EXPECT_NE(colour.find("data-label=\"slow\" data-pareto=\"0\""), std::string::npos);
}

TEST(Chart, BadBenchJsonNamesTheFile) {
  for (const char* text : {"", "{", "[]", "{\"scenes\": 3}", "{\"scenes\": [{\"results\": [{\"method\": \"x\"}]}]}"}) {
    const auto set = chartFromBenchJson(text, "dir/b.json");
    ASSERT_FALSE(set) << text;
    EXPECT_EQ(set.error().rfind("dir/b.json: ", 0), 0u) << set.error();
    EXPECT_EQ(set.error().find('\n'), std::string::npos) << set.error();
  }
}

}  // namespace
