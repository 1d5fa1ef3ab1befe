// The bench runner and its JSON on a tiny scene: every renderer gives timed frames, each
// softraster method agrees with lavapipe to the bit, and the JSON has the documented fields.
// Never asserts on timings (the machine is shared): only that they exist and are ordered.
#include "output/bench_json.hpp"
#include "output/bench_table.hpp"
#include "run/bench.hpp"
#include "scene/scene.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

const std::filesystem::path kTinySphere = std::filesystem::path(TEST_DATA_DIR) / "bench" / "tiny_sphere.json";

crosscheck::BenchResults benchTiny() {
  auto scene = crosscheck::loadScene(kTinySphere);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  std::vector<crosscheck::Scene> scenes;
  scenes.push_back(std::move(*scene));
  crosscheck::BenchOptions options;
  options.frames = 2;
  options.warmup = 1;
  options.threads = 2;
  return crosscheck::runBench(scenes, options, crosscheck::measureMachine());
}

}  // namespace

TEST(Bench, TinySceneHasEveryRendererAndExactAgreement) {
  const crosscheck::BenchResults results = benchTiny();
  ASSERT_EQ(results.scenes.size(), 1u);
  const crosscheck::BenchScene& scene = results.scenes[0];
  EXPECT_EQ(scene.pixels, 48u * 32u);
  EXPECT_EQ(scene.triangles, 2u * 16u * 8u);
  EXPECT_EQ(scene.bytesWritten, 48u * 32u * 8u);
  EXPECT_GT(scene.memoryLimitMilliseconds, 0);
  ASSERT_EQ(scene.runs.size(), 3u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"softraster", "exact"}, {"softraster", "exact-scalar"}, {"lavapipe", ""}};
  for (std::size_t i = 0; i < 3; ++i) {
    const crosscheck::BenchRun& run = scene.runs[i];
    SCOPED_TRACE(run.renderer + " " + run.method);
    EXPECT_TRUE(run.ok()) << run.error;
    EXPECT_EQ(run.renderer, expected[i].first);
    EXPECT_EQ(run.method, expected[i].second);
    EXPECT_EQ(run.frameMilliseconds.size(), 2u);
    EXPECT_LE(run.minMilliseconds, run.medianMilliseconds);
    EXPECT_GT(run.setupMilliseconds, 0);
    EXPECT_GT(run.ratioVsLavapipe, 0);
    EXPECT_GE(run.threads, 1u);
    if (run.renderer == "lavapipe") {
      EXPECT_FALSE(run.agreement);
      EXPECT_EQ(run.threads, 2u);
      continue;
    }
    ASSERT_TRUE(run.agreement);
    EXPECT_EQ(run.agreement->coverageMismatches, 0u);
    for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(run.agreement->colourMaxDelta[ch], 0) << "channel " << ch;
    EXPECT_EQ(run.agreement->depthMaxDelta, 0.0);
  }
  EXPECT_EQ(scene.runs[0].threads, 2u);
  EXPECT_EQ(scene.runs[1].threads, 1u);  // the scalar method draws on the calling thread alone
  EXPECT_TRUE(results.allAgree());
  EXPECT_FALSE(results.machine.cpu.empty());
  EXPECT_GE(results.machine.cores, 1u);
  EXPECT_GT(results.machine.memsetGigabytesPerSecond, 0);
  EXPECT_GT(results.machine.memsetWarmGigabytesPerSecond, 0);

  const std::string table = crosscheck::benchTable(results);
  EXPECT_NE(table.find("softraster exact-scalar"), std::string::npos) << table;
  EXPECT_NE(table.find("> 1: softraster is faster"), std::string::npos) << table;
  EXPECT_NE(table.find("0/0/0"), std::string::npos) << table;
}

