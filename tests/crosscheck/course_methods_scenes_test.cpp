// The course's methods (Method::Scanline, Trapezoid, Barycentric) on every scene of scenes/, with
// every shading model the scenes use: each draws without an error and without a fault (hostile
// scenes included: NaN and Inf vertices, w = 0, huge coordinates, slivers, the near plane),
// perspective-correct and with affine varyings, in Vulkan depth and (D32 single-sample scenes) in
// the course's 1/z buffer; and where the exact method covers a fair number of pixels, a course
// method covers a comparable number (within a factor of two) — not bit-identity, which these
// methods do not have. Each scene is its own test case (CourseMethods/CourseSceneDrawn.WithEveryMethod/<name>).
#include "compare/compare.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <softraster/options.hpp>

#include "scene_list.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

const std::filesystem::path kScenes = SCENES_DIR;

class CourseSceneDrawn : public ::testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(CourseSceneDrawn, WithEveryMethod) {
  const auto scene = crosscheck::loadScene(conformanceScenePath(GetParam()));
  ASSERT_TRUE(scene) << scene.error();
  softraster::ContextOptions exactOptions;
  exactOptions.method = softraster::Method::ExactScalar;
  const auto exact = crosscheck::renderSoftraster(*scene, exactOptions);
  ASSERT_TRUE(exact) << exact.error();
  const std::uint64_t exactCovered = crosscheck::coveredPixels(*exact, *scene);
  for (softraster::Method method : softraster::kMethods) {
    if (!softraster::isCourseMethod(method)) continue;
    for (const bool affine : {false, true}) {
      for (const bool inverseZ : {false, true}) {
        if (inverseZ && (scene->depthFormat != softraster::DepthFormat::D32Sfloat || scene->samples != 1)) continue;
        SCOPED_TRACE(std::string(softraster::methodName(method)) + (affine ? " affine" : "") + (inverseZ ? " 1/z" : ""));
        softraster::ContextOptions options;
        options.method = method;
        options.affineVaryings = affine;
        if (inverseZ) options.depthMode = softraster::DepthMode::InverseZ;
        const auto frame = crosscheck::renderSoftraster(*scene, options);
        // gl_FragDepth has no meaning in the course's 1/z buffer: that draw is refused, with one error.
        if (inverseZ && !frame && frame.error().find("gl_FragDepth needs the Vulkan depth mode") != std::string::npos) continue;
        ASSERT_TRUE(frame) << frame.error();
        ASSERT_EQ(frame->rgba.size(), std::size_t{4} * scene->width * scene->height);
        if (inverseZ) continue;  // a 1/z frame's clear depth differs, so coverage is not counted by it
        const std::uint64_t covered = crosscheck::coveredPixels(*frame, *scene);
        if (exactCovered >= 100) {
          EXPECT_GE(2 * covered, exactCovered) << covered << " pixels covered, exact " << exactCovered;
          EXPECT_LE(covered, 2 * exactCovered) << covered << " pixels covered, exact " << exactCovered;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CourseMethods, CourseSceneDrawn, ::testing::ValuesIn(conformanceSceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
