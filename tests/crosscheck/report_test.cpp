// The HTML report without a browser: page structure (summary table, worst-first order, lazy
// images, nothing from the network), the images written per scene, and the value readout's pixel
// data decoded back to the frames' exact bytes. The page in a real browser: report_chromium_test.sh.
#include "output/artifacts.hpp"
#include "output/report/report.hpp"
#include "run/conformance.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace {

using namespace crosscheck;
namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(TEST_DATA_DIR) / "conformance";
const fs::path kArtifacts = ARTIFACTS_DIR;

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::vector<std::uint8_t> fromBase64(const std::string& text) {
  static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  std::uint32_t buffer = 0;
  int bits = 0;
  for (char c : text) {
    if (c == '=') break;
    buffer = (buffer << 6) | static_cast<std::uint32_t>(kAlphabet.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>(buffer >> bits));
    }
  }
  return out;
}

std::vector<std::uint8_t> inflated(const std::vector<std::uint8_t>& data, std::size_t size) {
  std::vector<std::uint8_t> out(size + 1);
  uLongf length = static_cast<uLongf>(out.size());
  EXPECT_EQ(uncompress(out.data(), &length, data.data(), static_cast<uLong>(data.size())), Z_OK);
  out.resize(length);
  return out;
}

// Runs the fixtures like `crosscheck report` does and writes the report into the artifacts.
std::vector<SceneResult> runIntoReport(const fs::path& dir) {
  fs::remove_all(dir);
  ConformanceOptions options;
  options.onFrames = [&](SceneResult& result, const Scene& scene, const Frame& soft, const Frame& vulkan) {
    const softraster::Status images = writeSceneImages(dir, result.entry.name, &result, scene, soft, vulkan);
    return !images ? images : writePixelData(dir, fs::path(result.entry.name) / "pixels.js", &result, soft, vulkan);
  };
  std::vector<SceneEntry> suite;
  for (const char* name : {"broken_obj", "depth_slope", "flat_triangle", "malformed"}) {
    suite.push_back({name, kFixtures / (std::string(name) + ".json")});
  }
  return runConformance(suite, options);
}

TEST(Report, PageHasSummaryTableLazyImagesAndNoNetwork) {
  const fs::path dir = kArtifacts / "report-unit";
  const auto results = runIntoReport(dir);
  RunResults run;
  run.scenes = results;
  run.finished = std::time(nullptr);
  run.commandLine = "crosscheck report";
  run.seconds = 1.5;
  run.jobs = 2;
  const softraster::Status written = writeReport(dir, run);
  ASSERT_TRUE(written) << written.message();
  std::ifstream in(dir / "index.html");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string html = buffer.str();

  EXPECT_EQ(count(html, "<table id=\"summary\""), 1u);
  EXPECT_EQ(count(html, "<tr class=\"st-"), 4u);                // one row per scene
  EXPECT_EQ(count(html, "<details class=\"scene"), 4u);         // one section per scene
  // Two scenes rendered: seven views and the onion-skin/wipe stack's two images each, and a
  // thumbnail in the table; every image lazy.
  EXPECT_EQ(count(html, "<img loading=\"lazy\""), 2u * 8u);
  EXPECT_EQ(count(html, "<img class=\"stack-top\" loading=\"lazy\""), 2u);
  EXPECT_EQ(count(html, "<img class=\"thumb\" loading=\"lazy\""), 2u);
  EXPECT_EQ(count(html, "<img "), 2u * 10u);
  EXPECT_EQ(count(html, "data-pixels=\""), 2u);
  EXPECT_NE(html.find("image-rendering: pixelated"), std::string::npos);
  EXPECT_NE(html.find("<p class=\"counts\">2 passed, 2 failed</p>"), std::string::npos);
  EXPECT_FALSE(std::regex_search(html, std::regex("(src|href)=\"(https?:)?//"))) << "refers to the network";
  EXPECT_EQ(html.find("<link"), std::string::npos) << "a stylesheet from elsewhere";
  // Worst first: the two crashes (by name), then the passes.
  const auto at = [&](const std::string& name) {
    const auto position = html.find(">" + name + "</a>");
    EXPECT_NE(position, std::string::npos) << name;
    return position;
  };
  EXPECT_LT(at("broken_obj"), at("malformed"));
  EXPECT_LT(at("malformed"), at("depth_slope"));
  EXPECT_LT(at("depth_slope"), at("flat_triangle"));
  // Triage: both crashes listed at the top and as expectations lines, their error in the table,
  // the counts that decide a result as columns, a stable anchor and the command per scene.
  EXPECT_NE(html.find("<h2>Unexpected results (2)</h2>"), std::string::npos);
  EXPECT_EQ(count(html, "<div class=\"row-error\">"), 2u);
  EXPECT_NE(html.find(">broken_obj,Crash # "), std::string::npos) << "expectations line, worst first";
  EXPECT_NE(html.find("\nmalformed,Crash # "), std::string::npos) << "expectations line";
  EXPECT_NE(html.find(">colour pixels over</th>"), std::string::npos);
  EXPECT_NE(html.find(">depth pixels over</th>"), std::string::npos);
  EXPECT_NE(html.find("href=\"#scene=depth_slope\""), std::string::npos);
  EXPECT_NE(html.find("<code class=\"reproduce\">crosscheck compare "), std::string::npos);
  EXPECT_NE(html.find("id=\"filter-unexpected\""), std::string::npos);
  for (const SceneResult& r : results) {
    for (const SceneImage& image : r.images) {
      EXPECT_TRUE(fs::is_regular_file(dir / image.file)) << image.file;
      EXPECT_NE(html.find("src=\"" + image.file.generic_string() + "\""), std::string::npos) << image.file;
    }
  }
}

