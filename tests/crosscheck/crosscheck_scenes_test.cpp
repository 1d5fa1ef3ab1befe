// Cross-checks: every scene in scenes/ rendered by softraster and by Vulkan on lavapipe, with the
// validation layer on (any message fails), compared within the scene's tolerance. Each scene is
// its own test case (CrossCheck/Scene.Matches/<name>), found when the test binary starts.
// On failure the soft, vulkan and diff images are written to build/test-artifacts/<scene>/.
#include "compare/compare.hpp"
#include "output/image_io.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include "scene_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kScenes = SCENES_DIR;
const std::filesystem::path kArtifacts = ARTIFACTS_DIR;

void writeArtifacts(const std::string& name, const crosscheck::Frame& soft, const crosscheck::Frame& vulkan,
                    const crosscheck::Scene& scene) {
  const auto dir = kArtifacts / name;
  crosscheck::writePng(dir / "soft.png", soft.width, soft.height, soft.rgba);
  crosscheck::writePng(dir / "vulkan.png", vulkan.width, vulkan.height, vulkan.rgba);
  crosscheck::writePng(dir / "diff.png", soft.width, soft.height, crosscheck::diffHeatmap(soft, vulkan, scene));
  ADD_FAILURE() << "images written to " << dir.string();
}

// A scene rendered by softraster (with `options`) and by Vulkan on lavapipe (with validation).
struct RenderedScene {
  std::optional<crosscheck::Scene> scene;
  std::optional<crosscheck::Frame> soft, reference;
  std::vector<std::string> validationMessages;
};

// Fails the calling test (ASSERT in a void helper) when anything cannot be rendered.
void renderBoth(const std::string& name, RenderedScene& out, const softraster::ContextOptions& options = {}) {
  auto scene = crosscheck::loadScene(conformanceScenePath(name));
  ASSERT_TRUE(scene) << scene.error();
  out.scene = std::move(*scene);
  vkref::DeviceOptions device;
  device.validation = true;
  const auto vulkan = crosscheck::openVulkan(device);
  ASSERT_TRUE(vulkan) << vulkan.error();
  auto soft = crosscheck::renderSoftraster(*out.scene, options);
  ASSERT_TRUE(soft) << soft.error();
  out.soft = std::move(*soft);
  auto reference = crosscheck::renderVulkan(*out.scene, **vulkan);
  ASSERT_TRUE(reference) << reference.error();
  out.reference = std::move(*reference);
  out.validationMessages = (*vulkan)->validationMessages();
}

void crossCheckScene(const std::string& name) {
  RenderedScene r;
  ASSERT_NO_FATAL_FAILURE(renderBoth(name, r));
  const auto& scene = r.scene;
  const auto& soft = r.soft;
  const auto& reference = r.reference;
  for (const std::string& message : r.validationMessages) ADD_FAILURE() << "validation: " << message;

  const crosscheck::Comparison c = crosscheck::compareFrames(*soft, *reference, *scene);
  ::testing::Test::RecordProperty("coverage_mismatches", std::to_string(c.coverageMismatches));
  ::testing::Test::RecordProperty("depth_max_delta", std::to_string(c.depthMaxDelta));
  EXPECT_LE(c.coverageMismatches, scene->tolerance.maxCoverageMismatches);
  EXPECT_LE(c.colourPixelsOver, scene->tolerance.maxColourPixelsOver);
  EXPECT_LE(c.depthPixelsOver, scene->tolerance.maxDepthPixelsOver);
  for (int ch = 0; ch < 4; ++ch) EXPECT_LE(c.colourMaxDelta[ch], scene->tolerance.colourThreshold) << "channel " << ch;
  EXPECT_LE(c.depthMaxDelta, scene->tolerance.depthThreshold);
  EXPECT_EQ(c.stencilMismatches, 0u) << "stencil is compared exactly";

  // The scene must actually draw something, or agreement proves nothing.
  EXPECT_GE(crosscheck::coveredPixels(*soft, *scene), 100u) << "the scene draws almost nothing";

  if (::testing::Test::HasFailure()) writeArtifacts(name, *soft, *reference, *scene);
}

std::vector<std::string> sceneNames() { return conformanceSceneNames(); }

class Scene : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(Scene, Matches) { crossCheckScene(GetParam()); }

