// Issue 13's topology and primitive state, cross-checked: the negative-height viewport, primitive
// restart, provoking vertex last, stippled lines (polygon-mode lines too) and the adjacency
// topologies, each on its scene in both renderers (the fast and the scalar exact paths) under the
// validation layer, to the bit, with a check that the state changes the picture; then every
// scene-loader error these states add, each one line naming the file and quoting the Vulkan rule.
// Last, the known deviation (4x MSAA scissor): softraster in spec mode differs from lavapipe
// exactly where lavapipe's scissor planes reach past the rectangle, and the conformance runner and
// results.json say so.
#include "agreement.hpp"
#include "output/report/report.hpp"
#include "results/results_json.hpp"
#include "run/conformance.hpp"
#include "run/deviations.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using agreement::expectSceneError;
using agreement::pixelsDiffering;
using agreement::renderAgreeing;

std::size_t coveredPixels(const crosscheck::Frame& f) {
  crosscheck::Frame clear = f;
  for (std::size_t i = 0; i + 3 < clear.rgba.size(); i += 4) {
    clear.rgba[i] = clear.rgba[i + 1] = clear.rgba[i + 2] = 26;  // the scenes' clear colour 0.1
  }
  return pixelsDiffering(f, clear);
}

TEST(Topology, NegativeViewportHeightMatchesAndFlips) {
  const crosscheck::Frame flipped = renderAgreeing("viewport_flip", {});
  EXPECT_GT(coveredPixels(flipped), 2000u);
  // Culling follows the flipped winding: with the ordinary viewport the other triangle survives.
  const crosscheck::Frame ordinary = renderAgreeing("viewport_flip", {"draws.0.viewport={\"width\":256,\"height\":192}"});
  EXPECT_GT(pixelsDiffering(flipped, ordinary), 500u);
  // A flipped viewport at the framebuffer's bottom edge, and one beyond its top.
  renderAgreeing("viewport_flip", {"draws.5.viewport={\"x\":3.5,\"y\":192,\"width\":200,\"height\":-60.25}"});
  renderAgreeing("viewport_flip", {"draws.4.viewport={\"x\":0,\"y\":100,\"width\":256,\"height\":-150}"});
  // With 4x MSAA (softraster draws only triangles there: the lines and points become triangles).
  renderAgreeing("viewport_flip", {"framebuffer.samples=4", "draws.6.topology=triangle_strip",
                                   "draws.7.topology=triangle_list", "draws.7.cull=none"});
}

TEST(Topology, PrimitiveRestartMatches) {
  for (const char* name : {"primitive_restart_strip", "primitive_restart_line_strip", "primitive_restart_fan"}) {
    SCOPED_TRACE(name);
    EXPECT_GT(coveredPixels(renderAgreeing(name, {})), 1000u);
  }
  // Each run starts its strip's winding afresh: culling the other face shows the other triangles.
  const crosscheck::Frame back = renderAgreeing("primitive_restart_strip", {});
  const crosscheck::Frame front = renderAgreeing("primitive_restart_strip", {"draws.0.cull=front"});
  EXPECT_GT(pixelsDiffering(back, front), 1000u);
}

TEST(Topology, ProvokingVertexLastMatchesAndChangesFlatColours) {
  const crosscheck::Frame last = renderAgreeing("provoking_vertex_last", {});
  std::vector<std::string> first;
  for (int d = 0; d < 9; ++d) first.push_back("draws." + std::to_string(d) + ".provoking_vertex=first");
  const crosscheck::Frame firstFrame = renderAgreeing("provoking_vertex_last", first);
  EXPECT_GT(pixelsDiffering(last, firstFrame), 3000u);
  // Flat colours on the adjacency strip too (provoking vertex last there).
  renderAgreeing("adjacency", {});
}

