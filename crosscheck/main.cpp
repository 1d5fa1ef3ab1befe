// crosscheck: the command line. Renders scenes with softraster and with Vulkan (lavapipe),
// compares them within each scene's tolerance and writes the images:
//   crosscheck render SCENE --renderer soft|vulkan -o OUT.png [--depth-out OUT.png]
//   crosscheck compare SCENE [-o DIR] [--json]
//   crosscheck conformance [SCENE|DIR ...] [--expectations FILE] [--jobs N] [--shard I/N] [--junit FILE] [-o DIR]
//                          [--timeout SECONDS] [--memory-limit MB] [--set KEY.PATH=VALUE ...]
//   crosscheck report [SCENE|DIR ...] -o DIR [--baseline DIR] [--no-chart] [--chart-frames N]
//                     [--expectations FILE] [--jobs N] [--shard I/N]
//                     [--junit FILE] [--timeout SECONDS] [--memory-limit MB] [--set KEY.PATH=VALUE ...]
//   crosscheck merge RESULTS.json|DIR ... -o DIR [--junit FILE]
//   crosscheck bench [SCENE|DIR ...] [--method all|LIST] [--frames N] [--warmup N] [--threads N]
//                    [--softraster-no-avx512] [-o FILE.json]
//   crosscheck chart BENCH.json [-o CHART.svg]
//   crosscheck stability [SCENE|DIR ...] [--frames N] [--threads N] [--json FILE]
//   crosscheck view SCENE [--set KEY.PATH=VALUE ...] [--script FILE] [-o|--screenshots DIR]
// render, compare and view also take --method NAME (options.hpp kMethods: exact, exact-scalar, scanline, trapezoid,
// barycentric), --affine (a course method's varyings interpolated affinely) and --threads N (softraster's);
// every command that renders takes --softraster-fma and --softraster-deviations driver|spec.
// Exit status (README, "Exit status"): 0 success / within tolerance / nothing unexpected; 1
// outside tolerance or an unexpected conformance result; 2 anything that kept the comparison from
// happening: bad usage, a scene or file that cannot be loaded, a renderer's error, an unwritable
// output.
// This file only sets up CLI11 and hands the parsed options to one subcommand in cli/
// (cli/commands.hpp); a parse error is exit status 2 with the usage below, a bad value of a
// number or method option one error line naming the option, exit status 2.
#include "cli/commands.hpp"
#include "view/controls.hpp"
#include "view/script.hpp"

#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

// A whole number option in min..max, or nullopt after printing one error line naming it.
std::optional<unsigned> wholeNumber(const char* option, const std::string& text, unsigned min, unsigned max) {
  unsigned value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < min || value > max) {
    std::fprintf(stderr, "crosscheck: %s %s: expected a whole number from %u to %u\n", option, text.c_str(), min, max);
    return std::nullopt;
  }
  return value;
}

// A number of seconds in (0, max], or 0; nullopt after printing one error line naming the option.
std::optional<double> seconds(const char* option, const std::string& text, double max) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !(value >= 0 && value <= max)) {
    std::fprintf(stderr, "crosscheck: %s %s: expected a number of seconds from 0 (none) to %g\n", option, text.c_str(), max);
    return std::nullopt;
  }
  return value;
}

constexpr unsigned kMaxThreads = 1024;
constexpr double kMaxTimeoutSeconds = 7 * 24 * 3600;
constexpr unsigned kMaxMemoryLimitMegabytes = 1u << 26;  // 64 TB

constexpr const char* kUsage =
    "usage: crosscheck render SCENE --renderer soft|vulkan -o OUT.png [--depth-out OUT.png]\n"
    "       crosscheck compare SCENE [-o DIR] [--json]\n"
    "       crosscheck conformance [SCENE|DIR ...] [--expectations FILE] [--jobs N] [--shard I/N] [--junit FILE] "
    "[-o DIR] [--timeout SECONDS] [--memory-limit MB] [--set KEY.PATH=VALUE ...]\n"
    "       crosscheck report [SCENE|DIR ...] -o DIR [--baseline DIR] [--no-chart] [--chart-frames N] [--expectations FILE] [--jobs N] "
    "[--shard I/N] [--junit FILE] [--timeout SECONDS] [--memory-limit MB] [--set KEY.PATH=VALUE ...]\n"
    "       crosscheck merge RESULTS.json|DIR ... -o DIR [--junit FILE]\n"
    "       crosscheck bench [SCENE|DIR ...] [--method all|LIST] [--frames N] [--warmup N] [--threads N]\n"
    "                        [--softraster-no-avx512] [-o FILE.json]\n"
    "       crosscheck chart BENCH.json [-o CHART.svg]\n"
    "       crosscheck stability [SCENE|DIR ...] [--frames N] [--threads N] [--json FILE]\n"
    "       crosscheck view SCENE [--set KEY.PATH=VALUE ...] [--script FILE] [-o|--screenshots DIR]\n"
    "       (crosscheck SUBCOMMAND --help for every option)";

