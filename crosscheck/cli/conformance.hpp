// The `conformance` and `report` subcommands behind the command line: check the arguments, run
// the suite, print one line per scene (in suite order), a progress line when stderr is a terminal,
// the summary and, last, "N passed, N failed[, N skipped]"; write JUnit, images and the report.
// Exit status: 0 when nothing unexpected happened, 1 when something did (or an output file could
// not be written after the run), 2 for bad usage, an unreadable or malformed expectations file, a
// suite that cannot be collected, or an output folder that cannot be written.
// Deliberately no command-line parsing here (main.cpp does that with CLI11).
#pragma once

#include <softraster/pipeline.hpp>
#include <vkref/renderer.hpp>

#include <string>
#include <vector>

namespace crosscheck {

struct ConformanceCommand {
  std::vector<std::string> inputs;   // scene files and directories; empty: scenes/
  std::string expectationsFile;
  unsigned jobs = 1;
  std::string shard;                 // "I/N", 1-based; empty: the whole suite
  std::string junitFile;
  std::string outDir;                // conformance --out: per-scene PNGs
  std::string reportDir;             // report -o: index.html, PNGs and pixel data; empty: no report
  vkref::DeviceOptions device;
  softraster::ContextOptions softraster;
  std::string commandLine;           // shown in the report
};

int runConformanceCommand(const ConformanceCommand& command);

}  // namespace crosscheck
