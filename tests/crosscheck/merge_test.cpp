// Shards and their merge: results.json on disk (paths relative to its folder, the format version
// checked), mergeShards' checks (missing, duplicated, another suite, other rendering options) and
// order, a run against a baseline, JUnit identity whatever the shard, and the real command line:
// `report --shard I/3` three times then `merge` gives results.json byte for byte and JUnit equal
// to an unsharded run's but for timings. The merge command's error lines: conformance_cli_test.sh.
#include "output/junit.hpp"
#include "results/baseline.hpp"
#include "results/merge.hpp"
#include "results/results_file.hpp"
#include "results/results_json.hpp"

#include <softraster/options.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace {

using namespace crosscheck;
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kArtifacts = ARTIFACTS_DIR;

std::string readText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

SceneResult scene(const std::string& name, Outcome outcome) {
  SceneResult r;
  r.entry = {name, "scenes/" + name + ".json"};
  r.outcome = r.actual = outcome;
  return r;
}

// Shard `index` of `count` over a suite of the names, as `conformance --shard` records it.
RunResults shardOf(const std::vector<std::string>& names, std::size_t index, std::size_t count) {
  RunResults run;
  for (const std::string& name : names) run.suite.push_back({name, "scenes/" + name + ".json"});
  run.shard = {index, count};
  for (const SceneEntry& entry : selectShard(run.suite, run.shard)) run.scenes.push_back(scene(entry.name, Outcome::Pass));
  return run;
}

const std::vector<std::string> kNames = {"a", "b", "c", "d", "e"};

std::string mergeError(const std::vector<ShardResults>& shards) {
  const auto merged = mergeShards(shards);
  EXPECT_FALSE(merged);
  return merged ? std::string() : merged.error();
}

TEST(Merge, ShardsBecomeOneRunInSuiteOrder) {
  std::vector<ShardResults> shards;
  for (std::size_t i : {3u, 1u, 2u}) shards.push_back({"s" + std::to_string(i) + ".json", shardOf(kNames, i, 3)});
  shards[0].run.finished = 30, shards[1].run.finished = 10, shards[2].run.finished = 20;
  shards[0].run.seconds = 1, shards[1].run.seconds = 4, shards[2].run.seconds = 2;
  const auto merged = mergeShards(shards);
  ASSERT_TRUE(merged) << merged.error();
  ASSERT_EQ(merged->scenes.size(), kNames.size());
  for (std::size_t i = 0; i < kNames.size(); ++i) EXPECT_EQ(merged->scenes[i].entry.name, kNames[i]);
  EXPECT_EQ(merged->shard.count, 1u);
  EXPECT_EQ(merged->suite.size(), kNames.size());
  EXPECT_EQ(merged->finished, 30);
  EXPECT_EQ(merged->seconds, 4);
}

