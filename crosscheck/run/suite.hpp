// The suite of a conformance run: which scene files it covers, in a stable order, and the slice
// of it that one shard runs.
// Arguments are scene files or directories; a directory contributes the *.json files directly in
// it (not its subdirectories; the default suite names scenes/stability/ besides scenes/). A scene's name is its file stem ("scenes/room.json" is "room"):
// expectations files, output folders and reports use it, so two scenes in one run may not share
// a name. The suite is sorted by path; a file named twice (or found twice) runs once.
// Deliberately no patterns or filters: name the files or folders to run.
#pragma once

#include <softraster/status.hpp>

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace crosscheck {

struct SceneEntry {
  std::string name;             // file stem
  std::filesystem::path path;   // as given, or directory as given / file name
};

// The default suite when no argument is given: the scenes/ directory of the current directory,
// and its stability/ folder (the stability cases) when there is one.
inline constexpr std::string_view kDefaultSceneDir = "scenes";
inline constexpr std::string_view kDefaultStabilitySceneDir = "scenes/stability";

// Whether a scene is a stability case: its file is in a folder named "stability" (the report
// counts its hits and lists it in the stability table).
bool isStabilityCase(const SceneEntry& entry);

// Collects the suite. A *.json path that does not exist is kept (it becomes a Crash when run, so
// the rest of the suite still runs). Errors (one line, naming the path): any other path that does
// not exist, a directory that cannot be read or holds no *.json file, two different scene files
// with one name.
softraster::Result<std::vector<SceneEntry>> collectScenes(const std::vector<std::string>& inputs);

// Shard I of N, 1-based: "1/3", "2/3", "3/3". Scene k of the sorted suite (0-based) belongs to
// shard (k mod N) + 1, so shards differ in size by at most one and every scene is in exactly one.
struct Shard {
  std::size_t index = 1;
  std::size_t count = 1;
};

// Parses "I/N" with 1 <= I <= N; the error is one line starting "--shard TEXT: ".
softraster::Result<Shard> parseShard(std::string_view text);

bool inShard(std::size_t position, Shard shard);

std::vector<SceneEntry> selectShard(const std::vector<SceneEntry>& suite, Shard shard);

}  // namespace crosscheck
