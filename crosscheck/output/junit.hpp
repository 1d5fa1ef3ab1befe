// JUnit XML for CI systems: one <testsuite> with one <testcase> per scene. Skip and ExpectedFail
// are <skipped message="...">, Fail and UnexpectedPass <failure>, Crash <error>; every testcase's
// <system-out> holds its metrics, limits, timings and image paths. Times are in seconds.
// Deliberately no XML library: the writer builds text and escapes every value (markup.hpp).
#pragma once

#include "run/conformance.hpp"

#include <softraster/status.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace crosscheck {

struct JUnitInfo {
  std::string suiteName = "crosscheck.conformance";
  double seconds = 0;        // wall time of the whole run
  std::string timestamp;     // ISO 8601, optional
};

std::string junitXml(const std::vector<SceneResult>& results, const JUnitInfo& info);

// Writes the file (creating its folder); the error is "FILE: cannot write JUnit file: reason".
softraster::Status writeJUnit(const std::filesystem::path& file, const std::vector<SceneResult>& results,
                              const JUnitInfo& info);

}  // namespace crosscheck