// softraster's method names, "exact, exact-scalar, ...", for usage and errors.
std::string methodList() {
  std::string list;
  for (softraster::Method m : softraster::kMethods) list += (list.empty() ? "" : ", ") + std::string(softraster::methodName(m));
  return list;
}

// Flags several subcommands share, as typed.
struct CommonFlags {
  std::vector<std::string> overrides;
  std::string device;
  bool validation = false;
  std::string fma = "auto";
  std::string deviations = "driver";  // --softraster-deviations: lavapipe's behaviour or the spec's
  std::string softrasterDepth = "z";  // render only: "inverse-z" is the course's 1/z buffer
  std::string method = "exact";       // render, compare and view: a name of kMethods
  bool affine = false;                // render and compare: affine varyings (course methods only)
  std::string threadsText = "0";      // render, compare and view: softraster's threads, 0 = every core
  unsigned threads = 0;               // threadsText, once checked()

  // Checks method and threads; false after printing one error line.
  bool checked() {
    if (!softraster::methodFromName(method)) {
      std::fprintf(stderr, "crosscheck: --method %s: expected one of %s\n", method.c_str(), methodList().c_str());
      return false;
    }
    if (affine && !softraster::isCourseMethod(*softraster::methodFromName(method))) {
      std::fprintf(stderr, "crosscheck: --affine: applies only to the course's methods (scanline, trapezoid, barycentric), "
                   "not to --method %s\n", method.c_str());
      return false;
    }
    const auto parsed = wholeNumber("--threads", threadsText, 0, kMaxThreads);
    if (!parsed) return false;
    threads = *parsed;
    return true;
  }

  softraster::ContextOptions softraster() const {
    softraster::ContextOptions options;
    options.method = *softraster::methodFromName(method);
    options.affineVaryings = affine;
    options.threads = threads;
    if (fma != "auto") options.fusedMultiplyAdd = fma == "fused";
    if (deviations == "spec") options.deviations = softraster::Deviations::Spec;
    if (softrasterDepth == "inverse-z") options.depthMode = softraster::DepthMode::InverseZ;
    return options;
  }
  vkref::DeviceOptions deviceOptions() const {
    vkref::DeviceOptions options;
    options.deviceName = device;
    options.validation = validation;
    return options;
  }
  crosscheck::cli::SceneOptions sceneOptions(const std::string& scene) const {
    return {scene, overrides, deviceOptions(), softraster()};
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"crosscheck: softraster against Vulkan (lavapipe), scene by scene"};
  app.require_subcommand(1);
  CommonFlags common;
  auto addDevice = [&](CLI::App* cmd) {
    cmd->add_option("--device", common.device, "Vulkan device name substring (default: lavapipe)");
    cmd->add_flag("--validation", common.validation, "Enable VK_LAYER_KHRONOS_validation (in a suite, a message makes the scene Crash)");
    cmd->add_option("--softraster-fma", common.fma,
                    "How softraster rounds lavapipe's fmuladd: auto (as this CPU, like lavapipe), fused or separate; "
                    "the setting lavapipe does not use shows how much a scene depends on it")
        ->check(CLI::IsMember({"auto", "fused", "separate"}));
    cmd->add_option("--softraster-deviations", common.deviations,
                    "Where lavapipe deviates from the Vulkan spec (docs/lavapipe-rules.md, Deviations), softraster follows "
                    "the driver (default) or the spec; spec shows how much a scene depends on the deviation")
        ->check(CLI::IsMember({"driver", "spec"}));
  };
  auto addCommon = [&](CLI::App* cmd) {
    cmd->add_option("--set", common.overrides, "Override a scene value, e.g. camera.yaw=90 (repeatable)");
    cmd->add_option("--method", common.method,
                    "softraster's method: exact (lavapipe's rules, SIMD fast path where possible, default), exact-scalar "
                    "(the same bits, one pixel at a time), or one of the course's: scanline, trapezoid, barycentric "
                    "(charted against Vulkan, not bit-identical)");
    cmd->add_flag("--affine", common.affine,
                  "With a course method: interpolate perspective varyings linearly in screen space (affine) instead of "
                  "perspective-correct");
    cmd->add_option("--threads", common.threadsText, "softraster's drawing threads; 0 (default) = every core");
    addDevice(cmd);
  };

