// crosscheck conformance, and the suite run it shares with crosscheck report (see commands.hpp):
// check the arguments, run the suite, print one line per scene (in suite order), a progress line
// when stderr is a terminal, the summary and, last, "N passed, N failed[, N skipped]"; write
// JUnit, the scenes' images and DIR/results.json. The scenes run in worker processes (run/conformance.hpp), which
// write the images; a worker that fails after its last scene is one line on stderr and exit 1.
#include "cli/commands.hpp"

#include "output/artifacts.hpp"
#include "output/junit.hpp"
#include "output/report/report.hpp"  // writePixelData
#include "output/summary.hpp"
#include "results/results.hpp"
#include "results/results_file.hpp"
#include "run/conformance.hpp"
#include "run/expectations.hpp"
#include "run/suite.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <optional>
#include <set>

namespace crosscheck::cli {
namespace {

using Clock = std::chrono::steady_clock;
using softraster::Status;


// Creates the folder and proves a file can be created in it, so a run does not end in an error.
Status prepareOutputDir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    return Status::error(dir + ": cannot create output directory" +
                         (ec ? ": " + ec.message() : std::string(": not a directory")));
  }
  const std::filesystem::path probe = std::filesystem::path(dir) / ".crosscheck-write-test";
  if (!std::ofstream(probe)) return Status::error(dir + ": cannot write into output directory");
  std::filesystem::remove(probe, ec);
  return {};
}

// Opens the file for appending (so an existing file is not emptied yet) to prove it is writable.
Status prepareOutputFile(const std::string& file) {
  const std::filesystem::path path(file);
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (std::filesystem::is_directory(path, ec) || !std::ofstream(path, std::ios::app)) {
    return Status::error(file + ": cannot write this file");
  }
  return {};
}

// Prints finished scenes in suite order, and the progress line on a terminal.
class Printer {
 public:
  Printer(std::size_t total, Clock::time_point start) : finished_(total, nullptr), start_(start), tty_(isatty(fileno(stderr))) {}

  void finished(std::size_t position, const SceneResult& result, std::size_t done) {
    finished_[position] = &result;
    if (isUnexpected(result.outcome)) ++failures_;
    if (tty_) std::fputs("\r\033[K", stderr);
    while (next_ < finished_.size() && finished_[next_]) std::printf("%s\n", resultLine(*finished_[next_++]).c_str());
    std::fflush(stdout);
    if (tty_) {
      const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
      std::fprintf(stderr, "\r%s", progressLine(done, finished_.size(), failures_, elapsed).c_str());
      std::fflush(stderr);
    }
  }

  bool onTerminal() const { return tty_; }

  void end() {
    if (!tty_) return;
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }

 private:
  std::vector<const SceneResult*> finished_;
  std::size_t next_ = 0, failures_ = 0;
  Clock::time_point start_;
  bool tty_;
};

}  // namespace

