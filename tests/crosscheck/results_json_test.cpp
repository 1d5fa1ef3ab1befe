// results_json: a SceneResult and a RunResults with every field set survive JSON (as text and as
// the CBOR the worker processes send) unchanged, non-finite numbers and bytes that are not UTF-8
// included; a malformed value is one error line naming the field.
#include "results/results_json.hpp"

#include "output/junit.hpp"
#include "output/summary.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace crosscheck;
using nlohmann::json;

SceneResult everyFieldSet() {
  SceneResult r;
  r.entry = {"room", "scenes/room.json"};
  r.outcome = Outcome::ExpectedFail;
  r.actual = Outcome::Fail;
  r.expectation = Expectation{Outcome::Fail, "known: edge differs", 7};
  r.error = "";
  r.loaded = true;
  r.description = "a room, \"quoted\" and \xCE\x94";
  r.width = 320;
  r.height = 240;
  r.tolerance = {3, 0x1p-20, 5, 6, 7};
  Comparison c;
  c.pixels = 76800;
  c.coverageMismatches = 12;
  c.samples = 4;
  c.colourMaxDelta = {1, 2, 3, 255};
  c.resolvedColourMaxDelta = {1, 0, 3, 7};
  c.colourUnit = "half ULPs";
  c.colourMeanDelta = {0.1, 1.0 / 3.0, 0.0, 1e-300};
  c.colourPixelsOver = 9;
  c.psnr = std::numeric_limits<double>::infinity();
  c.depthMaxDelta = 0x1.fffffep-3;
  c.depthPixelsOver = 4;
  c.failures = {"coverage_mismatches 12 > 5", "colour_pixels_over 9 > 6"};
  r.comparison = c;
  r.softMilliseconds = 1.25;
  r.vulkanMilliseconds = 2.5e-3;
  r.milliseconds = 123.456789012345;
  r.timings = {0.5, 1.5, 2.5, 0.125, 99.75, 12.5};
  VariantResults v;
  v.frames = 3;
  v.lavapipeMilliseconds = 0.75;
  v.lavapipeError = "";
  VariantRun compared;
  compared.label = "exact 1/z";
  compared.method = "exact";
  compared.depth = "1/z";
  compared.frameMilliseconds = {0.5, 0.25, 1.0 / 3.0};
  compared.medianMilliseconds = 0.5;
  compared.coverageMismatches = 17;
  compared.colourMaxDelta = 255;
  compared.differingPixels = 40;
  compared.withinTolerance = false;
  compared.hits = HitCounts{2, 3, 1000};
  VariantRun failed;
  failed.label = "exact-scalar";
  failed.method = "exact-scalar";
  failed.depth = "z";
  failed.error = "softraster: draw 'x': out of memory";
  v.runs = {compared, failed};
  r.variants = v;
  r.stabilityCase = true;
  r.imageRoot = "out/images";
  r.images = {{"soft", "room/soft.png"}, {"diff", "room/diff.png"}};
  r.pixelData = "room/pixels.js";
  r.depthViewRange = {0.25f, 0.99999994f};
  return r;
}

