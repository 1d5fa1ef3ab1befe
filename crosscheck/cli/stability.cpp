// crosscheck stability [SCENE|DIR ...] [--frames N] [--json FILE]: every stability case drawn
// with every variant (run/stability.hpp), printed as a table and written as JSON
// (output/stability_output.hpp). Exit 0 when `exact` passes every case, 1 when it does not, 2
// when the cases cannot be collected, the JSON cannot be written or no Vulkan device opens.
// Deliberately no timing or formatting of its own.
#include "cli/commands.hpp"

#include "output/markup.hpp"
#include "output/stability_output.hpp"
#include "run/stability.hpp"
#include "run/suite.hpp"

#include <cstdio>
#include <fstream>

namespace crosscheck::cli {

int stabilityCommand(const StabilityCommand& command) {
  const auto suite = collectScenes(command.inputs.empty() ? std::vector<std::string>{std::string(kDefaultStabilitySceneDir)}
                                                          : command.inputs);
  if (!suite) return failWith(suite.error());
  if (!command.jsonFile.empty() && !canWrite(command.jsonFile)) {  // proven before the run
    return failWith(command.jsonFile + ": cannot write this file");
  }
  StabilityOptions options;
  options.frames = command.frames;
  options.device = command.device;
  options.softraster = command.softraster;
  options.onCase = [](std::size_t position, std::size_t count, const StabilityCase& c) {
    std::fprintf(stderr, "stability: [%zu/%zu] %s\n", position + 1, count, c.entry.path.string().c_str());
    std::fflush(stderr);
  };
  const auto results = runStability(*suite, options);
  if (!results) return failWith(results.status());
  std::fputs(stabilityTable(*results).c_str(), stdout);
  std::fflush(stdout);
  if (!command.jsonFile.empty()) {
    const softraster::Status written = writeDocument(command.jsonFile, stabilityJson(*results), "the stability JSON");
    if (!written) return failWith(written);
    std::printf("JSON: %s\n", command.jsonFile.c_str());
  }
  return results->referencePasses() ? 0 : 1;
}

}  // namespace crosscheck::cli