INSTANTIATE_TEST_SUITE_P(CrossCheck, Scene, ::testing::ValuesIn(sceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

TEST(CrossCheck, SuiteIsNotEmpty) { EXPECT_GE(sceneNames().size(), 20u); }

// A closed mesh covers every pixel inside its silhouette exactly once (no cracks between shared
// edges, no double hits): sphere_coverage.json counts fragments in the red channel with additive
// blending. Checked in both renderers: no count above 1, and no uncovered pixel that cannot be
// reached from the image border through uncovered pixels (a hole inside the silhouette).
TEST(Stability, ClosedSphereCoversEachPixelOnce) {
  RenderedScene r;
  ASSERT_NO_FATAL_FAILURE(renderBoth("sphere_coverage", r));
  for (const auto* frame : {&*r.soft, &*r.reference}) {
    const int w = static_cast<int>(frame->width), h = static_cast<int>(frame->height);
    std::vector<std::uint8_t> count(static_cast<std::size_t>(w * h));
    std::size_t once = 0;
    for (std::size_t i = 0; i < count.size(); ++i) {
      count[i] = frame->rgba[4 * i];
      ASSERT_LE(count[i], 1) << "pixel (" << i % w << ", " << i / w << ") hit " << int{count[i]} << " times";
      once += count[i];
    }
    std::vector<bool> outside(count.size(), false);
    std::vector<int> stack;
    for (int x = 0; x < w; ++x) stack.insert(stack.end(), {x, (h - 1) * w + x});
    for (int y = 0; y < h; ++y) stack.insert(stack.end(), {y * w, y * w + w - 1});
    while (!stack.empty()) {
      const int i = stack.back();
      stack.pop_back();
      if (outside[static_cast<std::size_t>(i)] || count[static_cast<std::size_t>(i)] != 0) continue;
      outside[static_cast<std::size_t>(i)] = true;
      const int x = i % w, y = i / w;
      if (x > 0) stack.push_back(i - 1);
      if (x + 1 < w) stack.push_back(i + 1);
      if (y > 0) stack.push_back(i - w);
      if (y + 1 < h) stack.push_back(i + w);
    }
    for (std::size_t i = 0; i < count.size(); ++i) {
      ASSERT_TRUE(count[i] == 1 || outside[i]) << "crack at (" << i % w << ", " << i / w << ")";
    }
    EXPECT_GT(once, 20000u) << "the sphere should cover a disc of radius ~95 px";
  }
}

// The course's 1/z depth buffer (softraster only, not a Vulkan mode): it holds 1/w, which Vulkan's
// z/w buffer determines too: z = A + B/w with A = far/(far-near), B = -near*far/(far-near).
// It resolves visibility like z/w except where surfaces are nearly at the same depth.
TEST(DepthModes, InverseZBufferHoldsOneOverZ) {
  softraster::ContextOptions options;
  options.depthMode = softraster::DepthMode::InverseZ;
  RenderedScene r;
  ASSERT_NO_FATAL_FAILURE(renderBoth("room", r, options));
  const auto& inverse = r.soft;
  const auto& reference = r.reference;
  const double nearPlane = 0.05, farPlane = 10;  // room.json's camera
  const double a = farPlane / (farPlane - nearPlane), b = -nearPlane * farPlane / (farPlane - nearPlane);
  std::size_t covered = 0, colourDiffers = 0;
  double worst = 0;
  for (std::size_t i = 0; i < inverse->depth.size(); ++i) {
    const bool coveredInverse = inverse->depth[i] != 0.0f, coveredReference = reference->depth[i] != 1.0f;
    ASSERT_EQ(coveredInverse, coveredReference) << "pixel " << i;
    if (!coveredInverse) continue;
    ++covered;
    colourDiffers += !std::equal(inverse->rgba.begin() + 4 * i, inverse->rgba.begin() + 4 * i + 4,
                                 reference->rgba.begin() + 4 * i);
    const double oneOverZ = (reference->depth[i] - a) / b;
    worst = std::max(worst, std::fabs(inverse->depth[i] - oneOverZ) / oneOverZ);
  }
  ::testing::Test::RecordProperty("colour_pixels_differing", std::to_string(colourDiffers));
  ::testing::Test::RecordProperty("worst_relative_one_over_z_error", std::to_string(worst));
  EXPECT_GT(covered, 10000u);
  EXPECT_LT(worst, 2e-4) << "the 1/z buffer should hold 1/w to float precision of the z/w reference";
  EXPECT_LE(colourDiffers, covered / 1000) << colourDiffers << " of " << covered << " pixels resolve differently";
  std::printf("1/z buffer: %zu of %zu covered pixels differ in colour from z/w; worst relative 1/z error %.3g\n",
              colourDiffers, covered, worst);
}