TEST(Merge, EachErrorNamesTheFileAndTheScene) {
  const ShardResults one{"one.json", shardOf(kNames, 1, 2)}, two{"two.json", shardOf(kNames, 2, 2)};
  EXPECT_EQ(mergeError({one}), "one.json: scene 'b' of the suite is in none of the 1 file (missing)");
  EXPECT_EQ(mergeError({one, one}), "one.json: scene 'a' is also in one.json (duplicated)");
  ShardResults overlapping{"three.json", shardOf(kNames, 1, 3)};  // a, d
  EXPECT_EQ(mergeError({one, two, overlapping}), "three.json: scene 'a' is also in one.json (duplicated)");
  ShardResults other{"other.json", shardOf({"a", "b", "c", "d", "f"}, 2, 2)};
  EXPECT_EQ(mergeError({one, other}), "other.json: another suite than one.json: scene 5 is scenes/f.json, not scenes/e.json");
  ShardResults shorter{"short.json", shardOf({"a", "b", "c"}, 2, 2)};
  EXPECT_EQ(mergeError({one, shorter}), "short.json: another suite than one.json: 3 scenes, not 5");
  ShardResults renamed = two;
  renamed.run.suiteName = "other";
  EXPECT_EQ(mergeError({one, renamed}), "two.json: another suite than one.json: named 'other', not 'crosscheck.conformance'");
  ShardResults options = two;
  options.run.renderArguments = "--softraster-fma separate";
  EXPECT_EQ(mergeError({one, options}), "two.json: other rendering options than one.json: '--softraster-fma separate', not ''");
  // Expectations: the same entries (line numbers and path aside), or one line naming the first scene that differs.
  Expectations known;
  known.file = "scenes/expectations.txt";
  known.byScene["c"] = {Outcome::Fail, "lavapipe rounds differently", 3};
  ShardResults withExpectations = one, sameExpectations = two;
  withExpectations.run.expectations = known;
  sameExpectations.run.expectations = known;
  sameExpectations.run.expectations->file = "elsewhere/expectations.txt";
  sameExpectations.run.expectations->byScene["c"].line = 7;
  const auto agreed = mergeShards({withExpectations, sameExpectations});
  ASSERT_TRUE(agreed) << agreed.error();
  ASSERT_TRUE(agreed->expectations);
  EXPECT_EQ(agreed->expectations->file, "scenes/expectations.txt");
  EXPECT_EQ(mergeError({withExpectations, two}), "two.json: other expectations than one.json: applied none, not 'scenes/expectations.txt'");
  EXPECT_EQ(mergeError({one, sameExpectations}), "two.json: other expectations than one.json: applied 'elsewhere/expectations.txt', not none");
  ShardResults skipping = sameExpectations;
  skipping.run.expectations->byScene["c"].outcome = Outcome::Skip;
  EXPECT_EQ(mergeError({withExpectations, skipping}),
            "two.json: other expectations than one.json: scene 'c': expected Skip ('lavapipe rounds differently'); "
            "in one.json: expected Fail ('lavapipe rounds differently')");
  ShardResults extra = sameExpectations;
  extra.run.expectations->byScene["a"] = {Outcome::Crash, "", 1};
  EXPECT_EQ(mergeError({withExpectations, extra}), "two.json: other expectations than one.json: scene 'a': expected Crash; in one.json: not listed");
  ShardResults stray = two;
  stray.run.scenes.push_back(scene("z", Outcome::Pass));
  EXPECT_EQ(mergeError({one, stray}), "two.json: scene 'z' is not in its suite");
  EXPECT_EQ(mergeError({}), "no results to merge");
}

TEST(JUnit, TestIdentityDoesNotDependOnTheShard) {
  const RunResults whole = shardOf(kNames, 1, 1), shard = shardOf(kNames, 2, 3);
  const std::string all = junitXml(whole), part = junitXml(shard);
  EXPECT_EQ(part.find("shard2"), std::string::npos) << part;
  EXPECT_NE(part.find("<property name=\"shard\" value=\"2/3\"/>"), std::string::npos) << part;
  EXPECT_EQ(all.find("<properties>"), std::string::npos) << all;
  // b is in shard 2 of 3: the same testcase line in both.
  const std::regex testcase("<testcase [^>]*name=\"b\"[^>]*>");
  std::smatch inAll, inPart;
  ASSERT_TRUE(std::regex_search(all, inAll, testcase));
  ASSERT_TRUE(std::regex_search(part, inPart, testcase));
  EXPECT_EQ(inAll.str(), inPart.str());
  EXPECT_NE(inAll.str().find("classname=\"crosscheck.conformance\""), std::string::npos) << inAll.str();
}

TEST(Baseline, MarksNewFailuresFixedScenesAndChangedMetrics) {
  RunResults before, now;
  const auto compared = [](Outcome outcome, std::uint64_t mismatches) {
    SceneResult r = scene("x", outcome);
    r.comparison = Comparison{};
    r.comparison->coverageMismatches = mismatches;
    return r;
  };
  before.scenes = {compared(Outcome::Pass, 0), scene("broke", Outcome::Pass), scene("mended", Outcome::Crash),
                   scene("still", Outcome::Crash), scene("gone", Outcome::Pass)};
  before.scenes[0].entry.name = "metrics";
  now.scenes = {compared(Outcome::Fail, 12), scene("broke", Outcome::Crash), scene("mended", Outcome::Pass),
                scene("still", Outcome::Crash), scene("added", Outcome::Fail)};
  now.scenes[0].entry.name = "metrics";
  const BaselineComparison v = compareWithBaseline(now, before);
  ASSERT_EQ(v.scenes.size(), 5u);
  EXPECT_TRUE(v.scenes[0].newFailure);
  ASSERT_EQ(v.scenes[0].changes.size(), 1u);
  EXPECT_EQ(v.scenes[0].changes[0].metric, "coverage mismatches");
  EXPECT_EQ(v.scenes[0].changes[0].before, 0);
  EXPECT_EQ(v.scenes[0].changes[0].after, 12);
  EXPECT_TRUE(v.scenes[1].newFailure);
  EXPECT_EQ(v.scenes[1].before, Outcome::Pass);
  EXPECT_TRUE(v.scenes[2].fixed);
  EXPECT_FALSE(v.scenes[3].newFailure || v.scenes[3].fixed) << "failing in both is neither";
  EXPECT_FALSE(v.scenes[4].inBaseline);
  EXPECT_TRUE(v.scenes[4].newFailure);
  EXPECT_EQ(v.newFailures, 3u);
  EXPECT_EQ(v.fixed, 1u);
  EXPECT_EQ(v.changed, 1u);
  EXPECT_EQ(v.added, 1u);
  EXPECT_EQ(v.gone, std::vector<std::string>{"gone"});
}

