// Merging shards' results (see merge.hpp).
#include "results/merge.hpp"

#include <algorithm>
#include <map>
#include <string>

namespace crosscheck {
namespace {

using softraster::Status;

std::string quoted(const std::string& text) { return "'" + text + "'"; }

// Why two suites differ, or empty when they are the same.
std::string suiteDifference(const std::vector<SceneEntry>& a, const std::vector<SceneEntry>& b) {
  if (a.size() != b.size()) {
    return std::to_string(b.size()) + (b.size() == 1 ? " scene" : " scenes") + ", not " + std::to_string(a.size());
  }
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].name != b[i].name || a[i].path != b[i].path) {
      return "scene " + std::to_string(i + 1) + " is " + b[i].path.string() + ", not " + a[i].path.string();
    }
  }
  return "";
}

std::string expected(const Expectation* e) {
  if (!e) return "not listed";
  std::string text = "expected " + std::string(outcomeName(e->outcome));
  if (!e->reason.empty()) text += " (" + quoted(e->reason) + ")";
  return text;
}

// Why two runs applied different expectations, or empty when they agree on every scene's
// outcome and reason (line numbers and the file's path may differ).
std::string expectationsDifference(const std::optional<Expectations>& a, const std::optional<Expectations>& b,
                                   const std::string& aName) {
  if (!a && !b) return "";
  if (!a) return "applied " + quoted(b->file.string()) + ", not none";
  if (!b) return "applied none, not " + quoted(a->file.string());
  std::map<std::string, std::pair<const Expectation*, const Expectation*>> both;
  for (const auto& [name, e] : a->byScene) both[name].first = &e;
  for (const auto& [name, e] : b->byScene) both[name].second = &e;
  for (const auto& [name, pair] : both) {
    const auto& [ea, eb] = pair;
    if (ea && eb && ea->outcome == eb->outcome && ea->reason == eb->reason) continue;
    return "scene " + quoted(name) + ": " + expected(eb) + "; in " + aName + ": " + expected(ea);
  }
  return "";
}

}  // namespace

softraster::Result<RunResults> mergeShards(const std::vector<ShardResults>& shards) {
  if (shards.empty()) return Status::error("no results to merge");
  const ShardResults& first = shards.front();
  const std::string firstName = first.file.string();
  const std::vector<SceneEntry>& suite = first.run.suite;
  std::map<std::string, std::size_t> position;  // scene name -> position in the suite
  for (std::size_t i = 0; i < suite.size(); ++i) position.emplace(suite[i].name, i);

  std::vector<const SceneResult*> byPosition(suite.size(), nullptr);
  std::vector<const ShardResults*> from(suite.size(), nullptr);
  RunResults merged;
  merged.suite = suite;
  merged.suiteName = first.run.suiteName;
  merged.renderArguments = first.run.renderArguments;
  merged.expectations = first.run.expectations;
  for (const ShardResults& shard : shards) {
    const std::string name = shard.file.string();
    const RunResults& run = shard.run;
    if (const std::string why = suiteDifference(suite, run.suite); !why.empty() || run.suiteName != first.run.suiteName) {
      return Status::error(name + ": another suite than " + firstName + ": " +
                           (why.empty() ? "named " + quoted(run.suiteName) + ", not " + quoted(first.run.suiteName) : why));
    }
    if (run.renderArguments != first.run.renderArguments) {
      return Status::error(name + ": other rendering options than " + firstName + ": " + quoted(run.renderArguments) +
                           ", not " + quoted(first.run.renderArguments));
    }
    if (const std::string why = expectationsDifference(first.run.expectations, run.expectations, firstName); !why.empty()) {
      return Status::error(name + ": other expectations than " + firstName + ": " + why);
    }
    for (const SceneResult& r : run.scenes) {
      const auto it = position.find(r.entry.name);
      if (it == position.end() || suite[it->second].path != r.entry.path) {
        return Status::error(name + ": scene " + quoted(r.entry.name) + " is not in its suite");
      }
      if (from[it->second]) {
        return Status::error(name + ": scene " + quoted(r.entry.name) + " is also in " + from[it->second]->file.string() +
                             " (duplicated)");
      }
      byPosition[it->second] = &r;
      from[it->second] = &shard;
    }
    merged.finished = std::max(merged.finished, run.finished);
    merged.seconds = std::max(merged.seconds, run.seconds);
    merged.jobs = std::max(merged.jobs, run.jobs);
  }
  for (std::size_t i = 0; i < suite.size(); ++i) {
    if (!byPosition[i]) {
      return Status::error(firstName + ": scene " + quoted(suite[i].name) + " of the suite is in none of the " +
                           std::to_string(shards.size()) + (shards.size() == 1 ? " file" : " files") + " (missing)");
    }
    merged.scenes.push_back(*byPosition[i]);
  }
  return merged;
}

}  // namespace crosscheck