  std::string scenePath, renderer = "soft", output, depthOutput, outDir;
  std::vector<float> depthRange;
  bool json = false;

  CLI::App* render = app.add_subcommand("render", "Render one scene with one renderer");
  render->add_option("SCENE", scenePath, "Scene file")->required();
  render->add_option("--renderer", renderer, "soft (softraster) or vulkan (lavapipe)")
      ->check(CLI::IsMember({"soft", "vulkan"}))
      ->capture_default_str();
  render->add_option("-o,--output", output, "Colour PNG to write")->required();
  render->add_option("--depth-out", depthOutput, "Depth view PNG to write");
  render->add_option("--softraster-depth", common.softrasterDepth,
                     "softraster's depth buffer: z (Vulkan's z/w, default) or inverse-z (the course's 1/z buffer, "
                     "not a Vulkan mode)")
      ->check(CLI::IsMember({"z", "inverse-z"}));
  render->add_option("--depth-range", depthRange, "Depth mapped to black..white (LO HI); default: the image's range")
      ->expected(2);
  addCommon(render);

  CLI::App* compare = app.add_subcommand("compare", "Render one scene with both renderers and compare");
  compare->add_option("SCENE", scenePath, "Scene file")->required();
  // -o/--output on every subcommand that writes files; --out, the old name, still works.
  compare->add_option("-o,--output,--out", outDir, "Directory for soft.png, vulkan.png, diff.png and depth views");
  compare->add_flag("--json", json, "Print one JSON object instead of text");
  addCommon(compare);

  crosscheck::cli::SuiteCommand suite;
  std::string reportDir, baselineDir;
  int jobs = 1;
  std::string timeoutText = "0", memoryLimitText = std::to_string(crosscheck::kDefaultMemoryLimitMegabytes);
  const auto addSuite = [&](CLI::App* cmd) {
    cmd->add_option("SCENES", suite.inputs,
                    "Scene files and directories (their *.json files); default: scenes/ of the current directory");
    cmd->add_option("--expectations", suite.expectationsFile,
                    "Known results, lines 'SCENE,STATUS # reason' (SCENE: file stem; STATUS: Pass, Fail, Crash, Timeout, Skip)");
    cmd->add_option("-j,--jobs", jobs, "Scenes rendered in parallel (worker processes, one Vulkan renderer each)")
        ->check(CLI::Range(1, 1024));
    cmd->add_option("--timeout", timeoutText,
                    "Seconds a scene may take before its worker is killed and it is a Timeout; 0 (default) = none");
    cmd->add_option("--memory-limit", memoryLimitText,
                    "Address space of each worker process in MB, past which an allocation fails and the scene is a "
                    "Crash (out of memory); 0 = none; default " + memoryLimitText);
    cmd->add_option("--shard", suite.shard, "Run slice I of N (1-based: 1/3, 2/3, 3/3); scene k goes to shard k mod N + 1");
    cmd->add_option("--junit", suite.junitFile, "Write JUnit XML to this file");
    cmd->add_option("--set", suite.overrides, "Override a value in every scene, e.g. camera.yaw=90 (repeatable)");
    addDevice(cmd);
  };
  CLI::App* conformance =
      app.add_subcommand("conformance", "Cross-check every scene of a suite; exit 0 when nothing unexpected happened");
  addSuite(conformance);
  conformance->add_option("-o,--output,--out", outDir, "Write soft/vulkan/diff/depth PNGs to DIR/<scene>/");
  CLI::App* reportCommand =
      app.add_subcommand("report", "Run the suite like conformance and write an HTML report to DIR/index.html");
  addSuite(reportCommand);
  reportCommand->add_option("-o,--output", reportDir, "Report directory")->required();
  bool noChart = false;
  std::string chartFramesText = std::to_string(crosscheck::cli::kDefaultChartFrames);
  reportCommand->add_flag("--no-chart", noChart,
                          "Leave out the speed-vs-accuracy chart (every method and option drawn a few timed frames "
                          "per scene) and the stability table");
  reportCommand->add_option("--chart-frames", chartFramesText,
                            "Timed frames per method and option for the chart (default " + chartFramesText + ")");
  reportCommand->add_option("--baseline", baselineDir,
                            "An earlier run's output directory (or its results.json): mark new failures, fixed scenes "
                            "and changed metrics against it");