TEST(ResultsFile, PathsAreRelativeToItsFolderAndTheFormatIsChecked) {
  const fs::path dir = kArtifacts / "results-file" / "out";
  fs::remove_all(dir.parent_path());
  RunResults run = shardOf(kNames, 1, 1);
  run.junitFile = dir.parent_path() / "conformance.junit.xml";
  run.scenes[0].imageRoot = dir;
  run.scenes[0].images = {{"soft", "a/soft.png"}};
  run.scenes[0].timings = {1, 2, 3, 4, 5};
  ASSERT_TRUE(writeResultsFile(dir, run));
  const json stored = json::parse(readText(dir / "results.json"));
  EXPECT_EQ(stored["format"], kResultsFormat);
  EXPECT_EQ(stored["junit_file"], "../conformance.junit.xml");
  EXPECT_EQ(stored["scenes"][0]["image_root"], ".");
  EXPECT_EQ(stored["scenes"][1]["image_root"], "") << "no images";
  EXPECT_EQ(stored["scenes"][0]["step_milliseconds"], json({{"load", 1}, {"soft", 2}, {"vulkan", 3}, {"compare", 4}, {"images", 5}, {"variants", 0}}));
  // Moved elsewhere as a whole, the folder's paths still hold.
  const fs::path moved = kArtifacts / "results-file" / "moved";
  fs::rename(dir, moved);
  const auto back = readResultsFile(moved);  // the folder, or the file itself
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->scenes[0].imageRoot, moved / "");
  EXPECT_EQ(back->junitFile, (moved / "../conformance.junit.xml").lexically_normal());
  EXPECT_EQ(back->scenes[0].timings.images, 5);
  ASSERT_EQ(back->suite.size(), kNames.size());

  // Errors name the file.
  const auto missing = readResultsFile(kArtifacts / "results-file" / "nothing");
  ASSERT_FALSE(missing);
  EXPECT_EQ(missing.error(), (kArtifacts / "results-file" / "nothing").string() + ": cannot read results file: file not found");
  json later = stored;
  later["format"] = 2;
  std::ofstream(moved / "results.json") << later.dump();
  const auto newer = readResultsFile(moved / "results.json");
  ASSERT_FALSE(newer);
  EXPECT_EQ(newer.error(), (moved / "results.json").string() +
                               ": results JSON: /format: version 2, but this crosscheck reads version 1");
  std::ofstream(moved / "results.json") << "{\"format\": 1,";
  const auto broken = readResultsFile(moved / "results.json");
  ASSERT_FALSE(broken);
  EXPECT_EQ(broken.error().rfind((moved / "results.json").string() + ": not JSON: ", 0), 0u) << broken.error();
}

// ---- the command line: three shards merged against one unsharded run ----

// Timing fields set to 0: any key ending in "milliseconds" (step_milliseconds is an object of
// them), "seconds" and "finished"; nothing else.
void zeroTimings(json& value) {
  if (value.is_array()) {
    for (json& item : value) zeroTimings(item);
    return;
  }
  if (!value.is_object()) return;
  for (auto& [key, item] : value.items()) {
    const bool timing = key == "seconds" || key == "finished" ||
                        (key.size() >= 12 && key.compare(key.size() - 12, 12, "milliseconds") == 0);
    if (timing) {
      item = 0;
    } else {
      zeroTimings(item);
    }
  }
}

