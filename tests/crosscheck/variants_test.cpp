// run/variants.hpp: the variant list follows softraster::kMethods; a variant that cannot draw a
// scene (the 1/z depth buffer on a D16 framebuffer) is a row with its error and the others are
// measured; hit counting finds nothing wrong with exact on the closed sphere and finds the holes
// of a frame with pixels taken away (compareHits by hand).
#include "render/render.hpp"
#include "run/variants.hpp"
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

using namespace crosscheck;

const std::filesystem::path kScenes = SCENES_DIR;

TEST(Variants, OnePerMethodAndDepthModeAndAffineForTheCourseMethods) {
  const auto variants = chartVariants();
  std::size_t course = 0;
  for (softraster::Method m : softraster::kMethods) course += softraster::isCourseMethod(m) ? 1 : 0;
  ASSERT_EQ(variants.size(), 2 * softraster::kMethods.size() + course);
  EXPECT_EQ(variants[0].label, "exact");
  EXPECT_EQ(variants[1].label, "exact 1/z");
  std::size_t at = 0;
  for (softraster::Method m : softraster::kMethods) {
    EXPECT_EQ(variants[at].options.method, m);
    EXPECT_EQ(variants[at].options.depthMode, softraster::DepthMode::Vulkan);
    EXPECT_FALSE(variants[at].options.affineVaryings);
    EXPECT_EQ(variants[at + 1].options.depthMode, softraster::DepthMode::InverseZ);
    at += 2;
    if (softraster::isCourseMethod(m)) {
      EXPECT_EQ(variants[at].label, std::string(softraster::methodName(m)) + " affine");
      EXPECT_TRUE(variants[at].options.affineVaryings);
      ++at;
    }
  }
}

TEST(Variants, AFailingVariantIsARow) {
  const auto scene = loadScene(kScenes / "depth_d16.json");
  ASSERT_TRUE(scene) << scene.error();
  const auto vulkan = openVulkan({});
  ASSERT_TRUE(vulkan) << vulkan.error();
  VariantOptions options;
  options.frames = 1;
  const VariantResults results = runVariants(*scene, chartVariants(), **vulkan, options);
  ASSERT_EQ(results.runs.size(), chartVariants().size());
  EXPECT_GT(results.lavapipeMilliseconds, 0);
  for (const VariantRun& run : results.runs) {
    if (run.depth == "1/z") {
      EXPECT_NE(run.error.find("D32_SFLOAT"), std::string::npos) << run.label << ": " << run.error;
      EXPECT_FALSE(run.coverageMismatches);
    } else if (run.method.rfind("exact", 0) == 0) {
      EXPECT_TRUE(run.ok()) << run.error;
      EXPECT_EQ(run.frameMilliseconds.size(), 1u);
      EXPECT_EQ(run.differingPixels, 0u) << run.label;
      EXPECT_EQ(run.withinTolerance, true) << run.label;
    }
  }
}

TEST(Variants, HitsOfTheClosedSphere) {
  const auto scene = loadScene(kScenes / "stability" / "closed_mesh_edges.json");
  ASSERT_TRUE(scene) << scene.error();
  const auto vulkan = openVulkan({});
  ASSERT_TRUE(vulkan) << vulkan.error();
  const Scene counting = hitCountScene(*scene);
  const auto reference = renderVulkan(counting, **vulkan);
  ASSERT_TRUE(reference) << reference.error();
  auto soft = renderSoftraster(counting, {});
  ASSERT_TRUE(soft) << soft.error();
  const HitCounts same = compareHits(*soft, *reference);
  EXPECT_GT(same.referenceCovered, 1000u);
  EXPECT_EQ(same.cracks, 0u);
  EXPECT_EQ(same.doubleHits, 0u);
  // Every pixel is hit at most once by lavapipe: a closed mesh with back faces culled.
  for (std::size_t i = 0; i < reference->rgba.size(); i += 4) ASSERT_LE(reference->rgba[i], 1) << "pixel " << i / 4;
  // Take three hits away and add two: three cracks, two double hits.
  std::size_t removed = 0, added = 0;
  for (std::size_t i = 0; i < soft->rgba.size() && (removed < 3 || added < 2); i += 4) {
    if (soft->rgba[i] == 1 && removed < 3) {
      soft->rgba[i] = 0;
      ++removed;
    } else if (soft->rgba[i] == 1 && added < 2) {
      soft->rgba[i] = 2;
      ++added;
    }
  }
  const HitCounts broken = compareHits(*soft, *reference);
  EXPECT_EQ(broken.cracks, 3u);
  EXPECT_EQ(broken.doubleHits, 2u);
}

}  // namespace

TEST(Variants, HitsAreCountedWithTheStencilTestOff) {
  // The stencil would mask what a rasterizer covered: the counting scene turns it off.
  const auto scene = loadScene(kScenes / "stencil_mask_two_pass.json");
  ASSERT_TRUE(scene) << scene.error();
  ASSERT_TRUE(scene->draws[1].state.depth.stencilTestEnable);
  for (const auto& draw : hitCountScene(*scene).draws) EXPECT_FALSE(draw.state.depth.stencilTestEnable) << draw.name;
}