// Every field, compared one by one (NaN equal to NaN).
void expectSame(const SceneResult& a, const SceneResult& b) {
  const auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
  EXPECT_EQ(a.entry.name, b.entry.name);
  EXPECT_EQ(a.entry.path, b.entry.path);
  EXPECT_EQ(a.outcome, b.outcome);
  EXPECT_EQ(a.actual, b.actual);
  ASSERT_EQ(a.expectation.has_value(), b.expectation.has_value());
  if (a.expectation) {
    EXPECT_EQ(a.expectation->outcome, b.expectation->outcome);
    EXPECT_EQ(a.expectation->reason, b.expectation->reason);
    EXPECT_EQ(a.expectation->line, b.expectation->line);
  }
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.loaded, b.loaded);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.tolerance.colourThreshold, b.tolerance.colourThreshold);
  EXPECT_EQ(a.tolerance.depthThreshold, b.tolerance.depthThreshold);
  EXPECT_EQ(a.tolerance.maxCoverageMismatches, b.tolerance.maxCoverageMismatches);
  EXPECT_EQ(a.tolerance.maxColourPixelsOver, b.tolerance.maxColourPixelsOver);
  EXPECT_EQ(a.tolerance.maxDepthPixelsOver, b.tolerance.maxDepthPixelsOver);
  ASSERT_EQ(a.comparison.has_value(), b.comparison.has_value());
  if (a.comparison) {
    const Comparison &x = *a.comparison, &y = *b.comparison;
    EXPECT_EQ(x.pixels, y.pixels);
    EXPECT_EQ(x.coverageMismatches, y.coverageMismatches);
    EXPECT_EQ(x.samples, y.samples);
    EXPECT_EQ(x.colourMaxDelta, y.colourMaxDelta);
    EXPECT_EQ(x.resolvedColourMaxDelta, y.resolvedColourMaxDelta);
    EXPECT_EQ(x.colourUnit, y.colourUnit);
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(same(x.colourMeanDelta[i], y.colourMeanDelta[i])) << i;
    EXPECT_EQ(x.colourPixelsOver, y.colourPixelsOver);
    EXPECT_TRUE(same(x.psnr, y.psnr)) << x.psnr << " " << y.psnr;
    EXPECT_TRUE(same(x.depthMaxDelta, y.depthMaxDelta));
    EXPECT_EQ(x.depthPixelsOver, y.depthPixelsOver);
    EXPECT_EQ(x.failures, y.failures);
  }
  EXPECT_TRUE(same(a.softMilliseconds, b.softMilliseconds));
  EXPECT_TRUE(same(a.vulkanMilliseconds, b.vulkanMilliseconds));
  EXPECT_TRUE(same(a.milliseconds, b.milliseconds));
  EXPECT_TRUE(same(a.timings.load, b.timings.load));
  EXPECT_TRUE(same(a.timings.soft, b.timings.soft));
  EXPECT_TRUE(same(a.timings.vulkan, b.timings.vulkan));
  EXPECT_TRUE(same(a.timings.compare, b.timings.compare));
  EXPECT_TRUE(same(a.timings.images, b.timings.images));
  EXPECT_TRUE(same(a.timings.variants, b.timings.variants));
  EXPECT_EQ(a.stabilityCase, b.stabilityCase);
  ASSERT_EQ(a.variants.has_value(), b.variants.has_value());
  if (a.variants) {
    EXPECT_EQ(a.variants->frames, b.variants->frames);
    EXPECT_TRUE(same(a.variants->lavapipeMilliseconds, b.variants->lavapipeMilliseconds));
    EXPECT_EQ(a.variants->lavapipeError, b.variants->lavapipeError);
    ASSERT_EQ(a.variants->runs.size(), b.variants->runs.size());
    for (std::size_t i = 0; i < a.variants->runs.size(); ++i) {
      const VariantRun &x = a.variants->runs[i], &y = b.variants->runs[i];
      EXPECT_EQ(x.label, y.label);
      EXPECT_EQ(x.method, y.method);
      EXPECT_EQ(x.depth, y.depth);
      EXPECT_EQ(x.frameMilliseconds, y.frameMilliseconds);
      EXPECT_TRUE(same(x.medianMilliseconds, y.medianMilliseconds));
      EXPECT_EQ(x.coverageMismatches, y.coverageMismatches);
      EXPECT_EQ(x.colourMaxDelta, y.colourMaxDelta);
      EXPECT_EQ(x.differingPixels, y.differingPixels);
      EXPECT_EQ(x.withinTolerance, y.withinTolerance);
      ASSERT_EQ(x.hits.has_value(), y.hits.has_value());
      if (x.hits) {
        EXPECT_EQ(x.hits->cracks, y.hits->cracks);
        EXPECT_EQ(x.hits->doubleHits, y.hits->doubleHits);
        EXPECT_EQ(x.hits->referenceCovered, y.hits->referenceCovered);
      }
      EXPECT_EQ(x.error, y.error);
    }
  }
  EXPECT_EQ(a.imageRoot, b.imageRoot);
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].kind, b.images[i].kind);
    EXPECT_EQ(a.images[i].file, b.images[i].file);
  }
  EXPECT_EQ(a.pixelData, b.pixelData);
  EXPECT_EQ(a.depthViewRange, b.depthViewRange);
}

