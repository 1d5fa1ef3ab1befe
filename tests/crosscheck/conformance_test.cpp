// The conformance runner's parts: suite collection, sharding, expectations files, statuses (with
// the softraster renderer replaced to produce a real failure, an error and an exception), worker
// isolation (a renderer that segfaults, aborts, allocates without bound or never returns), counts,
// the text summary and the JUnit writer. The command line is tested in conformance_cli_test.sh.
#include "output/junit.hpp"
#include "output/markup.hpp"
#include "output/summary.hpp"
#include "run/conformance.hpp"
#include "run/expectations.hpp"
#include "run/suite.hpp"

#include <gtest/gtest.h>

#include "run/worker_processes.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <stdexcept>
#include <thread>

namespace {

using namespace crosscheck;
namespace fs = std::filesystem;

const fs::path kData = TEST_DATA_DIR;
const fs::path kFixtures = kData / "conformance";
const fs::path kArtifacts = ARTIFACTS_DIR;

std::vector<std::string> namesOf(const std::vector<SceneEntry>& suite) {
  std::vector<std::string> names;
  for (const SceneEntry& e : suite) names.push_back(e.name);
  return names;
}

std::vector<SceneEntry> syntheticSuite(std::size_t size) {
  std::vector<SceneEntry> suite;
  for (std::size_t i = 0; i < size; ++i) suite.push_back({"scene" + std::to_string(100 + i), "s/scene" + std::to_string(100 + i) + ".json"});
  return suite;
}

// ---- suite collection ----

TEST(Suite, DirectoryGivesItsJsonFilesSortedByPath) {
  const auto suite = collectScenes({kFixtures.string()});
  ASSERT_TRUE(suite) << suite.error();
  EXPECT_EQ(namesOf(*suite), (std::vector<std::string>{"broken_obj", "depth_slope", "flat_triangle", "malformed"}));
  EXPECT_EQ((*suite)[1].path, kFixtures / "depth_slope.json");
}

TEST(Suite, FileNamedTwiceRunsOnceAndMissingFileIsKept) {
  const auto suite = collectScenes({(kFixtures / "flat_triangle.json").string(), kFixtures.string(),
                                    (kData / "nope.json").string()});
  ASSERT_TRUE(suite) << suite.error();
  EXPECT_EQ(namesOf(*suite), (std::vector<std::string>{"broken_obj", "depth_slope", "flat_triangle", "malformed", "nope"}));
}

TEST(Suite, TwoScenesWithOneNameAreAnError) {
  const fs::path dir = kArtifacts / "suite-duplicate-names";
  fs::remove_all(dir);
  fs::create_directories(dir / "a");
  fs::create_directories(dir / "b");
  fs::copy_file(kFixtures / "flat_triangle.json", dir / "a" / "x.json");
  fs::copy_file(kFixtures / "flat_triangle.json", dir / "b" / "x.json");
  const auto suite = collectScenes({(dir / "a").string(), (dir / "b").string()});
  EXPECT_FALSE(suite);
  const std::string& error = suite.error();
  EXPECT_NE(error.find("scene name 'x' is already used by"), std::string::npos) << error;
}

TEST(Suite, DirectoryWithoutScenesIsAnError) {
  const fs::path dir = kArtifacts / "suite-empty";
  fs::create_directories(dir);
  const auto suite = collectScenes({dir.string()});
  EXPECT_FALSE(suite);
  EXPECT_EQ(suite.error(), dir.string() + ": no *.json scene files in this directory");
}

// ---- sharding ----

TEST(Shard, ParsesOneBasedAndRejectsTheRest) {
  const auto shard = parseShard("2/3");
  ASSERT_TRUE(shard) << shard.error();
  EXPECT_EQ(shard->index, 2u);
  EXPECT_EQ(shard->count, 3u);
  for (const char* bad : {"0/3", "4/3", "1/0", "0/0", "3", "/3", "1/", "a/b", "1/3x", "-1/3", "1//3", ""}) {
    const auto parsed = parseShard(bad);
    EXPECT_FALSE(parsed) << bad;
    const std::string& error = parsed.error();
    EXPECT_EQ(error.rfind("--shard ", 0), 0u) << error;
  }
}

TEST(Shard, UnionOfAllShardsIsTheSuiteWithNoSceneTwice) {
  for (std::size_t size : {0u, 1u, 2u, 3u, 7u, 10u}) {
    const auto suite = syntheticSuite(size);
    for (std::size_t n = 1; n <= 3; ++n) {
      std::multiset<std::string> seen;
      for (std::size_t i = 1; i <= n; ++i) {
        const auto slice = selectShard(suite, {i, n});
        EXPECT_GE(slice.size(), size / n) << "shard " << i << "/" << n << " of " << size;
        EXPECT_LE(slice.size(), (size + n - 1) / n) << "shard " << i << "/" << n << " of " << size;
        for (const SceneEntry& e : slice) seen.insert(e.name);
        // The slice keeps suite order.
        EXPECT_TRUE(std::is_sorted(slice.begin(), slice.end(), [](const auto& a, const auto& b) { return a.name < b.name; }));
      }
      const auto names = namesOf(suite);
      EXPECT_EQ(std::vector<std::string>(seen.begin(), seen.end()), names) << n << " shards of " << size;
    }
  }
}

TEST(Shard, IsDeterministic) {
  const auto suite = syntheticSuite(7);
  EXPECT_EQ(namesOf(selectShard(suite, {2, 3})), (std::vector<std::string>{"scene101", "scene104"}));
  EXPECT_EQ(namesOf(selectShard(suite, {1, 1})), namesOf(suite));
}

// ---- expectations ----

TEST(Expectations, ParsesNamesStatusesReasonsAndComments) {
  const auto e = parseExpectations("# header\n\n  room , Fail # edge differs\nsky,Skip\n  # indented comment\nx,Crash#why\n",
                                   "exp.txt");
  ASSERT_TRUE(e) << e.error();
  ASSERT_EQ(e->byScene.size(), 3u);
  ASSERT_TRUE(e->find("room"));
  EXPECT_EQ(e->find("room")->outcome, Outcome::Fail);
  EXPECT_EQ(e->find("room")->reason, "edge differs");
  EXPECT_EQ(e->find("room")->line, 3);
  EXPECT_EQ(e->find("sky")->outcome, Outcome::Skip);
  EXPECT_EQ(e->find("sky")->reason, "");
  EXPECT_EQ(e->find("x")->outcome, Outcome::Crash);
  EXPECT_EQ(e->find("x")->reason, "why");
  EXPECT_EQ(e->find("missing"), nullptr);
}

TEST(Expectations, MalformedLinesNameFileAndLine) {
  const std::pair<const char*, const char*> cases[] = {
      {"ok,Pass\nno comma here\n", "exp.txt:2: expected 'SCENE,STATUS # reason', got 'no comma here'"},
      {"a,Fail,Skip\n", "exp.txt:1: expected 'SCENE,STATUS # reason', got 'a,Fail,Skip'"},
      {",Fail\n", "exp.txt:1: missing scene name before ','"},
      {"\n\na,fail\n", "exp.txt:3: 'fail' is not one of Pass, Fail, Crash, Timeout, Skip"},
      {"a,ExpectedFail\n", "exp.txt:1: 'ExpectedFail' is not one of Pass, Fail, Crash, Timeout, Skip"},
      {"a,\n", "exp.txt:1: '' is not one of Pass, Fail, Crash, Timeout, Skip"},
      {"a,Fail\nb,Skip\na,Skip\n", "exp.txt:3: scene 'a' is already listed on line 1"},
  };
  for (const auto& [text, message] : cases) {
    const auto parsed = parseExpectations(text, "exp.txt");
    EXPECT_FALSE(parsed) << text;
    EXPECT_EQ(parsed.error(), message);
  }
}

TEST(Expectations, UnreadableFileIsOneLine) {
  const auto missing = loadExpectations(kData / "no_such_file.txt");
  EXPECT_FALSE(missing);
  EXPECT_EQ(missing.error(), (kData / "no_such_file.txt").string() + ": cannot read expectations file: file not found");
  const auto directory = loadExpectations(kData);
  EXPECT_FALSE(directory);
  EXPECT_EQ(directory.error(), kData.string() + ": cannot read expectations file: is a directory, not a file");
}

TEST(Expectations, AppliedToActualResults) {
  const Expectation fail{Outcome::Fail, "", 1}, crash{Outcome::Crash, "", 1}, pass{Outcome::Pass, "", 1};
  EXPECT_EQ(applyExpectation(Outcome::Pass, nullptr), Outcome::Pass);
  EXPECT_EQ(applyExpectation(Outcome::Fail, nullptr), Outcome::Fail);
  EXPECT_EQ(applyExpectation(Outcome::Crash, nullptr), Outcome::Crash);
  EXPECT_EQ(applyExpectation(Outcome::Fail, &pass), Outcome::Fail);
  EXPECT_EQ(applyExpectation(Outcome::Fail, &fail), Outcome::ExpectedFail);
  EXPECT_EQ(applyExpectation(Outcome::Pass, &fail), Outcome::UnexpectedPass);
  EXPECT_EQ(applyExpectation(Outcome::Crash, &fail), Outcome::Crash);
  EXPECT_EQ(applyExpectation(Outcome::Crash, &crash), Outcome::ExpectedFail);
  EXPECT_EQ(applyExpectation(Outcome::Pass, &crash), Outcome::UnexpectedPass);
  EXPECT_EQ(applyExpectation(Outcome::Fail, &crash), Outcome::Fail);
}

// ---- statuses from real runs ----

// softraster with one pixel painted magenta: a real coverage and colour difference.
softraster::Result<Frame> paintedSoftraster(const Scene& scene) {
  auto frame = renderSoftraster(scene);
  if (frame) {
    const std::size_t i = 4 * (frame->width * (frame->height / 2) + 1);
    frame->rgba[i] = 255, frame->rgba[i + 1] = 0, frame->rgba[i + 2] = 255, frame->rgba[i + 3] = 255;
  }
  return frame;
}

SceneEntry fixture(const std::string& name) { return {name, kFixtures / (name + ".json")}; }

TEST(Conformance, PassFailAndCrashFromLoading) {
  ConformanceOptions options;
  const auto results = runConformance({fixture("flat_triangle"), fixture("malformed"), fixture("broken_obj")}, options);
  ASSERT_EQ(results.size(), 3u);
  EXPECT_EQ(results[0].outcome, Outcome::Pass);
  ASSERT_TRUE(results[0].comparison);
  EXPECT_EQ(results[0].comparison->pixels, 32u * 24u);
  EXPECT_GT(results[0].vulkanMilliseconds, 0);
  EXPECT_EQ(results[1].outcome, Outcome::Crash);
  EXPECT_EQ(results[1].error.find((kFixtures / "malformed.json").string() + ": parse error at line 3"), 0u) << results[1].error;
  EXPECT_EQ(results[2].outcome, Outcome::Crash);
  EXPECT_NE(results[2].error.find("malformed.obj"), std::string::npos) << results[2].error;

  options.renderSoft = paintedSoftraster;
  const auto failed = runConformance({fixture("flat_triangle")}, options);
  EXPECT_EQ(failed[0].outcome, Outcome::Fail);
  ASSERT_TRUE(failed[0].comparison);
  EXPECT_EQ(failed[0].comparison->coverageMismatches, 1u);
  EXPECT_EQ(failed[0].comparison->failures.front(), "coverage_mismatches 1 > 0");
  EXPECT_EQ(resultDetail(failed[0]), "coverage_mismatches 1 > 0; colour_pixels_over 1 > 0 (colour max |Δ| 255 8-bit steps, threshold 1)");
}

TEST(Conformance, RendererErrorAndExceptionAreCrashAndTheRunGoesOn) {
  ConformanceOptions options;
  options.renderSoft = [](const Scene& scene) -> softraster::Result<Frame> {
    if (scene.width == 32) return softraster::Status::error("softraster: draw 'x': out of memory\nsecond line");
    throw std::runtime_error("boom");
  };
  const auto results = runConformance({fixture("flat_triangle"), fixture("depth_slope")}, options);
  EXPECT_EQ(results[0].outcome, Outcome::Crash);
  EXPECT_EQ(results[0].error, "softraster: draw 'x': out of memory second line");  // one line
  EXPECT_EQ(results[1].outcome, Outcome::Crash);
  EXPECT_EQ(results[1].error, "exception: boom");
}

TEST(Conformance, ExpectationsGiveExpectedFailUnexpectedPassAndSkip) {
  const auto expectations = parseExpectations("flat_triangle,Fail # painted\ndepth_slope,Fail # passes\nmalformed,Skip\n"
                                              "broken_obj,Crash # broken on purpose\n",
                                              "exp.txt");
  ASSERT_TRUE(expectations) << expectations.error();
  std::atomic<int> softCalls{0};
  ConformanceOptions options;
  options.isolation = Isolation::Threads;  // softCalls is counted in this process
  options.expectations = &*expectations;
  options.renderSoft = [&](const Scene& scene) {
    ++softCalls;
    return scene.width == 32 ? paintedSoftraster(scene) : renderSoftraster(scene);
  };
  const auto results =
      runConformance({fixture("broken_obj"), fixture("depth_slope"), fixture("flat_triangle"), fixture("malformed")}, options);
  EXPECT_EQ(results[0].outcome, Outcome::ExpectedFail);
  EXPECT_EQ(results[0].actual, Outcome::Crash);
  EXPECT_EQ(results[1].outcome, Outcome::UnexpectedPass);
  EXPECT_EQ(resultDetail(results[1]), "expected Fail (line 2), but passed");
  EXPECT_EQ(results[2].outcome, Outcome::ExpectedFail);
  EXPECT_EQ(results[2].actual, Outcome::Fail);
  ASSERT_TRUE(results[2].expectation);
  EXPECT_EQ(results[2].expectation->reason, "painted");
  EXPECT_EQ(results[3].outcome, Outcome::Skip);
  EXPECT_FALSE(results[3].loaded);
  EXPECT_EQ(softCalls, 2);  // skipped and unloadable scenes never render

  const Counts counts = countResults(results);
  EXPECT_EQ(counts.passed, 2u);   // ExpectedFail x2
  EXPECT_EQ(counts.failed, 1u);   // UnexpectedPass
  EXPECT_EQ(counts.skipped, 1u);
  EXPECT_EQ(countsLine(counts), "2 passed, 1 failed, 1 skipped");
  EXPECT_EQ(countsLine(countResults({results[1]})), "0 passed, 1 failed");
}

TEST(Conformance, ParallelRunKeepsSuiteOrderAndReportsEveryScene) {
  std::vector<SceneEntry> suite;
  for (int round = 0; round < 3; ++round) {
    for (const char* name : {"flat_triangle", "depth_slope", "malformed"}) {
      suite.push_back({std::string(name) + std::to_string(round), kFixtures / (std::string(name) + ".json")});
    }
  }
  ConformanceOptions options;
  options.jobs = 3;
  std::vector<std::size_t> positions, dones;
  options.onFinished = [&](std::size_t position, const SceneResult& result, std::size_t done) {
    EXPECT_EQ(result.entry.name, suite[position].name);
    positions.push_back(position);
    dones.push_back(done);
  };
  const auto results = runConformance(suite, options);
  ASSERT_EQ(results.size(), suite.size());
  for (std::size_t i = 0; i < suite.size(); ++i) {
    EXPECT_EQ(results[i].entry.name, suite[i].name);
    EXPECT_EQ(results[i].outcome, i % 3 == 2 ? Outcome::Crash : Outcome::Pass) << suite[i].name << ": " << results[i].error;
  }
  std::sort(positions.begin(), positions.end());
  for (std::size_t i = 0; i < suite.size(); ++i) {
    EXPECT_EQ(positions[i], i);
    EXPECT_EQ(dones[i], i + 1);
  }
}

TEST(Conformance, ThreadsGiveTheSameResultsAsWorkerProcesses) {
  const std::vector<SceneEntry> suite = {fixture("broken_obj"), fixture("depth_slope"), fixture("flat_triangle"),
                                         fixture("malformed")};
  ConformanceOptions options;
  options.jobs = 2;
  const auto processes = runConformance(suite, options);
  options.isolation = Isolation::Threads;
  const auto threads = runConformance(suite, options);
  ASSERT_EQ(processes.size(), threads.size());
  for (std::size_t i = 0; i < suite.size(); ++i) {
    EXPECT_EQ(resultLine(processes[i]).substr(0, resultLine(processes[i]).find("  (soft")),
              resultLine(threads[i]).substr(0, resultLine(threads[i]).find("  (soft")));
  }
}

// ---- isolation: a scene that brings its worker down is that scene's Crash or Timeout ----

// A suite of five scenes where only the middle one (flat_triangle, 32 pixels wide) misbehaves
// in softraster; the others must keep their results.
std::vector<SceneEntry> suiteAroundOneBadScene() {
  return {{"before", kFixtures / "depth_slope.json"}, {"before_broken", kFixtures / "malformed.json"},
          fixture("flat_triangle"), {"after", kFixtures / "depth_slope.json"},
          {"after_broken", kFixtures / "broken_obj.json"}};
}

void expectOthersIntact(const std::vector<SceneResult>& results) {
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results[0].outcome, Outcome::Pass) << results[0].error;
  EXPECT_EQ(results[1].outcome, Outcome::Crash);
  EXPECT_NE(results[1].error.find("parse error"), std::string::npos) << results[1].error;
  EXPECT_EQ(results[3].outcome, Outcome::Pass) << results[3].error;
  ASSERT_TRUE(results[3].comparison);
  EXPECT_EQ(results[3].comparison->pixels, 64u * 48u);
  EXPECT_EQ(results[4].outcome, Outcome::Crash);
  EXPECT_NE(results[4].error.find("malformed.obj"), std::string::npos) << results[4].error;
}

