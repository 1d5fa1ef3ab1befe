// Suite collection and sharding (see suite.hpp).
#include "run/suite.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <system_error>

namespace crosscheck {
namespace {

using softraster::Status;

std::string identity(const std::filesystem::path& path) {
  std::error_code ec;
  const auto canonical = std::filesystem::weakly_canonical(path, ec);
  return (ec ? path.lexically_normal() : canonical).string();
}

bool parseCount(std::string_view text, std::size_t* value) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), *value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

softraster::Result<std::vector<SceneEntry>> collectScenes(const std::vector<std::string>& inputs) {
  const bool useDefault = inputs.empty();
  std::vector<std::string> roots = useDefault ? std::vector<std::string>{std::string(kDefaultSceneDir)} : inputs;
  if (std::error_code ec; useDefault && std::filesystem::is_directory(kDefaultStabilitySceneDir, ec)) {
    roots.emplace_back(kDefaultStabilitySceneDir);
  }
  std::vector<std::filesystem::path> files;
  for (const std::string& root : roots) {
    const std::filesystem::path path(root);
    std::error_code ec;
    if (!std::filesystem::is_directory(path, ec)) {
      if (useDefault) {
        return Status::error(root + ": no such directory (run crosscheck from the repository root, or name scene files "
                                    "or directories)");
      }
      if (!std::filesystem::exists(path, ec) && path.extension() != ".json") {
        return Status::error(root + ": no such file or directory");  // a mistyped folder, most likely
      }
      files.push_back(path);  // a file, or a missing scene file that will be reported as a Crash
      continue;
    }
    std::size_t found = 0;
    std::filesystem::directory_iterator it(path, ec), end;
    for (; !ec && it != end; it.increment(ec)) {
      std::error_code typeError;
      if (it->path().extension() == ".json" && !it->is_directory(typeError)) {
        files.push_back(it->path());
        ++found;
      }
    }
    if (ec) return Status::error(root + ": cannot read directory: " + ec.message());
    if (found == 0) return Status::error(root + ": no *.json scene files in this directory");
  }

  std::sort(files.begin(), files.end(), [](const auto& a, const auto& b) { return a.generic_string() < b.generic_string(); });
  std::vector<SceneEntry> suite;
  std::map<std::string, std::filesystem::path> seenFiles;  // identity -> path
  std::map<std::string, std::filesystem::path> seenNames;  // name -> path
  for (const auto& file : files) {
    if (!seenFiles.emplace(identity(file), file).second) continue;
    const std::string name = file.stem().string();
    if (name.empty()) return Status::error(file.string() + ": not a scene file name");
    if (const auto [it, inserted] = seenNames.emplace(name, file); !inserted) {
      return Status::error(file.string() + ": scene name '" + name + "' is already used by " + it->second.string() +
                           " (scene names are file stems and must be unique in a run)");
    }
    suite.push_back({name, file});
  }
  return suite;
}

softraster::Result<Shard> parseShard(std::string_view text) {
  const auto slash = text.find('/');
  Shard shard;
  if (slash == std::string_view::npos || !parseCount(text.substr(0, slash), &shard.index) ||
      !parseCount(text.substr(slash + 1), &shard.count)) {
    return Status::error("--shard " + std::string(text) + ": expected I/N with whole numbers, e.g. 1/3");
  }
  if (shard.count == 0 || shard.index == 0 || shard.index > shard.count) {
    return Status::error("--shard " + std::string(text) + ": needs 1 <= I <= N (shards are numbered from 1)");
  }
  return shard;
}

bool isStabilityCase(const SceneEntry& entry) { return entry.path.parent_path().filename() == "stability"; }

bool inShard(std::size_t position, Shard shard) { return position % shard.count == shard.index - 1; }

std::vector<SceneEntry> selectShard(const std::vector<SceneEntry>& suite, Shard shard) {
  std::vector<SceneEntry> slice;
  for (std::size_t k = 0; k < suite.size(); ++k) {
    if (inShard(k, shard)) slice.push_back(suite[k]);
  }
  return slice;
}

}  // namespace crosscheck