  crosscheck::cli::MergeCommand merge;
  CLI::App* mergeCommand = app.add_subcommand(
      "merge", "Merge the results.json of N shards (--shard I/N) into one report, JUnit file and results.json");
  mergeCommand->add_option("RESULTS", merge.inputs, "Each shard's results.json, or the output directory holding it")
      ->required();
  mergeCommand->add_option("-o,--output", merge.outDir,
                           "Directory for index.html, results.json, junit.xml and every scene's images (copied)")
      ->required();
  mergeCommand->add_option("--junit", merge.junitFile, "Write the JUnit XML here instead of DIR/junit.xml");

  crosscheck::cli::BenchCommand bench;
  std::string framesText = "15", warmupText = "3", benchThreadsText = "0", benchMethods = "exact,exact-scalar";
  CLI::App* benchCommand = app.add_subcommand(
      "bench", "Time steady-state frames of softraster (its methods) and lavapipe, and their agreement");
  benchCommand->add_option("SCENES", bench.inputs,
                           "Scene files and directories (their *.json files); default: scenes/bench of the current "
                           "directory");
  benchCommand->add_option("--method", benchMethods,
                           "softraster's methods to time: all (" + methodList() +
                               ") or a comma-separated list of them, a course method optionally as NAME+affine "
                               "(affine varyings); default exact,exact-scalar");
  benchCommand->add_option("--frames", framesText, "Timed frames per renderer (default 15)");
  benchCommand->add_option("--warmup", warmupText, "Untimed frames per renderer before them (default 3)");
  benchCommand->add_option("--threads", benchThreadsText,
                           "softraster's threads and lavapipe's LP_NUM_THREADS; 0 (default) = every core");
  benchCommand->add_option("-o,--output,--json", bench.jsonFile, "Write the results as JSON to this file");
  bool benchNoAvx512 = false;
  benchCommand->add_flag("--softraster-no-avx512", benchNoAvx512,
                         "softraster's fast path without AVX-512 even where the CPU has it (AVX2 only, the same "
                         "bits): times the AVX2 path on an AVX-512 machine");
  addDevice(benchCommand);

  crosscheck::cli::ChartCommand chart;
  CLI::App* chartCommand =
      app.add_subcommand("chart", "Write a bench JSON's speed-vs-accuracy chart as a standalone SVG");
  chartCommand->add_option("BENCH", chart.benchJson, "A bench JSON (crosscheck bench --json FILE)")->required();
  chartCommand->add_option("-o,--output", chart.output, "The SVG to write (default: BENCH with .svg)");

  crosscheck::cli::StabilityCommand stability;
  std::string stabilityFramesText = "3", stabilityThreadsText = "0";
  CLI::App* stabilityCommand = app.add_subcommand(
      "stability", "Draw every stability case with every method and option against lavapipe: wrong pixels, cracks, "
                   "double hits, time; exit 0 when exact passes every case");
  stabilityCommand->add_option("SCENES", stability.inputs,
                               "Scene files and directories (their *.json files); default: scenes/stability of the "
                               "current directory");
  stabilityCommand->add_option("--frames", stabilityFramesText, "Timed frames per variant (default 3)");
  stabilityCommand->add_option("--threads", stabilityThreadsText, "softraster's threads; 0 (default) = every core");
  stabilityCommand->add_option("-o,--output,--json", stability.jsonFile, "Write the results as JSON to this file");
  addDevice(stabilityCommand);

  crosscheck::cli::ViewCommand viewArgs;
  CLI::App* viewCommand = app.add_subcommand(
      "view", "A window: the scene rendered live by softraster and Vulkan (lavapipe), compared frame by frame");
  viewCommand->add_option("SCENE", scenePath, "Scene file")->required();
  viewCommand->add_option("--script", viewArgs.script, "Keys and frames from FILE instead of the keyboard (format below)");
  viewCommand->add_option("-o,--output,--screenshots", viewArgs.outDir,
                          "Folder for screenshots and saved scenes (default out/view)");
  addCommon(viewCommand);
  {
    std::string footer = "\nKeys (one step a frame while held; the status under the picture shows frame times and metrics):\n";
    for (const std::string& line : crosscheck::view::controlLines()) footer += "  " + line + "\n";
    char steps[160];
    std::snprintf(steps, sizeof steps, "Steps a frame: move %g scene units, turn %g degrees, light %g units, time %g s.\n",
                  crosscheck::view::kMoveStep, crosscheck::view::kTurnStep, crosscheck::view::kLightStep,
                  crosscheck::view::kTimeStep);
    footer += steps;
    footer += "Save as scene writes the scene file with the changed camera, light and time as --set overrides\n"
              "applied (OBJ paths made relative to the folder) and NAME.soft.png, NAME.vulkan.png, NAME.diff.png.\n\n" +
              crosscheck::view::scriptHelp() +
              "Without a display (DISPLAY unset) it is one error line and exit 2; run it under xvfb-run -a for scripts.";
    viewCommand->footer(footer);
  }

