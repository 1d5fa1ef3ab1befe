// results.json: a whole run's RunResults (results_json.hpp) as a file in the run's output folder,
// which `conformance -o DIR` and `report -o DIR` write, `merge` reads from each shard and
// `report --baseline DIR` compares against. Format and fields: docs/results-json.md.
// Paths the run wrote (the image root, the JUnit file) are stored relative to the folder the file
// is in, so the folder can be moved or downloaded elsewhere as a whole; reading resolves them
// against the file's folder again. Scene paths stay as the run was given them (they name the
// suite, relative to where it was started).
// Deliberately no merging and no comparing here (merge.hpp, baseline.hpp), and text only: the file
// is for people and CI tools as much as for crosscheck.
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <filesystem>
#include <string_view>

namespace crosscheck {

inline constexpr std::string_view kResultsFileName = "results.json";

// Writes dir/results.json; the error is "FILE: cannot write results file: reason".
softraster::Status writeResultsFile(const std::filesystem::path& dir, const RunResults& run);

// Reads a results.json, or DIR/results.json when `path` is a folder. Errors are one line naming
// the file: "FILE: cannot read results file: reason", "FILE: not JSON: ...", "FILE: results
// JSON: /PLACE: what is wrong" (a field, or a format version this crosscheck does not read).
softraster::Result<RunResults> readResultsFile(const std::filesystem::path& path);

// The file readResultsFile reads for `path`: itself, or path/results.json for a folder.
std::filesystem::path resultsFileOf(const std::filesystem::path& path);

}  // namespace crosscheck
