// Helpers the scene-parameter tests share (texture_test, shadow_test, lighting_test,
// stencil_test): a scene of scenes/ rendered by both renderers under the validation layer and
// required to agree to the bit (stencil included), the same scene in softraster's spec mode (the
// known deviations' tests), how many pixels two frames differ in, and a scene error checked to be
// one line naming the file and the place.
#pragma once

#include "compare/compare.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace agreement {

inline const std::filesystem::path kScenes = SCENES_DIR;

// softraster (the fast and the scalar exact paths) and lavapipe agree to the bit on scene `name`
// (scenes/NAME.json) with `overrides`, with no validation message; returns softraster's frame.
inline crosscheck::Frame renderAgreeing(const std::string& name, const std::vector<std::string>& overrides) {
  auto scene = crosscheck::loadScene(kScenes / (name + ".json"), overrides);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  vkref::DeviceOptions device;
  device.validation = true;
  auto vulkan = crosscheck::openVulkan(device);
  EXPECT_TRUE(vulkan) << vulkan.error();
  if (!vulkan) return {};
  auto reference = crosscheck::renderVulkan(*scene, **vulkan);
  EXPECT_TRUE(reference) << reference.error();
  if (!reference) return {};
  for (const std::string& m : (*vulkan)->validationMessages()) ADD_FAILURE() << "validation: " << m;
  crosscheck::Frame first;
  for (softraster::Method method : {softraster::Method::Exact, softraster::Method::ExactScalar}) {
    softraster::ContextOptions options;
    options.method = method;
    auto soft = crosscheck::renderSoftraster(*scene, options);
    EXPECT_TRUE(soft) << soft.error();
    if (!soft) return {};
    const crosscheck::Comparison c = crosscheck::compareFrames(*soft, *reference, *scene);
    EXPECT_EQ(c.coverageMismatches, 0u) << name;
    for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(c.colourMaxDelta[ch], 0) << name << " channel " << ch;
    EXPECT_EQ(c.depthMaxDelta, 0.0) << name;
    EXPECT_EQ(c.stencilMismatches, 0u) << name;
    EXPECT_TRUE(soft->colourWords == reference->colourWords && soft->sampleColourWords == reference->sampleColourWords)
        << name << ": the stored colour words differ";
    EXPECT_EQ(c.moreColour.size(), scene->moreColour.size()) << name;
    for (std::size_t k = 0; k < c.moreColour.size(); ++k) {  // colour attachments 1..: every sample and the resolve
      for (int ch = 0; ch < 4; ++ch) {
        EXPECT_EQ(c.moreColour[k].colourMaxDelta[ch], 0) << name << " attachment " << k + 1 << " channel " << ch;
      }
      const crosscheck::ColourImage &ours = soft->moreColour[k], &theirs = reference->moreColour[k];
      EXPECT_TRUE(ours.rgba == theirs.rgba && ours.colourWords == theirs.colourWords &&
                  ours.sampleRgba == theirs.sampleRgba && ours.sampleColourWords == theirs.sampleColourWords)
          << name << ": colour attachment " << k + 1 << "'s stored texels differ";
    }
    EXPECT_TRUE(c.passed()) << name << ": " << (c.failures.empty() ? "" : c.failures.front());
    if (first.rgba.empty()) first = std::move(*soft);
  }
  return first;
}

// Scene `name` drawn by softraster following the spec (Deviations::Spec), on the fast and the
// scalar exact path in that order: the frames a known deviation's test compares with lavapipe's.
// Empty (with a test failure) if the scene does not load or a path fails.
inline std::vector<crosscheck::Frame> renderInSpecMode(const std::string& name) {
  auto scene = crosscheck::loadScene(kScenes / (name + ".json"), {});
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return {};
  std::vector<crosscheck::Frame> frames;
  for (softraster::Method method : {softraster::Method::Exact, softraster::Method::ExactScalar}) {
    softraster::ContextOptions options;
    options.method = method;
    options.deviations = softraster::Deviations::Spec;
    auto spec = crosscheck::renderSoftraster(*scene, options);
    EXPECT_TRUE(spec) << spec.error();
    if (!spec) return {};
    frames.push_back(std::move(*spec));
  }
  return frames;
}

// Pixels whose RGB differs between two frames of the same size.
inline std::size_t pixelsDiffering(const crosscheck::Frame& a, const crosscheck::Frame& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
    n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
  }
  return n;
}

// Loading scenes/SCENE with `overrides` fails with one line containing `expected` and the file's name.
inline void expectSceneError(const std::vector<std::string>& overrides, const std::string& scene,
                             const std::string& expected) {
  auto loaded = crosscheck::loadScene(kScenes / scene, overrides);
  ASSERT_FALSE(loaded) << "expected an error containing: " << expected;
  EXPECT_NE(loaded.error().find(expected), std::string::npos) << loaded.error();
  EXPECT_NE(loaded.error().find(scene), std::string::npos) << loaded.error();
  EXPECT_EQ(loaded.error().find('\n'), std::string::npos) << loaded.error();
}

}  // namespace agreement
