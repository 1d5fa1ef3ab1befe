// results.json on disk (see results_file.hpp).
#include "results/results_file.hpp"

#include "results/results_json.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

namespace crosscheck {
namespace {

namespace fs = std::filesystem;
using softraster::Status;

fs::path absoluteNormal(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  return (ec ? path : absolute).lexically_normal();
}

// `path` relative to `dir` ("." for dir itself); absolute when there is no relative way.
fs::path relativeTo(const fs::path& path, const fs::path& dir) {
  if (path.empty()) return path;
  const fs::path absolute = absoluteNormal(path);
  const fs::path relative = absolute.lexically_relative(absoluteNormal(dir));
  return relative.empty() ? absolute : relative;
}

// The other way: a stored path read against the file's folder (an absolute one stays).
fs::path resolvedFrom(const fs::path& stored, const fs::path& dir) {
  if (stored.empty()) return stored;
  return (dir / stored).lexically_normal();
}

}  // namespace

fs::path resultsFileOf(const fs::path& path) {
  std::error_code ec;
  return fs::is_directory(path, ec) ? path / kResultsFileName : path;
}

Status writeResultsFile(const fs::path& dir, const RunResults& run) {
  RunResults stored = run;
  stored.junitFile = relativeTo(run.junitFile, dir);
  for (SceneResult& r : stored.scenes) r.imageRoot = relativeTo(r.imageRoot, dir);
  const std::string text = runResultsToJson(stored).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  const fs::path file = dir / kResultsFileName;
  std::error_code ec;
  fs::create_directories(dir, ec);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  if (out) out << text;
  if (!out) return Status::error(file.string() + ": cannot write results file: " + std::strerror(errno));
  return {};
}

softraster::Result<RunResults> readResultsFile(const fs::path& path) {
  const fs::path file = resultsFileOf(path);
  const std::string name = file.string();
  std::error_code ec;
  if (!fs::exists(file, ec)) return Status::error(name + ": cannot read results file: file not found");
  if (fs::is_directory(file, ec)) return Status::error(name + ": cannot read results file: is a directory");
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  if (!in) return Status::error(name + ": cannot read results file: " + std::strerror(errno));
  nlohmann::json value;
  try {
    value = nlohmann::json::parse(buffer.str());
  } catch (const nlohmann::json::exception& e) {
    return Status::error(name + ": not JSON: " + e.what());
  }
  auto run = runResultsFromJson(value);
  if (!run) return Status::error(name + ": " + run.error());
  const fs::path dir = file.parent_path();
  run->junitFile = resolvedFrom(run->junitFile, dir);
  for (SceneResult& r : run->scenes) r.imageRoot = resolvedFrom(r.imageRoot, dir);
  return run;
}

}  // namespace crosscheck
