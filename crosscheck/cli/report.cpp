// crosscheck report: the conformance run (conformance.cpp) with each scene's images and pixel
// data in DIR/<scene>/, and the HTML page DIR/index.html over them (see commands.hpp).
#include "cli/commands.hpp"

#include "output/report/report.hpp"

#include <filesystem>

namespace crosscheck::cli {

int reportCommand(const SuiteCommand& command, const std::string& reportDir) {
  SuiteOutputs outputs;
  outputs.name = "report";
  outputs.imageDir = reportDir;
  outputs.pixelData = true;
  outputs.write = [&](const RunResults& run) { return writeReport(reportDir, run); };
  outputs.doneLine = "report: " + (std::filesystem::path(reportDir) / "index.html").string();
  return runSuite(command, outputs);
}

}  // namespace crosscheck::cli