TEST(Report, WorstFirstOrdersByStatusThenMetrics) {
  std::vector<SceneResult> results(5);
  const Outcome outcomes[] = {Outcome::Pass, Outcome::Fail, Outcome::Skip, Outcome::Fail, Outcome::Crash};
  for (std::size_t i = 0; i < results.size(); ++i) {
    results[i].entry.name = "s" + std::to_string(i);
    results[i].outcome = outcomes[i];
    if (outcomes[i] == Outcome::Fail || outcomes[i] == Outcome::Pass) results[i].comparison = Comparison{};
  }
  results[1].comparison->coverageMismatches = 2;
  results[3].comparison->coverageMismatches = 9;
  EXPECT_EQ(worstFirst(results), (std::vector<std::size_t>{4, 3, 1, 0, 2}));
}

TEST(Report, MarksChangesAgainstABaseline) {
  const auto scene = [](const std::string& name, Outcome outcome, std::uint64_t mismatches) {
    SceneResult r;
    r.entry = {name, name + ".json"};
    r.outcome = r.actual = outcome;
    r.comparison = Comparison{};
    r.comparison->coverageMismatches = mismatches;
    return r;
  };
  RunResults before, now;
  before.scenes = {scene("broke", Outcome::Pass, 0), scene("mended", Outcome::Fail, 3), scene("same", Outcome::Pass, 0)};
  now.scenes = {scene("broke", Outcome::Fail, 12), scene("mended", Outcome::Pass, 0), scene("same", Outcome::Pass, 0)};
  ReportBaseline baseline;
  baseline.file = "old/results.json";
  baseline.versus = compareWithBaseline(now, before);
  const std::string html = reportHtml(now, {}, &baseline);
  EXPECT_NE(html.find("1 new failure</b> \xC2\xB7 1 fixed \xC2\xB7 2 scenes with changed metrics</p>"), std::string::npos) << html;
  EXPECT_EQ(count(html, "<span class=\"mark mark-new-failure\""), 3u) << "table, list at the top, section";
  EXPECT_EQ(count(html, "<span class=\"mark mark-fixed\""), 2u) << "table, section";
  EXPECT_EQ(count(html, "<td class=\"num over changed\""), 1u) << "broke's coverage, over its limit";
  EXPECT_NE(html.find("title=\"allowed 0; baseline 0\">12</td>"), std::string::npos);
  EXPECT_NE(html.find("against the baseline: Pass \xE2\x86\x92 Fail; coverage mismatches 0 \xE2\x86\x92 12"), std::string::npos);
  EXPECT_NE(html.find("data-name=\"same\" data-baseline=\"\""), std::string::npos);
  EXPECT_NE(html.find("id=\"filter-baseline\""), std::string::npos);
  EXPECT_EQ(reportHtml(now).find("id=\"filter-baseline\""), std::string::npos) << "no baseline, no filter";
  EXPECT_EQ(reportHtml(now).find("baseline-summary\""), std::string::npos);
}