SceneResult throughText(const SceneResult& r) {
  const auto back = sceneResultFromJson(json::parse(sceneResultToJson(r).dump()));
  EXPECT_TRUE(back) << back.error();
  return back ? *back : SceneResult{};
}

SceneResult throughCbor(const SceneResult& r) {
  const auto back = sceneResultFromJson(json::from_cbor(json::to_cbor(sceneResultToJson(r))));
  EXPECT_TRUE(back) << back.error();
  return back ? *back : SceneResult{};
}

TEST(ResultsJson, EveryFieldSurvivesTextAndCbor) {
  const SceneResult r = everyFieldSet();
  expectSame(r, throughText(r));
  expectSame(r, throughCbor(r));
  // What the writers print is the same too.
  EXPECT_EQ(resultLine(throughCbor(r)), resultLine(r));
}

// A file written before the chart (no "variants", "stability_case" or step "variants") still
// reads, as a scene without them: new fields are additions, not a new format.
TEST(ResultsJson, FieldsAddedWithTheChartAreOptional) {
  json value = sceneResultToJson(everyFieldSet());
  value.erase("variants");
  value.erase("stability_case");
  value["step_milliseconds"].erase("variants");
  const auto back = sceneResultFromJson(value);
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->variants);
  EXPECT_FALSE(back->stabilityCase);
  EXPECT_EQ(back->timings.variants, 0);
  // A malformed one is named.
  value["variants"] = {{"frames", 3}};
  const auto bad = sceneResultFromJson(value);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("/variants/lavapipe_milliseconds: missing"), std::string::npos) << bad.error();
}

// A file written before every sample was compared: one sample, the resolve's maximum is the maximum.
TEST(ResultsJson, FieldsAddedWithEverySampleAreOptional) {
  json value = sceneResultToJson(everyFieldSet());
  value["comparison"].erase("samples_compared");
  value["comparison"].erase("resolved_colour_max_delta");
  const auto back = sceneResultFromJson(value);
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(back->comparison);
  EXPECT_EQ(back->comparison->samples, 1u);
  EXPECT_EQ(back->comparison->resolvedColourMaxDelta, back->comparison->colourMaxDelta);
}

// A file written before the wider colour formats: its deltas are 8-bit steps; a unit that is not
// a string is named.
TEST(ResultsJson, ColourUnitIsOptional) {
  json value = sceneResultToJson(everyFieldSet());
  EXPECT_EQ(value["comparison"]["colour_unit"], "half ULPs");
  value["comparison"].erase("colour_unit");
  const auto back = sceneResultFromJson(value);
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(back->comparison);
  EXPECT_EQ(back->comparison->colourUnit, "8-bit steps");
  value["comparison"]["colour_unit"] = 8;
  const auto bad = sceneResultFromJson(value);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("/comparison/colour_unit: expected a string"), std::string::npos) << bad.error();
}

TEST(ResultsJson, DefaultsCrashesTimeoutsAndNonFiniteNumbers) {
  SceneResult crashed;
  crashed.entry = {"broken", "broken.json"};
  crashed.error = "worker killed by signal 11 (SIGSEGV)";
  expectSame(crashed, throughText(crashed));
  SceneResult timedOut = crashed;
  timedOut.outcome = timedOut.actual = Outcome::Timeout;
  timedOut.milliseconds = std::numeric_limits<double>::quiet_NaN();
  timedOut.softMilliseconds = -std::numeric_limits<double>::infinity();
  expectSame(timedOut, throughText(timedOut));
  EXPECT_EQ(sceneResultToJson(timedOut)["outcome"], "Timeout");
  EXPECT_EQ(sceneResultToJson(timedOut)["milliseconds"], "nan");
  EXPECT_EQ(sceneResultToJson(everyFieldSet())["comparison"]["psnr"], "inf");
}