// The file's text with every timing value zeroed. The file must be exactly what results_file
// writes (parsing and writing it again gives the same bytes), so comparing these compares the
// files byte for byte outside the timing values.
std::string withoutTimings(const fs::path& file) {
  const std::string text = readText(file);
  json value = json::parse(text);
  EXPECT_EQ(value.dump(1, ' ', false, json::error_handler_t::replace) + "\n", text) << file;
  zeroTimings(value);
  return value.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

// JUnit with its times (time="...", the timestamp, the time_ms and step_ms lines) taken out.
std::string junitWithoutTimes(const fs::path& file) {
  std::string text = readText(file);
  text = std::regex_replace(text, std::regex(" time(stamp)?=\"[^\"]*\""), "");
  text = std::regex_replace(text, std::regex("(time_ms|step_ms): [^\n]*\n"), "");
  return text;
}

int run(const std::string& arguments, const fs::path& log) {
  const std::string command = "cd '" SOURCE_DIR "' && '" CROSSCHECK "' " + arguments + " >'" + log.string() + "' 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(Merge, ThreeShardsEqualTheUnshardedRun) {
  const fs::path dir = kArtifacts / "merge-shards";
  fs::remove_all(dir);
  fs::create_directories(dir);
  // Pass (bit-identical: top_left_rule, flat_triangle), Fail (room and depth_slope under the fmuladd
  // rounding lavapipe does not use, with pixel data), Crash (broken_obj) and Skip (malformed, by
  // expectations).
  const std::string otherFma = softraster::ContextOptions{}.fusedMultiplyAdd ? "separate" : "fused";
  const std::string suite = "scenes/room.json scenes/top_left_rule.json tests/data/conformance --softraster-fma " + otherFma +
                            " --expectations tests/data/expectations/report.txt --jobs 2";
  const fs::path out = dir / "out";
  ASSERT_EQ(run("report " + suite + " -o " + out.string() + " --junit " + (out / "junit.xml").string(), dir / "unsharded.txt"), 1)
      << readText(dir / "unsharded.txt");
  fs::rename(out, dir / "unsharded");
  std::string shards;
  for (int i = 1; i <= 3; ++i) {
    const fs::path shard = dir / ("shard" + std::to_string(i));
    const std::string log = "shard" + std::to_string(i) + ".txt";
    const int status = run("report " + suite + " --shard " + std::to_string(i) + "/3 -o " + shard.string() + " --junit " +
                               (shard / "junit.xml").string(),
                           dir / log);
    EXPECT_TRUE(status == 0 || status == 1) << readText(dir / log);
    EXPECT_EQ(readText(shard / "junit.xml").find("shard" + std::to_string(i) + "of"), std::string::npos);
    // Folders and files alike.
    shards += " " + (i == 2 ? shard.string() : (shard / "results.json").string());
  }
  // Merged into the unsharded run's place, so the image paths in JUnit's <system-out> match too.
  ASSERT_EQ(run("merge" + shards + " -o " + out.string(), dir / "merge.txt"), 1) << readText(dir / "merge.txt");
  const std::string merged = withoutTimings(out / "results.json");
  EXPECT_EQ(merged, withoutTimings(dir / "unsharded" / "results.json"));
  EXPECT_EQ(junitWithoutTimes(out / "junit.xml"), junitWithoutTimes(dir / "unsharded" / "junit.xml"));
  // Six scenes, all there, every image copied into the merged folder.
  const auto back = readResultsFile(out);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->scenes.size(), 6u);
  std::size_t files = 0;
  for (const SceneResult& r : back->scenes) {
    for (const SceneImage& image : r.images) files += fs::exists(out / image.file);
    if (!r.pixelData.empty()) {
      EXPECT_TRUE(fs::exists(out / r.pixelData)) << r.pixelData;
    }
  }
  EXPECT_EQ(files, 14u) << "room's and depth_slope's six images, two previews";
  EXPECT_TRUE(fs::exists(out / "index.html"));
  const std::string log = readText(dir / "merge.txt");
  EXPECT_NE(log.find("crosscheck merge: 6 scenes from 3 files\n"), std::string::npos) << log;
  EXPECT_EQ(log.substr(log.rfind('\n', log.size() - 2) + 1), "2 passed, 3 failed, 1 skipped\n") << log;
}

}  // namespace