TEST(Report, PixelDataDecodesToTheFramesExactly) {
  Frame soft, vulkan;
  soft.width = vulkan.width = 3;
  soft.height = vulkan.height = 2;
  for (int i = 0; i < 24; ++i) soft.rgba.push_back(static_cast<std::uint8_t>(i * 11)), vulkan.rgba.push_back(static_cast<std::uint8_t>(255 - i));
  soft.depth = {0.0f, 0.25f, 0.5f, 1.0f, 0x1p-24f, 0.99999994f};
  vulkan.depth = {1.0f, 0.75f, 0.5f, 0.125f, 0x1p-23f, 0.3f};
  const std::string script = pixelDataScript("name \"quoted\" </script>", soft, vulkan);
  const std::string prefix = "crosscheckPixels(";
  ASSERT_EQ(script.rfind(prefix, 0), 0u);
  ASSERT_EQ(script.substr(script.size() - 3), ");\n");
  // The call's arguments are JSON: parse them as an array.
  const auto args = nlohmann::json::parse("[" + script.substr(prefix.size(), script.size() - prefix.size() - 3) + "]");
  EXPECT_EQ(args[0], "name \"quoted\" </script>");
  const auto& d = args[1];
  EXPECT_EQ(d["w"], 3);
  EXPECT_EQ(d["h"], 2);
  EXPECT_EQ(inflated(fromBase64(d["soft"]), 24), soft.rgba);
  EXPECT_EQ(inflated(fromBase64(d["vulkan"]), 24), vulkan.rgba);
  const auto depthBytes = inflated(fromBase64(d["softDepth"]), 24);
  ASSERT_EQ(depthBytes.size(), 24u);
  for (std::size_t i = 0; i < 6; ++i) {
    std::uint32_t bits = 0;
    for (int b = 0; b < 4; ++b) bits |= std::uint32_t{depthBytes[4 * i + b]} << (8 * b);  // little-endian
    EXPECT_EQ(std::bit_cast<float>(bits), soft.depth[i]) << i;
  }
  EXPECT_EQ(inflated(fromBase64(d["vulkanDepth"]), 24).size(), 24u);
}

// An MSAA scene that differs gets each sample's images, and its section a menu to pick one: with
// softraster following the spec at the MSAA scissor, lavapipe's extra samples (1..3, in a column
// and a row) differ while sample 0 does not, which only the per-sample views show.
TEST(Report, MsaaScenesGetEverySampleAndAMenuToPickOne) {
  const fs::path dir = kArtifacts / "report-samples";
  fs::remove_all(dir);
  ConformanceOptions options;
  options.isolation = Isolation::Threads;
  options.softraster.deviations = softraster::Deviations::Spec;
  std::array<std::size_t, 4> differing{};
  options.onFrames = [&](SceneResult& result, const Scene& scene, const Frame& soft, const Frame& vulkan) {
    EXPECT_EQ(soft.samples, 4u);
    for (std::size_t k = 0; k < soft.sampleRgba.size() / 4; ++k) {
      if (!std::equal(&soft.sampleRgba[4 * k], &soft.sampleRgba[4 * k] + 4, &vulkan.sampleRgba[4 * k])) ++differing[k % 4];
    }
    return writeSceneImages(dir, result.entry.name, &result, scene, soft, vulkan, SceneImageSet::Compact);
  };
  const fs::path scene = fs::path(SOURCE_DIR) / "scenes" / "msaa_scissor_viewport.json";
  const std::vector<SceneResult> results = runConformance({{"msaa_scissor_viewport", scene}}, options);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].outcome, Outcome::Fail) << results[0].error;
  EXPECT_EQ(differing[0], 0u) << "lavapipe's scissor planes never let sample 0 through";
  EXPECT_GT(differing[3], 100u);
  for (const std::string n : {"0", "1", "2", "3"}) {
    for (const std::string& kind : {"soft.sample" + n, "vulkan.sample" + n, "sample" + n + ".diff"}) {
      const auto image = std::find_if(results[0].images.begin(), results[0].images.end(),
                                      [&](const SceneImage& i) { return i.kind == kind; });
      ASSERT_NE(image, results[0].images.end()) << kind;
      EXPECT_TRUE(fs::exists(dir / image->file)) << image->file;
    }
  }
  RunResults run;
  run.scenes = results;
  const std::string html = reportHtml(run, dir);
  EXPECT_EQ(count(html, "<select class=\"sample-pick\">"), 1u);
  EXPECT_EQ(count(html, "<option value=\"3\">3</option>"), 1u);
  EXPECT_EQ(count(html, " data-samples=\"msaa_scissor_viewport/soft.sample0.png msaa_scissor_viewport/soft.sample1.png "
                        "msaa_scissor_viewport/soft.sample2.png msaa_scissor_viewport/soft.sample3.png\""),
            1u);
  EXPECT_EQ(count(html, " data-samples=\""), 3u);
}

