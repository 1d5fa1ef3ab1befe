// crosscheck merge: the results.json of N shards (conformance or report --shard I/N, run on N
// machines) into one run over the whole suite (results/merge.hpp checks that they are shards of
// the same suite and hold each scene once; an error is one line naming the file and the scene,
// exit 2), written to DIR as one report (DIR/index.html), one JUnit file (DIR/junit.xml unless
// --junit) and one DIR/results.json. Every scene's images and pixel data are copied into
// DIR/<scene>/, so the report works wherever the shards' folders were and whatever becomes of them.
// Prints one line per scene in suite order, the summary and, last, the counts; the exit status is
// conformance's (0 nothing unexpected, 1 something, 2 an error).
// Deliberately no rendering: merge reads what the shards recorded and runs nothing again.
#include "cli/commands.hpp"

#include "output/artifacts.hpp"
#include "output/junit.hpp"
#include "output/report/report.hpp"
#include "output/summary.hpp"
#include "results/merge.hpp"
#include "results/results_file.hpp"

#include <cstdio>
#include <filesystem>

namespace crosscheck::cli {

int mergeCommand(const MergeCommand& command) {
  std::vector<ShardResults> shards;
  for (const std::string& input : command.inputs) {
    auto run = readResultsFile(input);
    if (!run) return failWith(run.error());
    shards.push_back({resultsFileOf(input), std::move(*run)});
  }
  auto merged = mergeShards(shards);
  if (!merged) return failWith(merged.error());
  RunResults& run = *merged;
  const std::filesystem::path dir = command.outDir;
  run.commandLine = command.commandLine;
  run.junitFile = command.junitFile.empty() ? dir / "junit.xml" : std::filesystem::path(command.junitFile);

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) return failWith(dir.string() + ": cannot create output directory");
  for (SceneResult& r : run.scenes) {
    if (const softraster::Status copied = copySceneFiles(&r, dir); !copied) return failWith(copied.message());
  }
  std::printf("crosscheck merge: %zu scene%s from %zu file%s\n", run.scenes.size(), run.scenes.size() == 1 ? "" : "s",
              shards.size(), shards.size() == 1 ? "" : "s");
  for (const SceneResult& r : run.scenes) std::printf("%s\n", resultLine(r).c_str());
  std::fflush(stdout);

  const softraster::Status written[] = {writeJUnit(run.junitFile, run), writeResultsFile(dir, run), writeReport(dir, run)};
  for (const softraster::Status& status : written) {
    if (!status) return failWith(status.message());
  }
  const Counts counts = countResults(run.scenes);
  const std::string summary = summaryText(run);
  if (!summary.empty()) std::printf("\n%s", summary.c_str());
  std::printf("JUnit: %s\nresults: %s\nreport: %s\n", run.junitFile.string().c_str(),
              (dir / kResultsFileName).string().c_str(), (dir / "index.html").string().c_str());
  std::printf("%s\n", countsLine(counts).c_str());
  std::fflush(stdout);
  return counts.failed == 0 ? 0 : 1;
}

}  // namespace crosscheck::cli
