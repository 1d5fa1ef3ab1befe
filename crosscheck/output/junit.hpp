// JUnit XML for CI systems: one <testsuite> with one <testcase> per scene. Skip and ExpectedFail
// are <skipped message="...">, Fail and UnexpectedPass <failure>, Crash and Timeout <error>;
// every testcase's <system-out> holds its metrics, limits, timings and image paths. Times are in
// seconds.
// Reads a run's results (results.hpp) only: the suite name, time and timestamp are the run's.
// Test identity does not depend on sharding: the testsuite name and every classname are the
// suite's name and each testcase's name the scene's, whichever shard ran it (a shard is a
// <property name="shard" value="I/N"> of the testsuite), so CI history survives a new shard count
// and the JUnit of merged shards equals an unsharded run's but for times.
// Deliberately no XML library: the writer builds text and escapes every value (markup.hpp).
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <filesystem>
#include <string>

namespace crosscheck {

// The <testsuite> timestamp is RunResults::finished as ISO 8601 (UTC), left out when unknown.
std::string junitXml(const RunResults& run);

// Writes the file (creating its folder); the error is "FILE: cannot write JUnit file: reason".
softraster::Status writeJUnit(const std::filesystem::path& file, const RunResults& run);

}  // namespace crosscheck