TEST(Topology, StippledLinesMatch) {
  for (const char* name : {"line_stipple", "line_stipple_bresenham"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame stippled = renderAgreeing(name, {});
    EXPECT_GT(coveredPixels(stippled), 1000u);
    // Another pattern and factor on the strip moves its dashes.
    const crosscheck::Frame other = renderAgreeing(name, {"draws.2.line_stipple={\"factor\":5,\"pattern\":4369}"});
    EXPECT_GT(pixelsDiffering(stippled, other), 50u);
  }
  // Stippled strips with provoking vertex last (flat varyings on the segments).
  renderAgreeing("line_stipple", {"draws.2.shading=vertex_color_flat", "draws.2.provoking_vertex=last",
                                  "draws.3.shading=vertex_color_flat", "draws.3.provoking_vertex=last"});
}

// Stippled polygon-mode lines (Mesa's unfilled stage, then its stipple stage): both renderers agree,
// the stipple removes part of each outline, and points of polygon mode point are not stippled.
TEST(Topology, StippledPolygonModeLinesMatch) {
  for (const char* name : {"line_stipple_polygon_modes", "line_stipple_polygon_modes_bresenham"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame stippled = renderAgreeing(name, {});
    EXPECT_GT(coveredPixels(stippled), 800u);
    std::vector<std::string> solid;
    for (int d = 0; d < 7; ++d) {
      solid.push_back("draws." + std::to_string(d) + ".line_stipple={\"factor\":1,\"pattern\":65535}");
    }
    const crosscheck::Frame outlines = renderAgreeing(name, solid);
    EXPECT_GT(coveredPixels(outlines), coveredPixels(stippled) + 300u);
    // Only the point-mode draw (the last) solid: nothing changes.
    const crosscheck::Frame points = renderAgreeing(name, {solid.back()});
    EXPECT_EQ(pixelsDiffering(stippled, points), 0u);
    // The wide strip's other pattern moves its dashes.
    const crosscheck::Frame other = renderAgreeing(name, {"draws.1.line_stipple={\"factor\":5,\"pattern\":4369}"});
    EXPECT_GT(pixelsDiffering(stippled, other), 50u);
  }
}

TEST(Topology, AdjacencyTopologiesMatchAndIgnoreTheAdjacentVertices) {
  const crosscheck::Frame adjacency = renderAgreeing("adjacency", {});
  EXPECT_GT(coveredPixels(adjacency), 2000u);
  // Moving only the adjacent vertices of the indexed list changes nothing.
  const crosscheck::Frame moved = renderAgreeing("adjacency", {"draws.5.positions.3=[0.3,0.2,1.5]"});
  EXPECT_EQ(pixelsDiffering(adjacency, moved), 0u);
}

TEST(Topology, SceneErrorsQuoteTheRule) {
  const std::string flip = "viewport_flip.json";
  expectSceneError({"draws.0.viewport={\"width\":0,\"height\":192}"}, flip, "VUID-VkViewport-width-01770");
  expectSceneError({"draws.0.viewport={\"width\":256,\"height\":0}"}, flip, "/draws/0/viewport/height: must not be 0");
  expectSceneError({"draws.0.viewport={\"width\":256,\"height\":-20000}"}, flip, "VUID-VkViewport-height-01773");
  expectSceneError({"draws.0.viewport={\"y\":-32760,\"width\":256,\"height\":-100}"}, flip, "viewportBoundsRange");
  expectSceneError({"draws.0.point_size=300"}, flip, "pointSizeRange");
  expectSceneError({"draws.0.line_width=0.5"}, flip, "lineWidthRange");
  expectSceneError({"draws.0.primitive_restart=true"}, flip, "topology-06252");
  expectSceneError({"draws.0.primitive_restart=1"}, flip, "/draws/0/primitive_restart: expected true or false");
  expectSceneError({"draws.0.provoking_vertex=middle"}, flip, "/draws/0/provoking_vertex: 'middle' is not one of first, last");
  const std::string restart = "primitive_restart_fan.json";
  expectSceneError({"draws.0.primitive_restart=false"}, restart, "\"restart\" needs \"primitive_restart\": true");
  expectSceneError({"draws.0.topology=triangle_list"}, restart, "topology-06252");
  const std::string stipple = "line_stipple.json";
  expectSceneError({"draws.0.line_stipple={\"factor\":0,\"pattern\":1}"}, stipple, "stippledLineEnable-02767");
  expectSceneError({"draws.0.line_stipple={\"factor\":257,\"pattern\":1}"}, stipple, "must be in [1, 256]");
  expectSceneError({"draws.0.line_stipple={\"factor\":1,\"pattern\":65536}"}, stipple, "/draws/0/line_stipple/pattern");
  expectSceneError({"draws.0.line_stipple={\"factor\":1}"}, stipple, "needs \"factor\" and \"pattern\"");
  expectSceneError({"draws.0.line_stipple={\"factor\":1,\"pattern\":1,\"phase\":2}"}, stipple, "unknown field");
  expectSceneError({"draws.0.topology=patch_list"}, stipple, "'patch_list' is not one of");
}

TEST(Deviations, SpecModeDiffersOnlyInTheColumnAndRowLavapipesScissorPlanesReach) {
  const crosscheck::Frame driver = renderAgreeing("msaa_scissor_viewport", {});
  const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode("msaa_scissor_viewport");
  ASSERT_EQ(specFrames.size(), 2u);
  for (const crosscheck::Frame& spec : specFrames) {
    // The first draw's scissor is (37, 45), 100 x 80: lavapipe writes some samples of column 36
    // (rows 45..124), of row 44 (columns 37..136) and of pixel (36, 44); the spec none.
    std::size_t differing = 0;
    for (std::uint32_t y = 0; y < spec.height; ++y) {
      for (std::uint32_t x = 0; x < spec.width; ++x) {
        const std::size_t i = 4 * (std::size_t{y} * spec.width + x);
        if (std::equal(&spec.rgba[i], &spec.rgba[i] + 4, &driver.rgba[i])) continue;
        ++differing;
        const bool column = x == 36 && y >= 44 && y <= 124, row = y == 44 && x >= 36 && x <= 136;
        EXPECT_TRUE(column || row) << "pixel (" << x << ", " << y << ")";
      }
    }
    EXPECT_GT(differing, 100u);
  }
  // Without MSAA or without a scissor off the tile grid there is nothing to deviate from.
  auto flip = crosscheck::loadScene(agreement::kScenes / "viewport_flip.json", {});
  ASSERT_TRUE(flip) << flip.error();
  softraster::ContextOptions spec;
  spec.deviations = softraster::Deviations::Spec;
  auto a = crosscheck::renderSoftraster(*flip, spec), b = crosscheck::renderSoftraster(*flip, {});
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->rgba, b->rgba);
}

TEST(Deviations, TheRunnerMeasuresThemAndResultsJsonListsThem) {
  crosscheck::ConformanceOptions options;
  options.isolation = crosscheck::Isolation::Threads;
  const auto results = crosscheck::runConformance(
      {{"msaa_scissor_viewport", agreement::kScenes / "msaa_scissor_viewport.json"},
       {"viewport_flip", agreement::kScenes / "viewport_flip.json"}},
      options);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].outcome, crosscheck::Outcome::Pass) << results[0].error;
  ASSERT_TRUE(results[0].specDeviationPixels.has_value());
  EXPECT_GT(*results[0].specDeviationPixels, 100u);
  EXPECT_FALSE(results[1].specDeviationPixels.has_value()) << "not a deviation's scene";
  crosscheck::RunResults run;
  run.scenes = results;
  const nlohmann::json j = crosscheck::runResultsToJson(run);
  ASSERT_EQ(j["deviations"].size(), crosscheck::knownDeviations().size());
  EXPECT_EQ(j["deviations"][0]["scene"], "msaa_scissor_viewport");
  EXPECT_EQ(j["deviations"][0]["spec_mode_differing_pixels"], *results[0].specDeviationPixels);
  EXPECT_NE(j["deviations"][0]["spec"].get<std::string>().find("Scissor Test"), std::string::npos);
  const std::string html = crosscheck::reportHtml(run, ARTIFACTS_DIR, nullptr);
  EXPECT_NE(html.find("Deviations from the Vulkan spec"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">" + std::to_string(*results[0].specDeviationPixels) + "</td>"),
            std::string::npos);
  auto back = crosscheck::runResultsFromJson(j);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->scenes[0].specDeviationPixels, results[0].specDeviationPixels);
  EXPECT_FALSE(back->scenes[1].specDeviationPixels.has_value());
}

}  // namespace