int runSuite(const SuiteCommand& command, const SuiteOutputs& outputs) {
  if (command.jobs < 1) return failWith("--jobs must be at least 1");
  Shard shard;
  if (!command.shard.empty()) {
    const auto parsed = parseShard(command.shard);
    if (!parsed) return failWith(parsed.error());
    shard = *parsed;
  }
  for (const std::string& assignment : command.overrides) {
    if (const Status form = checkOverride(assignment); !form) return failWith(form.message());
  }
  std::optional<Expectations> expectations;
  if (!command.expectationsFile.empty()) {
    auto loaded = loadExpectations(command.expectationsFile);
    if (!loaded) return failWith(loaded.error());
    expectations = std::move(*loaded);
  }
  const auto suite = collectScenes(command.inputs);
  if (!suite) return failWith(suite.error());
  if (!outputs.imageDir.empty()) {
    if (const Status prepared = prepareOutputDir(outputs.imageDir); !prepared) return failWith(prepared.message());
  }
  if (!command.junitFile.empty()) {
    if (const Status prepared = prepareOutputFile(command.junitFile); !prepared) return failWith(prepared.message());
  }

  if (expectations) {
    std::set<std::string> names;
    for (const SceneEntry& entry : *suite) names.insert(entry.name);
    for (const auto& [name, expectation] : expectations->byScene) {
      if (!names.count(name)) {
        std::fprintf(stderr, "crosscheck: warning: %s:%d: no scene named '%s' in this suite\n",
                     expectations->file.string().c_str(), expectation.line, name.c_str());
      }
    }
  }
  const std::vector<SceneEntry> slice = selectShard(*suite, shard);
  ConformanceOptions options;
  options.jobs = command.jobs;
  options.overrides = command.overrides;
  options.expectations = expectations ? &*expectations : nullptr;
  // The jobs that run: no more than the scenes that are not skipped.
  const std::size_t jobs = jobsFor(slice, options);
  std::printf("crosscheck %s: %zu scene%s", outputs.name.c_str(), slice.size(), slice.size() == 1 ? "" : "s");
  if (shard.count > 1) std::printf(" (shard %zu/%zu of %zu)", shard.index, shard.count, suite->size());
  std::printf(", %zu job%s", jobs, jobs == 1 ? "" : "s");
  if (jobs < command.jobs) std::printf(" (--jobs %u: no more jobs than scenes to run)", command.jobs);
  std::printf("\n");
  for (const std::string& assignment : command.overrides) std::printf("  --set %s in every scene\n", assignment.c_str());
  std::fflush(stdout);

  const auto start = Clock::now();
  Printer printer(slice.size(), start);
  options.timeoutSeconds = command.timeoutSeconds;
  options.memoryLimitMegabytes = command.memoryLimitMegabytes;
  bool workerFailed = false;
  options.onWorkerError = [&](const std::string& error) {
    std::fprintf(stderr, "%scrosscheck: %s\n", printer.onTerminal() ? "\r\033[K" : "", error.c_str());
    workerFailed = true;
  };
  options.device = command.device;
  options.softraster = command.softraster;
  options.chartFrames = outputs.chartFrames;
  options.onFinished = [&](std::size_t position, const SceneResult& result, std::size_t done) {
    printer.finished(position, result, done);
  };
  if (!outputs.imageDir.empty()) {
    options.onFrames = [&](SceneResult& result, const Scene& scene, const Frame& soft, const Frame& vulkan) {
      const std::filesystem::path folder = result.entry.name;
      const Status images = writeSceneImages(outputs.imageDir, folder, &result, scene, soft, vulkan,
                                             outputs.pixelData ? SceneImageSet::Compact : SceneImageSet::All);
      // The report's value readout data is most of its size: kept only where the renders differ
      // beyond the tolerance, where a person will look.
      if (!images || !outputs.pixelData || result.comparison->passed()) return images;
      return writePixelData(outputs.imageDir, folder / "pixels.js", &result, soft, vulkan);
    };
  }
  RunResults run;
  run.scenes = runConformance(slice, options);
  printer.end();
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.finished = std::time(nullptr);
  run.jobs = static_cast<unsigned>(jobs);
  run.commandLine = command.commandLine;
  run.junitFile = command.junitFile;
  run.suite = *suite;
  run.shard = shard;
  run.renderArguments = renderArgumentsOf(command.commandLine);
  run.expectations = expectations;
  const Counts counts = countResults(run.scenes);

  bool written = true;
  if (!command.junitFile.empty()) {
    if (const Status status = writeJUnit(command.junitFile, run); !status) {
      std::fprintf(stderr, "crosscheck: %s\n", status.message().c_str());
      written = false;
    }
  }
  if (!outputs.imageDir.empty()) {
    if (const Status status = writeResultsFile(outputs.imageDir, run); !status) {
      std::fprintf(stderr, "crosscheck: %s\n", status.message().c_str());
      written = false;
    }
  }
  if (outputs.write) {
    if (const Status status = outputs.write(run); !status) {
      std::fprintf(stderr, "crosscheck: %s\n", status.message().c_str());
      written = false;
    }
  }
  std::fflush(stderr);

  const std::string summary = summaryText(run);
  if (!summary.empty()) std::printf("\n%s", summary.c_str());
  if (!command.junitFile.empty() && written) std::printf("JUnit: %s\n", command.junitFile.c_str());
  if (!outputs.imageDir.empty() && written) {
    std::printf("results: %s\n", (std::filesystem::path(outputs.imageDir) / kResultsFileName).string().c_str());
  }
  if (!outputs.doneLine.empty() && (!outputs.write || written)) std::printf("%s\n", outputs.doneLine.c_str());
  std::printf("ran %zu scene%s in %.2f s with %u job%s\n", run.scenes.size(), run.scenes.size() == 1 ? "" : "s",
              run.seconds, run.jobs, run.jobs == 1 ? "" : "s");
  std::printf("%s\n", countsLine(counts).c_str());
  std::fflush(stdout);
  if (!written) return 2;  // an output that could not be written: not a usable run (README, exit status)
  return counts.failed == 0 && !workerFailed ? 0 : 1;
}

int conformanceCommand(const SuiteCommand& command, const std::string& outDir) {
  SuiteOutputs outputs;
  outputs.name = "conformance";
  outputs.imageDir = outDir;
  if (!outDir.empty()) outputs.doneLine = "images: " + outDir + "/<scene>/";
  return runSuite(command, outputs);
}

}  // namespace crosscheck::cli
