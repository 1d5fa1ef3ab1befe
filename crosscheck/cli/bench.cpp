// crosscheck bench: steady-state frame times of softraster (the methods asked for: exact and
// exact-scalar by default) and of lavapipe on each scene, with their agreement (see
// commands.hpp): collects and loads the scenes (any that
// cannot be loaded is exit 2 before anything runs), measures the machine, runs the bench
// (run/bench.hpp), prints the table and writes the JSON.
// Deliberately no timing or formatting of its own (run/bench.cpp, output/bench_*), and no
// options beyond the run's size and its methods: a bench run always has lavapipe.
#include "cli/commands.hpp"

#include "output/bench_json.hpp"
#include "output/bench_table.hpp"
#include "run/bench.hpp"
#include "run/suite.hpp"
#include "scene/scene.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace crosscheck::cli {

int benchCommand(const BenchCommand& command) {
  if (command.frames < 1) return failWith("--frames must be at least 1");
  const auto suite = collectScenes(command.inputs.empty() ? std::vector<std::string>{std::string(kDefaultBenchDir)}
                                                          : command.inputs);
  if (!suite) return failWith(suite.error());
  std::vector<Scene> scenes;
  for (const SceneEntry& entry : *suite) {
    auto scene = loadScene(entry.path);
    if (!scene) return failWith(scene.error());
    scenes.push_back(std::move(*scene));
  }
  if (!command.jsonFile.empty() && !canWrite(command.jsonFile)) {  // proven before the run
    return failWith(command.jsonFile + ": cannot write this file");
  }

  BenchOptions options;
  options.frames = command.frames;
  options.warmup = command.warmup;
  options.threads = command.threads;
  options.device = command.device;
  options.softraster = command.softraster;
  options.methods = command.methods;
  options.onScene = [](std::size_t position, std::size_t count, const BenchScene& scene) {
    std::fprintf(stderr, "bench: [%zu/%zu] %s\n", position + 1, count, scene.scene.string().c_str());
    std::fflush(stderr);
  };
  const BenchMachine machine = measureMachine();
  const BenchResults results = runBench(scenes, options, machine);
  std::fputs(benchTable(results).c_str(), stdout);
  std::fflush(stdout);
  if (!command.jsonFile.empty()) {
    std::ofstream file(command.jsonFile, std::ios::trunc);
    file << benchJson(results);
    if (!file) {
      std::fprintf(stderr, "crosscheck: %s: cannot write this file\n", command.jsonFile.c_str());
      return 1;
    }
    std::printf("JSON: %s\n", command.jsonFile.c_str());
  }
  return results.allAgree() ? 0 : 1;
}

}  // namespace crosscheck::cli
