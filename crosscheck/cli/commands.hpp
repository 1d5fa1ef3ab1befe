// The subcommands behind the command line, one file each in cli/: what each was asked for
// (filled by main.cpp from the arguments) and the function that does it, prints its output and
// returns the exit status.
//   render       one scene, one renderer, PNGs                  0 written
//   compare      one scene, both renderers, text or JSON        0 within tolerance, 1 outside
//   conformance  a suite of scenes, one line each, JUnit, PNGs  0 nothing unexpected, 1 something
//   report       the conformance run plus DIR/index.html        as conformance
//   merge        N shards' results.json into one report, JUnit  as conformance
//                and results.json
//   bench        frame times of every renderer, table and JSON  0 every method agrees with lavapipe,
//                                                               1 a renderer failed or disagrees
//   chart        a bench JSON as a speed-vs-accuracy SVG        0 written
//   stability    every stability case x variant, table, JSON    0 exact passes every case, 1 not
//   view         a window: both renderers live, keys or a       0 closed or the script ended
//                --script, screenshots and saved scenes
// 2 is bad usage or a failure to finish everywhere (main.cpp's parse errors; a scene that cannot
// be loaded, rendered or written; the suite commands' unreadable
// expectations, shards, folders or output paths; merge's unreadable results or shards that do not
// make up one suite).
// Errors print as one line, "crosscheck: ..." on stderr (failWith, failIn below).
// Deliberately no argument parsing here (main.cpp does that with CLI11) and no rendering or
// formatting of their own: each command strings together scene/, render/, compare/, run/ and
// output/.
#pragma once

#include "results/results.hpp"
#include "run/bench.hpp"        // BenchMethod
#include "run/conformance.hpp"  // kDefaultMemoryLimitMegabytes

#include <softraster/pipeline.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace crosscheck::cli {

// Anything that kept a command from finishing: one error line, "crosscheck: MESSAGE" on stderr,
// and exit status 2.
inline int failWith(const std::string& message) {
  std::fprintf(stderr, "crosscheck: %s\n", message.c_str());
  return 2;
}
inline int failWith(const softraster::Status& status) { return failWith(status.message()); }

// A renderer's error about the scene ("vulkan: draw 0: ..."), with the scene file named first.
inline int failIn(const std::filesystem::path& scene, const softraster::Status& status) {
  return failWith(scene.string() + ": " + status.message());
}

// Whether `file` can be written, proven before a long run: its folder made, the file opened to
// append (so an existing one is not emptied yet) and not a directory.
inline bool canWrite(const std::string& file) {
  const std::filesystem::path path(file);
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  return !std::filesystem::is_directory(path, ec) && static_cast<bool>(std::ofstream(path, std::ios::app));
}

// Options the single-scene commands share.
struct SceneOptions {
  std::string scene;                    // the scene file
  std::vector<std::string> overrides;   // --set KEY.PATH=VALUE
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
};

struct RenderCommand {
  SceneOptions options;
  std::string renderer = "soft";        // soft or vulkan
  std::string output;                   // colour PNG
  std::string depthOutput;              // depth view PNG; empty: none
  std::vector<float> depthRange;        // LO HI mapped to black..white; empty: the image's own range
};
int renderCommand(const RenderCommand& command);

struct CompareCommand {
  SceneOptions options;
  std::string outDir;                   // soft, vulkan, diff and depth PNGs; empty: none
  bool json = false;
};
int compareCommand(const CompareCommand& command);

// Options the suite commands (conformance, report) share.
struct SuiteCommand {
  std::vector<std::string> inputs;      // scene files and directories; empty: scenes/
  std::vector<std::string> overrides;   // --set KEY.PATH=VALUE, applied to every scene
  std::string expectationsFile;
  unsigned jobs = 1;                    // worker processes
  double timeoutSeconds = 0;            // per scene; 0: none
  std::size_t memoryLimitMegabytes = kDefaultMemoryLimitMegabytes;  // per worker; 0: none
  std::string shard;                    // "I/N", 1-based; empty: the whole suite
  std::string junitFile;
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
  std::string commandLine;              // shown in the report
};
// outDir: conformance --out, per-scene PNGs and results.json; empty: none.
int conformanceCommand(const SuiteCommand& command, const std::string& outDir);
// The report's chart by default: 3 timed frames per variant (each variant also draws one untimed).
inline constexpr unsigned kDefaultChartFrames = 3;
// reportDir: report -o, index.html with its PNGs, pixel data and results.json; baselineDir:
// --baseline, an earlier run's folder (or its results.json) to mark changes against; empty: none.
// chartFrames: the speed-vs-accuracy chart's timed frames per variant (0: --no-chart).
int reportCommand(const SuiteCommand& command, const std::string& reportDir, const std::string& baselineDir = "",
                  unsigned chartFrames = kDefaultChartFrames);

struct MergeCommand {
  std::vector<std::string> inputs;      // results.json files, or the folders that hold them
  std::string outDir;                   // the merged report, results.json and (by default) junit.xml
  std::string junitFile;                // empty: outDir/junit.xml
  std::string commandLine;              // shown in the report
};
int mergeCommand(const MergeCommand& command);

// The suite run both suite commands are (conformance.cpp; report.cpp adds the page): check the
// arguments, run, print a line per scene in suite order (and a progress line when stderr is a
// terminal), write JUnit and what `outputs` adds, print the summary and, last,
// "N passed, N failed[, N skipped]".
struct SuiteOutputs {
  std::string name;                     // "conformance" or "report", in the first line
  std::string imageDir;                 // per-scene PNGs in imageDir/<scene>/; empty: none
  bool pixelData = false;               // and pixels.js beside them (the report's value readout)
  unsigned chartFrames = 0;             // the report's chart: timed frames per variant; 0: no chart
  std::function<softraster::Status(const RunResults&)> write;  // after the run (the report page); may be empty
  // Printed after the summary's JUnit line: always when `write` is empty, else only when
  // everything was written.
  std::string doneLine;
};
int runSuite(const SuiteCommand& command, const SuiteOutputs& outputs);

// What bench runs with no scene arguments, from the repository root.
inline constexpr std::string_view kDefaultBenchDir = "scenes/bench";

struct BenchCommand {
  std::vector<std::string> inputs;      // scene files and directories; empty: scenes/bench
  unsigned frames = 15;                 // timed frames per renderer, at least 1
  unsigned warmup = 3;
  unsigned threads = 0;                 // softraster threads and LP_NUM_THREADS; 0: every core
  std::string jsonFile;                 // empty: no JSON
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
  std::vector<BenchMethod> methods{{softraster::Method::Exact}, {softraster::Method::ExactScalar}};
};
int benchCommand(const BenchCommand& command);

struct ChartCommand {
  std::string benchJson;                // crosscheck bench --json FILE
  std::string output;                   // the SVG; empty: the JSON's path with .svg
};
int chartCommand(const ChartCommand& command);

struct StabilityCommand {
  std::vector<std::string> inputs;      // scene files and directories; empty: scenes/stability
  unsigned frames = 3;                  // timed frames per variant
  std::string jsonFile;                 // empty: no JSON
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
};
int stabilityCommand(const StabilityCommand& command);
struct ViewCommand {
  SceneOptions options;
  std::string script;                   // --script FILE; empty: the keyboard
  std::string outDir = "out/view";      // screenshots and saved scenes
};
// view.cpp; 2 for a bad script, scene, no display or a renderer's or writer's error.
int viewCommand(const ViewCommand& command);

}  // namespace crosscheck::cli