ConformanceOptions misbehavingOn32Wide(const std::function<void()>& misbehave) {
  ConformanceOptions options;
  options.renderSoft = [misbehave](const Scene& scene) {
    if (scene.width == 32) misbehave();
    return renderSoftraster(scene);
  };
  return options;
}

// Under AddressSanitizer a segfault is ASan's report and exit status 1, not the signal.
bool underAddressSanitizer() { return !workerMemoryLimitWorks(); }

TEST(Isolation, SegfaultIsCrashAndTheRunGoesOn) {
  for (unsigned jobs : {1u, 2u}) {
    ConformanceOptions options = misbehavingOn32Wide([] { std::raise(SIGSEGV); });
    options.jobs = jobs;
    const auto results = runConformance(suiteAroundOneBadScene(), options);
    expectOthersIntact(results);
    EXPECT_EQ(results[2].outcome, Outcome::Crash);
    if (underAddressSanitizer()) {
      EXPECT_EQ(results[2].error.rfind("worker ", 0), 0u) << results[2].error;
    } else {
      EXPECT_EQ(results[2].error, "worker killed by signal 11 (SIGSEGV)");
    }
    EXPECT_FALSE(results[2].loaded);
  }
}

TEST(Isolation, AbortIsCrashAndTheRunGoesOn) {
  ConformanceOptions options = misbehavingOn32Wide([] { std::abort(); });
  options.jobs = 2;
  const auto results = runConformance(suiteAroundOneBadScene(), options);
  expectOthersIntact(results);
  EXPECT_EQ(results[2].outcome, Outcome::Crash);
  EXPECT_EQ(results[2].error, "worker killed by signal 6 (SIGABRT)");
}