TEST(Bench, JsonHasTheDocumentedFields) {
  const crosscheck::BenchResults results = benchTiny();
  const auto json = nlohmann::json::parse(crosscheck::benchJson(results), nullptr, false);
  ASSERT_FALSE(json.is_discarded());
  ASSERT_TRUE(json.contains("machine"));
  EXPECT_TRUE(json["machine"]["cpu"].is_string());
  EXPECT_TRUE(json["machine"]["cores"].is_number_integer());
  EXPECT_TRUE(json["machine"]["memset_gb_per_s"].is_number());
  EXPECT_TRUE(json["machine"]["memset_warm_gb_per_s"].is_number());
  ASSERT_TRUE(json["machine"]["allocator"].is_string());
#if defined(__SANITIZE_ADDRESS__)
  EXPECT_EQ(json["machine"]["allocator"], "AddressSanitizer's allocator: its own (mallopt does not reach it)");
#elif defined(__GLIBC__)
  EXPECT_EQ(json["machine"]["allocator"], "glibc: mmap threshold 32 MiB, trim threshold 64 MiB");
#endif
  ASSERT_EQ(json["scenes"].size(), 1u);
  const auto& scene = json["scenes"][0];
  EXPECT_EQ(scene["scene"], kTinySphere.string());
  EXPECT_EQ(scene["pixels"], 48 * 32);
  EXPECT_EQ(scene["triangles"], 256);
  EXPECT_TRUE(scene["memory_limit_ms"].is_number());
  ASSERT_EQ(scene["results"].size(), 3u);
  for (const auto& r : scene["results"]) {
    SCOPED_TRACE(r.dump());
    for (const char* field : {"renderer", "threads", "median_ms", "min_ms", "setup_ms", "coverage_mismatches",
                              "colour_max_delta", "depth_max_delta", "ratio_vs_lavapipe"}) {
      EXPECT_TRUE(r.contains(field)) << field;
    }
    EXPECT_TRUE(r["median_ms"].is_number());
    EXPECT_TRUE(r["min_ms"].is_number());
    EXPECT_TRUE(r["setup_ms"].is_number());
    EXPECT_TRUE(r["threads"].is_number_integer());
    EXPECT_TRUE(r["ratio_vs_lavapipe"].is_number());
    if (r["renderer"] == "softraster") {
      EXPECT_TRUE(r["method"] == "exact" || r["method"] == "exact-scalar");
      EXPECT_EQ(r["coverage_mismatches"], 0);
      EXPECT_EQ(r["colour_max_delta"], 0);
      EXPECT_EQ(r["colour_unit"], "8-bit steps");
      EXPECT_EQ(r["depth_max_delta"], 0.0);
    } else {
      EXPECT_EQ(r["renderer"], "lavapipe");
      EXPECT_FALSE(r.contains("method"));
    }
  }
}

// --method's list: all, names in order (repeats dropped), +affine on course methods only.
TEST(Bench, MethodListsParse) {
  using crosscheck::BenchMethod;
  using softraster::Method;
  const auto all = crosscheck::parseBenchMethods("all");
  ASSERT_TRUE(all);
  ASSERT_EQ(all->size(), softraster::kMethods.size());
  for (std::size_t i = 0; i < all->size(); ++i) EXPECT_EQ((*all)[i], BenchMethod{softraster::kMethods[i]});
  const auto list = crosscheck::parseBenchMethods("trapezoid,exact,trapezoid+affine,exact");
  ASSERT_TRUE(list);
  EXPECT_EQ(*list, (std::vector<BenchMethod>{{Method::Trapezoid}, {Method::Exact}, {Method::Trapezoid, true}}));
  EXPECT_EQ((*list)[2].label(), "trapezoid+affine");
  for (const char* bad : {"", "fast", "exact,", ",exact", "exact+affine", "exact-scalar+affine", "scanline+", "+affine",
                          "scanline+affine+affine", "ALL"}) {
    EXPECT_FALSE(crosscheck::parseBenchMethods(bad)) << bad;
  }
}

#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__)  // (AddressSanitizer replaces malloc)
// What settleAllocator is for: a block well above glibc's starting mmap threshold (128 KiB), and
// above any block this test process has freed, comes from the heap and not from a fresh mapping
// (mallinfo2's hblks counts the mapped blocks), and stays there once freed and asked for again.
TEST(Bench, SettledAllocatorKeepsLargeBlocksOffMmap) {
  ASSERT_EQ(crosscheck::settleAllocator(), "glibc: mmap threshold 32 MiB, trim threshold 64 MiB");
  const std::size_t bytes = std::size_t{24} << 20;
  const int mappedBefore = mallinfo2().hblks;
  for (int round = 0; round < 2; ++round) {
    void* block = std::malloc(bytes);
    ASSERT_NE(block, nullptr);
    asm volatile("" : : "r"(block) : "memory");  // the block is used: the compiler keeps the malloc
    EXPECT_EQ(mallinfo2().hblks, mappedBefore) << "round " << round << ": the 24 MiB block was mapped";
    std::free(block);
  }
}
#endif
