// Merging the results of N shards (`conformance --shard I/N` on N machines, each writing its
// results.json) into the record of one run over the whole suite, as if it had run unsharded:
// scenes in suite order, shard 1/1. Checked first, each error one line naming the file and the
// scene: every file was taken over the same suite (the same scene names and paths, in order) with
// the same rendering options and the same expectations (every entry's outcome and reason), and together they hold each scene of it exactly once (a scene in two
// files is duplicated, a scene in none missing).
// The merged run's timing is the shards' (finished: the latest; seconds: the longest, as shards run
// side by side; jobs: the most); its JUnit file and command line are the caller's to set.
// Deliberately no files here: the caller reads them (results_file.hpp), copies the images
// (output/artifacts.hpp) and writes the outputs.
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <filesystem>
#include <vector>

namespace crosscheck {

struct ShardResults {
  std::filesystem::path file;   // where it was read from, for errors
  RunResults run;
};

// Errors: "FILE: another suite than FIRST: ...", "FILE: other rendering options than FIRST: ...",
// "FILE: scene 'NAME' is not in its suite", "FILE: scene 'NAME' is also in OTHER (duplicated)",
// "FIRST: scene 'NAME' of the suite is in none of the N files (missing)", "no results to merge".
softraster::Result<RunResults> mergeShards(const std::vector<ShardResults>& shards);

}  // namespace crosscheck