TEST(ResultsJson, CborCarriesBytesThatAreNotUtf8) {
  SceneResult r = everyFieldSet();
  r.entry.path = "scenes/bad\xFF\xC3name.json";
  r.error = "scenes/bad\xFF\xC3name.json: cannot open scene file";
  expectSame(r, throughCbor(r));
}

TEST(ResultsJson, RunResultsRoundTrip) {
  RunResults run;
  run.scenes = {everyFieldSet(), SceneResult{}};
  run.scenes[1].entry = {"second", "s/second.json"};
  run.suite = {{"room", "scenes/room.json"}, {"other", "scenes/other.json"}, {"second", "s/second.json"}};
  run.shard = {2, 3};
  run.suiteName = "crosscheck.conformance";
  run.renderArguments = "--softraster-fma separate --set camera.yaw=90";
  run.commandLine = "crosscheck conformance --jobs 2";  // not part of the record
  run.junitFile = "out/conformance.junit.xml";
  run.seconds = 12.5;
  run.jobs = 2;
  run.finished = 1735689600;
  const auto back = runResultsFromJson(json::parse(runResultsToJson(run).dump()));
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->suiteName, run.suiteName);
  ASSERT_EQ(back->suite.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back->suite[i].name, run.suite[i].name);
    EXPECT_EQ(back->suite[i].path, run.suite[i].path);
  }
  EXPECT_EQ(back->shard.index, 2u);
  EXPECT_EQ(back->shard.count, 3u);
  EXPECT_EQ(back->renderArguments, run.renderArguments);
  EXPECT_EQ(back->commandLine, "");
  EXPECT_EQ(runResultsToJson(run)["format"], kResultsFormat);
  EXPECT_EQ(back->junitFile, run.junitFile);
  EXPECT_EQ(back->seconds, run.seconds);
  EXPECT_EQ(back->jobs, run.jobs);
  EXPECT_EQ(back->finished, run.finished);
  ASSERT_EQ(back->scenes.size(), 2u);
  expectSame(back->scenes[0], run.scenes[0]);
  expectSame(back->scenes[1], run.scenes[1]);
  EXPECT_EQ(junitXml(*back), junitXml(run));
}

TEST(ResultsJson, MalformedValuesNameTheField) {
  const json good = sceneResultToJson(everyFieldSet());
  const auto errorOf = [](const json& value) {
    const auto r = sceneResultFromJson(value);
    EXPECT_FALSE(r);
    return r ? std::string() : r.error();
  };
  json missing = good;
  missing["comparison"].erase("psnr");
  EXPECT_EQ(errorOf(missing), "results JSON: /comparison/psnr: missing");
  json wrongType = good;
  wrongType["width"] = "wide";
  EXPECT_EQ(errorOf(wrongType), "results JSON: /width: expected a whole number from 0 to 4294967295");
  json tooBig = good;
  tooBig["width"] = 4294967296ull;
  EXPECT_EQ(errorOf(tooBig), "results JSON: /width: expected a whole number from 0 to 4294967295");
  json badOutcome = good;
  badOutcome["outcome"] = "Flake";
  EXPECT_EQ(errorOf(badOutcome), "results JSON: /outcome: 'Flake' is not an outcome");
  json shortArray = good;
  shortArray["comparison"]["colour_max_delta"] = {1, 2, 3};
  EXPECT_EQ(errorOf(shortArray), "results JSON: /comparison/colour_max_delta: expected an array of 4");
  json badNumber = good;
  badNumber["milliseconds"] = "fast";
  EXPECT_EQ(errorOf(badNumber), "results JSON: /milliseconds: expected a number (or \"inf\", \"-inf\", \"nan\")");
  EXPECT_EQ(errorOf(json::array()), "results JSON: /: expected an object");
  const auto run = runResultsFromJson(json{{"suite_name", "x"}});
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error(), "results JSON: /format: missing");
  json badShard = runResultsToJson(RunResults{});
  badShard["shard"]["index"] = 4;
  const auto shard = runResultsFromJson(badShard);
  ASSERT_FALSE(shard);
  EXPECT_EQ(shard.error(), "results JSON: /shard: expected 1 <= index <= count");
}

}  // namespace
