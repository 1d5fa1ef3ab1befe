// Bit identity of the fast path: every scene in scenes/ drawn by softraster's Method::Exact (the
// SIMD fast path, in row bands on 1, 2 and 7 threads, and on a CPU with AVX-512 also at 1 thread
// with ContextOptions::allowAvx512 off) and by Method::ExactScalar (the reference,
// one pixel at a time on one thread), compared byte for byte: colour and depth of every sample,
// before any resolve. Also with the course's 1/z depth buffer on the D32 scenes. Each scene is its
// own test case (FastPath/SceneDrawn.MatchesScalar/<name>).
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <softraster/detail/fast/batch.hpp>
#include <softraster/pipeline.hpp>
#include <vertex_color.hpp>

#include "scene_list.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kScenes = SCENES_DIR;

std::vector<std::string> sceneNames() { return conformanceSceneNames(); }

// The first sample whose colour, depth or stencil differs, as a readable failure; empty when identical.
std::string firstDifference(const softraster::Framebuffer& fast, const softraster::Framebuffer& scalar) {
  const std::size_t samples = scalar.depthStorage().size();
  if (fast.depthStorage().size() != samples || fast.colourAttachments() != scalar.colourAttachments()) return "sizes differ";
  for (std::uint32_t a = 0; a < scalar.colourAttachments(); ++a) {
    if (fast.colourFormat(a) != scalar.colourFormat(a) || fast.colour(a).size() != scalar.colour(a).size()) {
      return "colour attachment " + std::to_string(a) + "'s formats or sizes differ";
    }
  }
  if (fast.stencilStorage().size() != scalar.stencilStorage().size()) return "stencil sizes differ";
  const bool stencil = !scalar.stencilStorage().empty();
  const std::size_t perPixel = scalar.samples();
  for (std::size_t s = 0; s < samples; ++s) {
    bool colourDiffers = false;  // in any attachment, every stored byte of the sample
    for (std::uint32_t a = 0; a < scalar.colourAttachments(); ++a) {
      const std::size_t bytes = softraster::colourBytes(scalar.colourFormat(a));
      colourDiffers = colourDiffers || !std::equal(fast.colour(a).begin() + bytes * s, fast.colour(a).begin() + bytes * (s + 1),
                                                   scalar.colour(a).begin() + bytes * s);
    }
    const bool stencilDiffers = stencil && fast.stencilStorage()[s] != scalar.stencilStorage()[s];
    if (colourDiffers || stencilDiffers || fast.depthStorage()[s] != scalar.depthStorage()[s]) {
      const std::size_t pixel = s / perPixel;
      return "pixel (" + std::to_string(pixel % scalar.width()) + ", " + std::to_string(pixel / scalar.width()) +
             ") sample " + std::to_string(s % perPixel) + ": depth " + std::to_string(fast.depthStorage()[s]) +
             " vs " + std::to_string(scalar.depthStorage()[s]) + (colourDiffers ? ", colour differs" : "") +
             (stencilDiffers ? ", stencil " + std::to_string(fast.stencilStorage()[s]) + " vs " +
                                   std::to_string(scalar.stencilStorage()[s])
                             : "");
    }
  }
  return {};
}

void expectFastMatchesScalar(const crosscheck::Scene& scene, softraster::ContextOptions options) {
  options.method = softraster::Method::ExactScalar;
  options.threads = 1;
  const auto scalar = crosscheck::renderSoftrasterSamples(scene, options);
  ASSERT_TRUE(scalar) << scalar.error();
  for (const unsigned threads : {1u, 2u, 7u}) {
    options.method = softraster::Method::Exact;
    options.threads = threads;
    const auto fast = crosscheck::renderSoftrasterSamples(scene, options);
    ASSERT_TRUE(fast) << fast.error();
    EXPECT_EQ(firstDifference(*fast, *scalar), "") << threads << " threads";
  }
#if SOFTRASTER_HAS_FAST_PATH
  // Where the CPU has AVX-512, also the fast path without it (a long shader's blocks two at a
  // time in AVX2, as a CPU without AVX-512 draws them).
  if (softraster::detail::fast::cpuShadesWidePairs()) {
    options.method = softraster::Method::Exact;
    options.threads = 1;
    options.allowAvx512 = false;
    const auto fast = crosscheck::renderSoftrasterSamples(scene, options);
    ASSERT_TRUE(fast) << fast.error();
    EXPECT_EQ(firstDifference(*fast, *scalar), "") << "AVX-512 not allowed";
  }
#endif
}

class SceneDrawn : public ::testing::TestWithParam<std::string> {};

}  // namespace

// The scenes' shaders shade batches and this CPU runs the fast path, or the comparison below
// would compare the scalar path with itself.
TEST(FastPath, IsTakenHere) {
  static_assert(softraster::ShadesBatches<shaders::VertexColor>);
  static_assert(softraster::ShadesBatches<shaders::VertexColorFlat>);
  static_assert(softraster::ShadesBatches<shaders::VertexColorNoPerspective>);
#if SOFTRASTER_HAS_FAST_PATH
  if (!softraster::detail::fast::cpuRunsFastPath()) GTEST_SKIP() << "this CPU has no AVX2 and FMA";
#else
  GTEST_SKIP() << "no fast path on this architecture";
#endif
}

TEST_P(SceneDrawn, MatchesScalar) {
  const auto scene = crosscheck::loadScene(conformanceScenePath(GetParam()));
  ASSERT_TRUE(scene) << scene.error();
  expectFastMatchesScalar(*scene, {});
  if (scene->depthFormat == softraster::DepthFormat::D32Sfloat && scene->samples == 1) {
    softraster::ContextOptions inverseZ;
    inverseZ.depthMode = softraster::DepthMode::InverseZ;
    // A shader writing gl_FragDepth is refused in the 1/z buffer (no such depth there): one error.
    inverseZ.method = softraster::Method::ExactScalar;
    if (const auto refused = crosscheck::renderSoftrasterSamples(*scene, inverseZ);
        !refused && refused.error().find("gl_FragDepth needs the Vulkan depth mode") != std::string::npos) {
      inverseZ.method = softraster::Method::Exact;
      const auto fast = crosscheck::renderSoftrasterSamples(*scene, inverseZ);
      EXPECT_FALSE(fast);
      return;
    }
    expectFastMatchesScalar(*scene, inverseZ);
  }
}

INSTANTIATE_TEST_SUITE_P(FastPath, SceneDrawn, ::testing::ValuesIn(sceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });
