// crosscheck report: the conformance run (conformance.cpp) with each scene's images and pixel
// data in DIR/<scene>/, and the HTML page DIR/index.html over them (see commands.hpp); with
// --baseline, an earlier run's results.json read before the run (an unreadable one is exit 2) and
// the page marks what changed against it.
#include "cli/commands.hpp"

#include "output/report/report.hpp"
#include "results/baseline.hpp"
#include "results/results_file.hpp"

#include <cstdio>
#include <filesystem>
#include <optional>

namespace crosscheck::cli {
namespace {

softraster::Result<std::optional<ReportBaseline>> loadBaseline(const std::string& baselineDir) {
  if (baselineDir.empty()) return std::optional<ReportBaseline>();
  const auto baseline = readResultsFile(baselineDir);
  if (!baseline) return baseline.status();
  ReportBaseline loaded;
  loaded.file = resultsFileOf(baselineDir);
  loaded.finished = baseline->finished;
  loaded.run = *baseline;
  return std::optional<ReportBaseline>(std::move(loaded));
}

}  // namespace

int reportCommand(const SuiteCommand& command, const std::string& reportDir, const std::string& baselineDir,
                  unsigned chartFrames) {
  auto baseline = loadBaseline(baselineDir);
  if (!baseline) {
    std::fprintf(stderr, "crosscheck: --baseline: %s\n", baseline.error().c_str());
    return 2;
  }
  SuiteOutputs outputs;
  outputs.name = "report";
  outputs.imageDir = reportDir;
  outputs.pixelData = true;
  outputs.chartFrames = chartFrames;
  outputs.write = [&](const RunResults& run) {
    std::optional<ReportBaseline>& against = *baseline;
    if (against) against->versus = compareWithBaseline(run, against->run);
    return writeReport(reportDir, run, against ? &*against : nullptr);
  };
  outputs.doneLine = "report: " + (std::filesystem::path(reportDir) / "index.html").string();
  return runSuite(command, outputs);
}

}  // namespace crosscheck::cli