// A scene with several colour attachments that differs only in a later attachment still gets
// every image (not the compact preview), and each attachment after the first its own three views.
TEST(Report, LaterColourAttachmentsGetTheirOwnViews) {
  const fs::path dir = kArtifacts / "report-attachments";
  fs::remove_all(dir);
  auto scene = loadScene(fs::path(SOURCE_DIR) / "scenes" / "colour_attachments.json");
  ASSERT_TRUE(scene) << scene.error();
  auto soft = renderSoftraster(*scene);
  ASSERT_TRUE(soft) << soft.error();
  SceneResult same;
  same.entry.name = "same";
  ASSERT_TRUE(writeSceneImages(dir, "same", &same, *scene, *soft, *soft, SceneImageSet::Compact));
  ASSERT_EQ(same.images.size(), 1u);
  EXPECT_EQ(same.images[0].kind, "preview");
  Frame changed = *soft;
  changed.moreColour[1].colourWords[700] ^= 0x3ffu;  // attachment 2's red in one pixel
  SceneResult result;
  result.entry.name = "colour_attachments";
  result.width = soft->width;
  result.height = soft->height;
  ASSERT_TRUE(writeSceneImages(dir, "colour_attachments", &result, *scene, *soft, changed, SceneImageSet::Compact));
  for (const std::string n : {"1", "2", "3"}) {
    for (const std::string& kind : {"soft.attachment" + n, "vulkan.attachment" + n, "attachment" + n + ".diff"}) {
      const auto image = std::find_if(result.images.begin(), result.images.end(),
                                      [&](const SceneImage& i) { return i.kind == kind; });
      ASSERT_NE(image, result.images.end()) << kind;
      EXPECT_TRUE(fs::exists(dir / image->file)) << image->file;
    }
  }
  RunResults run;
  run.scenes = {result};
  const std::string html = reportHtml(run, dir);
  EXPECT_EQ(count(html, "<figcaption>colour attachment 2 difference (heatmap)</figcaption>"), 1u);
  EXPECT_EQ(count(html, "<figcaption>Vulkan colour attachment 3</figcaption>"), 1u);
  EXPECT_EQ(count(html, "src=\"colour_attachments/attachment2.diff.png\""), 1u);
}

TEST(Report, DepthViewsShareOneRange) {
  Frame a, b;
  a.depth = {1.0f, 0.4f, 0.6f};
  b.depth = {0.3f, 1.0f, 0.5f};
  EXPECT_EQ(sharedDepthRange(a, b, 1.0f), std::make_pair(0.3f, 0.6f));
  Frame flat;
  flat.depth = {1.0f, 0.75f};
  EXPECT_EQ(sharedDepthRange(flat, flat, 1.0f), std::make_pair(0.75f, 1.0f));  // one depth: up to the clear depth
  Frame empty;
  empty.depth = {1.0f, 1.0f};
  EXPECT_EQ(sharedDepthRange(empty, empty, 1.0f), std::make_pair(0.0f, 1.0f));
}

}  // namespace