TEST(Isolation, UncaughtExceptionOnAnotherThreadIsCrashWithItsMessage) {
  ConformanceOptions options = misbehavingOn32Wide([] {
    std::thread([] { throw std::runtime_error("thrown on a helper thread"); }).join();
  });
  const auto results = runConformance(suiteAroundOneBadScene(), options);
  expectOthersIntact(results);
  EXPECT_EQ(results[2].outcome, Outcome::Crash);
  EXPECT_EQ(results[2].error, "uncaught exception: thrown on a helper thread");
}

TEST(Isolation, RunawayAllocationIsCrashOutOfMemory) {
  if (underAddressSanitizer()) GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no limit under it";
  ConformanceOptions options = misbehavingOn32Wide([] {
    std::vector<std::unique_ptr<char[]>> hoard;
    while (true) hoard.emplace_back(new char[64 << 20]);  // address space, never touched
  });
  options.jobs = 2;
  options.memoryLimitMegabytes = 2048;
  const auto results = runConformance(suiteAroundOneBadScene(), options);
  expectOthersIntact(results);
  EXPECT_EQ(results[2].outcome, Outcome::Crash);
  EXPECT_EQ(results[2].error, "out of memory: over the worker's memory limit of 2048 MB (--memory-limit)");
}

TEST(Isolation, SceneThatNeverEndsIsTimeout) {
  ConformanceOptions options = misbehavingOn32Wide([] {
    while (true) std::this_thread::sleep_for(std::chrono::seconds(1));
  });
  options.jobs = 2;
  options.timeoutSeconds = 2;
  const auto start = std::chrono::steady_clock::now();
  const auto results = runConformance(suiteAroundOneBadScene(), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  expectOthersIntact(results);
  EXPECT_EQ(results[2].outcome, Outcome::Timeout);
  EXPECT_EQ(results[2].error, "no result within 2 s; worker killed (--timeout)");
  EXPECT_GE(results[2].milliseconds, 2000);
  EXPECT_LT(seconds, 30);
  EXPECT_TRUE(isUnexpected(results[2].outcome));
  EXPECT_EQ(countResults(results).failed, 3u);
  EXPECT_EQ(resultLine(results[2]), "Timeout        flat_triangle: no result within 2 s; worker killed (--timeout)");
}

TEST(Isolation, ExpectedTimeoutAndExpectedCrashAreExpectedFail) {
  const auto expectations = parseExpectations("flat_triangle,Timeout # hangs\n", "exp.txt");
  ASSERT_TRUE(expectations) << expectations.error();
  ConformanceOptions options = misbehavingOn32Wide([] {
    while (true) std::this_thread::sleep_for(std::chrono::seconds(1));
  });
  options.expectations = &*expectations;
  options.timeoutSeconds = 1;
  const auto timedOut = runConformance({fixture("flat_triangle")}, options);
  EXPECT_EQ(timedOut[0].outcome, Outcome::ExpectedFail);
  EXPECT_EQ(timedOut[0].actual, Outcome::Timeout);
  EXPECT_EQ(timedOut[0].expectation->reason, "hangs");
  options.renderSoft = {};
  const auto passed = runConformance({fixture("flat_triangle")}, options);
  EXPECT_EQ(passed[0].outcome, Outcome::UnexpectedPass);
}

TEST(Isolation, EveryWorkerDyingStillEndsTheRun) {
  ConformanceOptions options;
  options.jobs = 3;
  options.renderSoft = [](const Scene&) -> softraster::Result<Frame> { std::abort(); };
  std::vector<SceneEntry> suite;
  for (int i = 0; i < 7; ++i) suite.push_back({"s" + std::to_string(i), kFixtures / "flat_triangle.json"});
  std::size_t finished = 0;
  options.onFinished = [&](std::size_t, const SceneResult&, std::size_t done) { finished = done; };
  const auto results = runConformance(suite, options);
  EXPECT_EQ(finished, 7u);
  for (const SceneResult& r : results) {
    EXPECT_EQ(r.outcome, Outcome::Crash);
    EXPECT_EQ(r.error, "worker killed by signal 6 (SIGABRT)");
  }
}

// ---- text output ----

SceneResult madeUp(const std::string& name, Outcome outcome, double ms) {
  SceneResult r;
  r.entry = {name, name + ".json"};
  r.outcome = r.actual = outcome;
  r.milliseconds = ms;
  if (outcome == Outcome::Crash) r.error = name + ".json: broken";
  if (outcome == Outcome::Pass || outcome == Outcome::Fail) {
    r.loaded = true;
    r.comparison = Comparison{};
    r.softMilliseconds = ms / 4;
    r.vulkanMilliseconds = ms / 2;
    r.tolerance.depthThreshold = 0.5;
    if (outcome == Outcome::Fail) {
      r.comparison->depthMaxDelta = 0.75;
      r.comparison->depthPixelsOver = 3;
      r.comparison->failures = {"depth_pixels_over 3 > 0"};
    }
  }
  return r;
}

TEST(Summary, ListsFailuresWithMetricAndThresholdAndTheFiveSlowest) {
  std::vector<SceneResult> results;
  for (int i = 0; i < 6; ++i) results.push_back(madeUp("pass" + std::to_string(i), Outcome::Pass, 10.0 * (i + 1)));
  results.push_back(madeUp("bad", Outcome::Fail, 5));
  results.push_back(madeUp("broken", Outcome::Crash, 1));
  RunResults run;
  run.scenes = results;
  const std::string text = summaryText(run);
  EXPECT_NE(text.find("Failures (2):\n  Fail           bad: depth_pixels_over 3 > 0 (depth max |Δ| 0.75, threshold 0.5)\n"
                      "  Crash          broken: broken.json: broken\n"),
            std::string::npos)
      << text;
  const auto slowest = text.find("Slowest scenes:\n");
  ASSERT_NE(slowest, std::string::npos) << text;
  const std::string tail = text.substr(slowest);
  EXPECT_LT(tail.find("pass5"), tail.find("pass4"));
  EXPECT_LT(tail.find("pass2"), tail.find("pass1"));
  EXPECT_EQ(tail.find("pass0"), std::string::npos) << "only five";
  EXPECT_EQ(resultLine(results[6]), "Fail           bad: depth_pixels_over 3 > 0 (depth max |Δ| 0.75, threshold 0.5)  "
                                    "(soft 1.25 ms, vulkan 2.50 ms)");
  EXPECT_EQ(progressLine(3, 10, 1, 12.34), "[3/10] failures: 1 elapsed: 12.3s");
}

// ---- JUnit ----

TEST(JUnit, CountsAndElementsPerStatus) {
  std::vector<SceneResult> results = {madeUp("a", Outcome::Pass, 1500), madeUp("b", Outcome::Fail, 2),
                                      madeUp("c<&\"'>", Outcome::Crash, 3), madeUp("d", Outcome::Pass, 4),
                                      madeUp("e", Outcome::Skip, 0), madeUp("f", Outcome::Fail, 5)};
  results[3].outcome = Outcome::UnexpectedPass;
  results[3].expectation = Expectation{Outcome::Fail, "known", 7};
  results[5].outcome = Outcome::ExpectedFail;
  results[5].expectation = Expectation{Outcome::Fail, "tracked in issue 9", 8};
  results[0].imageRoot = "out";
  results[0].images = {{"diff", "a/diff.png"}};
  RunResults run;
  run.scenes = results;
  run.suiteName = "suite";
  run.seconds = 2.5;
  run.finished = 1735689600;  // 2025-01-01T00:00:00 UTC
  const std::string xml = junitXml(run);
  EXPECT_NE(xml.find("<testsuite name=\"suite\" tests=\"6\" failures=\"2\" errors=\"1\" skipped=\"2\" time=\"2.500\" "
                     "timestamp=\"2025-01-01T00:00:00\">"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"a\" file=\"a.json\" time=\"1.500\""), std::string::npos);
  EXPECT_NE(xml.find("<failure type=\"Fail\" message=\"depth_pixels_over 3 &gt; 0 (depth max |Δ| 0.75, threshold 0.5)\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("name=\"c&lt;&amp;&quot;&#39;&gt;\""), std::string::npos);
  EXPECT_NE(xml.find("<error type=\"Crash\" message=\"c&lt;&amp;&quot;&#39;&gt;.json: broken\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<failure type=\"UnexpectedPass\" message=\"expected Fail (line 7), but passed\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<skipped message=\"skipped by expectations\"/>"), std::string::npos);
  EXPECT_NE(xml.find("<skipped message=\"expected failure: depth_pixels_over 3 &gt; 0 (depth max |Δ| 0.75, threshold 0.5) "
                     "[tracked in issue 9]\"/>"),
            std::string::npos)
      << xml;
  EXPECT_NE(xml.find("image diff: out/a/diff.png\n"), std::string::npos);
  EXPECT_NE(xml.find("depth_pixels_over: 3 (allowed 0)\n"), std::string::npos);
}

TEST(Markup, EscapesAndReplacesWhatXmlCannotCarry) {
  EXPECT_EQ(escapeMarkup("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escapeMarkup("tab\tnl\ncr\r"), "tab\tnl\ncr\r");
  EXPECT_EQ(escapeMarkup(std::string("bell\x07" "end")), "bell\xEF\xBF\xBD" "end");
  EXPECT_EQ(escapeMarkup("\xCE\x94 ok"), "\xCE\x94 ok");                           // valid UTF-8 stays
  EXPECT_EQ(escapeMarkup("bad \xFF\xC3 end"), "bad \xEF\xBF\xBD\xEF\xBF\xBD end");  // invalid bytes do not
  EXPECT_EQ(escapeMarkup("\xED\xA0\x80"), "\xEF\xBF\xBD\xEF\xBF\xBD\xEF\xBF\xBD");  // a surrogate is not UTF-8
  EXPECT_EQ(encodeUrlPath("a b/c#d?.png"), "a%20b/c%23d%3F.png");
}

}  // namespace