  // CLI11 would call an unknown subcommand "A subcommand is required" or an extra argument.
  if (argc > 1 && argv[1][0] != '-') {
    const std::string name = argv[1];
    bool known = false;
    for (const CLI::App* sub : app.get_subcommands({})) known = known || sub->get_name() == name;
    if (!known) {
      std::fprintf(stderr, "crosscheck: unknown subcommand '%s' (expected render, compare, conformance, report, merge, "
                   "bench, chart, stability or view)\n%s\n",
                   name.c_str(), kUsage);
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "crosscheck: %s\n%s\n", e.what(), kUsage);
    return 2;
  }

  if ((render->parsed() || compare->parsed() || viewCommand->parsed()) && !common.checked()) return 2;
  if (viewCommand->parsed()) {
    viewArgs.options = common.sceneOptions(scenePath);
    return crosscheck::cli::viewCommand(viewArgs);
  }
  if (benchCommand->parsed()) {
    const auto frames = wholeNumber("--frames", framesText, 1, 100000);
    if (!frames) return 2;
    const auto warmup = wholeNumber("--warmup", warmupText, 0, 100000);
    if (!warmup) return 2;
    const auto threads = wholeNumber("--threads", benchThreadsText, 0, kMaxThreads);
    if (!threads) return 2;
    const auto methods = crosscheck::parseBenchMethods(benchMethods);
    if (!methods) {
      std::fprintf(stderr,
                   "crosscheck: --method %s: expected all or a comma-separated list of %s (a course method may be "
                   "NAME+affine)\n",
                   benchMethods.c_str(), methodList().c_str());
      return 2;
    }
    bench.methods = *methods;
    bench.frames = *frames;
    bench.warmup = *warmup;
    bench.threads = *threads;
    bench.device = common.deviceOptions();
    bench.softraster = common.softraster();
    bench.softraster.allowAvx512 = !benchNoAvx512;
    return crosscheck::cli::benchCommand(bench);
  }
  if (chartCommand->parsed()) return crosscheck::cli::chartCommand(chart);
  if (stabilityCommand->parsed()) {
    const auto frames = wholeNumber("--frames", stabilityFramesText, 1, 1000);
    if (!frames) return 2;
    const auto threads = wholeNumber("--threads", stabilityThreadsText, 0, kMaxThreads);
    if (!threads) return 2;
    stability.frames = *frames;
    stability.device = common.deviceOptions();
    stability.softraster = common.softraster();
    stability.softraster.threads = *threads;
    return crosscheck::cli::stabilityCommand(stability);
  }
  if (render->parsed()) {
    if (depthRange.size() == 2 && !(std::isfinite(depthRange[0]) && std::isfinite(depthRange[1]) && depthRange[0] < depthRange[1])) {
      std::fprintf(stderr, "crosscheck: --depth-range %g %g: expected two finite numbers LO < HI\n", depthRange[0], depthRange[1]);
      return 2;
    }
    return crosscheck::cli::renderCommand({common.sceneOptions(scenePath), renderer, output, depthOutput, depthRange});
  }
  if (compare->parsed()) return crosscheck::cli::compareCommand({common.sceneOptions(scenePath), outDir, json});
  if (mergeCommand->parsed()) {
    for (int i = 0; i < argc; ++i) merge.commandLine += (i ? " " : "") + std::string(argv[i]);
    return crosscheck::cli::mergeCommand(merge);
  }
  const auto timeout = seconds("--timeout", timeoutText, kMaxTimeoutSeconds);
  if (!timeout) return 2;
  const auto memoryLimit = wholeNumber("--memory-limit", memoryLimitText, 0, kMaxMemoryLimitMegabytes);
  if (!memoryLimit) return 2;
  suite.jobs = static_cast<unsigned>(jobs);
  suite.timeoutSeconds = *timeout;
  suite.memoryLimitMegabytes = *memoryLimit;
  suite.device = common.deviceOptions();
  suite.softraster = common.softraster();
  for (int i = 0; i < argc; ++i) suite.commandLine += (i ? " " : "") + std::string(argv[i]);
  if (reportCommand->parsed()) {
    const auto chartFrames = wholeNumber("--chart-frames", chartFramesText, 1, 1000);
    if (!chartFrames) return 2;
    return crosscheck::cli::reportCommand(suite, reportDir, baselineDir, noChart ? 0 : *chartFrames);
  }
  return crosscheck::cli::conformanceCommand(suite, outDir);
}
