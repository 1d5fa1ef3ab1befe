// The fragment built-in scenes, cross-checked: both renderers to the bit (the fast path's
// dispatch and the scalar exact path) under the validation layer, stencil included, over
// single-sample, 4x MSAA and two depth/stencil formats; then what each scene is about, checked
// against values worked out here rather than softraster's code: gl_FragCoord.xy is the pixel
// centre (the colour of a kept front-facing pixel is round(255 * (x + 0.5) / 128)), a discarded
// pixel keeps the stencil and depth under it, a kept one is written, and the draw behind shows
// through the holes; gl_FragDepth lands in the depth buffer clamped to [0, 1], or with depth
// clamp to the viewport's range, over D16, D24, D32 and 4x MSAA.
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace {

using agreement::renderAgreeing;

std::uint8_t stencilAt(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y) {
  return f.stencil.at(static_cast<std::size_t>(y) * f.width + x);
}

std::uint8_t channelAt(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, int c) {
  return f.rgba.at(4 * (static_cast<std::size_t>(y) * f.width + x) + static_cast<std::size_t>(c));
}

bool discardedBy(std::uint32_t x, std::uint32_t y) { return x % 4 < 2 && y % 4 < 2; }

void expectBuiltins(const std::string& name) {
  const crosscheck::Frame f = renderAgreeing(name, {});
  ASSERT_FALSE(f.rgba.empty()) << name;
  // Inside the first (front-facing, stencil-writing) triangle: (32, 40) is discarded, (34, 42) kept.
  EXPECT_TRUE(discardedBy(32, 40));
  EXPECT_FALSE(discardedBy(34, 42));
  EXPECT_EQ(int{stencilAt(f, 32, 40)}, 2) << name << ": a discarded fragment left the background's stencil";
  EXPECT_EQ(int{stencilAt(f, 34, 42)}, 3) << name << ": a kept front fragment incremented it";
  EXPECT_EQ(int{channelAt(f, 34, 42, 0)}, static_cast<int>(std::nearbyint(34.5 / 128 * 255))) << name;
  EXPECT_EQ(int{channelAt(f, 34, 42, 1)}, static_cast<int>(std::nearbyint(42.5 / 128 * 255))) << name;
  // The last draw (yellow, depth 3.2) shows through the holes of the nearer builtins triangles.
  std::size_t throughHoles = 0;
  for (std::uint32_t y = 20; y < 40; ++y) {
    for (std::uint32_t x = 22; x < 40; ++x) {
      const bool yellow = channelAt(f, x, y, 0) == 230 && channelAt(f, x, y, 1) == 230 && channelAt(f, x, y, 2) == 51;
      if (yellow) {
        EXPECT_TRUE(discardedBy(x, y)) << name << ": yellow at a kept pixel " << x << ", " << y;
        ++throughHoles;
      }
    }
  }
  EXPECT_GT(throughHoles, 0u) << name;
}

float depthAt(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y) {
  return f.depth.at(static_cast<std::size_t>(y) * f.width + x);
}

void expectFragDepth(const std::string& name) {
  const crosscheck::Frame f = renderAgreeing(name, {});
  ASSERT_FALSE(f.depth.empty()) << name;
  // Near the first triangle's nearest corner gl_FragDepth = (z - 0.8) * 8 is below 0: clamped to
  // 0 where the stripe adds nothing (x = 12), just above 0 where it adds 0.25 (x = 20).
  EXPECT_EQ(depthAt(f, 12, 14), 0.0f) << name;
  EXPECT_GT(depthAt(f, 20, 14), 0.0f) << name;
  EXPECT_LT(depthAt(f, 20, 14), 0.1f) << name;
  // With depth clamp the same negative value is clamped to the viewport's min_depth 0.2.
  EXPECT_NEAR(depthAt(f, 72, 124), 0.2f, 1e-4f) << name;
}

}  // namespace

TEST(FragmentBuiltins, FragDepthD16) { expectFragDepth("builtins_frag_depth_d16"); }

TEST(FragmentBuiltins, FragDepthD24) { expectFragDepth("builtins_frag_depth_d24"); }

TEST(FragmentBuiltins, FragDepthD32) { expectFragDepth("builtins_frag_depth_d32"); }

TEST(FragmentBuiltins, FragDepthMsaa) { expectFragDepth("builtins_frag_depth_msaa"); }

TEST(FragmentBuiltins, DiscardFragCoordFrontFacingSingleSample) { expectBuiltins("builtins_discard"); }

TEST(FragmentBuiltins, DiscardFragCoordFrontFacingMsaa) { expectBuiltins("builtins_discard_msaa"); }

TEST(FragmentBuiltins, DiscardFragCoordFrontFacingD32S8) { expectBuiltins("builtins_discard_d32"); }

// 64 varying components (softraster::kMaxVaryings, Vulkan's minimum maxVertexOutputComponents):
// both renderers agree, and the triangles are drawn (not refused or lost to clipping).
TEST(Varyings64, SixtyFourComponentsAgree) {
  for (const std::string name : {"varyings_64", "varyings_64_msaa"}) {
    const crosscheck::Frame f = renderAgreeing(name, {});
    ASSERT_FALSE(f.rgba.empty()) << name;
    std::size_t drawn = 0;
    for (std::size_t i = 0; i + 3 < f.rgba.size(); i += 4) drawn += f.rgba[i] != f.rgba[0] || f.rgba[i + 1] != f.rgba[1];
    EXPECT_GT(drawn, 5000u) << name;
  }
}

// What softraster does not draw yet is one error naming the draw, not a silent difference:
// lavapipe gives the lines and points of an unfilled polygon the polygon's gl_FrontFacing when
// the shader reads it (draw_pipe_unfilled.c), softraster's unfilled stage does not carry it.
TEST(FragmentBuiltins, PolygonModeLineIsRefused) {
  auto scene = crosscheck::loadScene(agreement::kScenes / "builtins_discard.json", {"draws.1.polygon_mode=line"});
  ASSERT_TRUE(scene) << scene.error();
  auto frame = crosscheck::renderSoftraster(*scene, {});
  ASSERT_FALSE(frame);
  EXPECT_NE(frame.error().find("polygon modes line and point with the fragment built-ins"), std::string::npos)
      << frame.error();
  EXPECT_NE(frame.error().find("front, ccw, stencil written"), std::string::npos) << frame.error();
  EXPECT_EQ(frame.error().find('\n'), std::string::npos) << frame.error();
}

// Sample shading (4x MSAA, minSampleShading 1): the shader runs once per covered sample with
// gl_FragCoord.xy at the sample, so each sample of a kept front-facing pixel has its own red and
// green, round(255 * (p + offset) / 128), not the pixel centre's; the discard pattern's edges lie
// on pixel edges, so the holes are the ones without sample shading.
TEST(FragmentBuiltins, SampleShadingShadesEverySampleAtItsPosition) {
  const crosscheck::Frame f = renderAgreeing("builtins_discard_sample_shading", {});
  ASSERT_EQ(f.samples, 4u);
  constexpr float kOffsets[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  const std::uint32_t x = 34, y = 42;
  for (std::uint32_t s = 0; s < 4; ++s) {
    const std::size_t i = 4 * ((static_cast<std::size_t>(y) * f.width + x) * 4 + s);
    EXPECT_EQ(int{f.sampleRgba.at(i)}, static_cast<int>(std::nearbyint((x + kOffsets[s][0]) / 128 * 255))) << s;
    EXPECT_EQ(int{f.sampleRgba.at(i + 1)}, static_cast<int>(std::nearbyint((y + kOffsets[s][1]) / 128 * 255))) << s;
    EXPECT_EQ(int{f.sampleStencil.at((static_cast<std::size_t>(y) * f.width + x) * 4 + s)}, 3) << s;
    const std::size_t hole = (static_cast<std::size_t>(40) * f.width + 32) * 4 + s;  // discarded on every sample
    EXPECT_EQ(int{f.sampleStencil.at(hole)}, 2) << s;
  }
  EXPECT_NE(f.sampleRgba.at(4 * ((static_cast<std::size_t>(y) * f.width + x) * 4 + 0)),
            f.sampleRgba.at(4 * ((static_cast<std::size_t>(y) * f.width + x) * 4 + 1)))
      << "samples 0 and 1 are shaded at x + 0.375 and x + 0.875";
}

// Sample shading with gl_FragDepth: each sample's invocation writes its own depth, from
// gl_FragCoord.z at the sample; without sample shading the four samples hold one value.
TEST(FragmentBuiltins, SampleShadingWritesFragDepthPerSample) {
  const crosscheck::Frame shaded = renderAgreeing("builtins_frag_depth_sample_shading", {});
  const crosscheck::Frame once = renderAgreeing("builtins_frag_depth_msaa", {});
  ASSERT_EQ(shaded.samples, 4u);
  ASSERT_EQ(once.samples, 4u);
  const std::size_t first = (static_cast<std::size_t>(40) * shaded.width + 40) * 4;
  for (std::size_t s = 1; s < 4; ++s) {
    EXPECT_NE(shaded.sampleDepthStorage.at(first + s), shaded.sampleDepthStorage.at(first)) << s;
    EXPECT_EQ(once.sampleDepthStorage.at(first + s), once.sampleDepthStorage.at(first)) << s;
  }
}

// gl_SampleID and gl_SamplePosition (builtins_sample): reading gl_SampleID shades every sample on
// its own without any sample shading state. With 4x MSAA each sample of a covered pixel holds its
// own position (the standard offsets, as UNORM8) and index / 4, and sample 3 is discarded in the
// top half (its stencil not counted); with one sample gl_SampleID is 0 and gl_SamplePosition
// (0.5, 0.5).
TEST(FragmentBuiltins, SampleIdAndPositionShadeEachSample) {
  const crosscheck::Frame msaa = renderAgreeing("builtins_sample_msaa", {});
  ASSERT_EQ(msaa.samples, 4u);
  constexpr float kOffsets[4][2] = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  const auto unorm = [](float v) { return static_cast<int>(std::nearbyint(v * 255)); };
  for (const std::uint32_t y : {60u, 100u}) {  // inside the counter-clockwise triangle (in front of the background), top and bottom half
    const std::uint32_t x = 30;
    for (std::uint32_t s = 0; s < 4; ++s) {
      const std::size_t sample = (static_cast<std::size_t>(y) * msaa.width + x) * 4 + s;
      const bool discarded = s == 3 && y < 96;
      EXPECT_EQ(int{msaa.sampleStencil.at(sample)}, discarded ? 0 : 1) << y << " sample " << s;
      if (discarded) continue;
      EXPECT_EQ(int{msaa.sampleRgba.at(4 * sample)}, unorm(kOffsets[s][0])) << y << " sample " << s;
      EXPECT_EQ(int{msaa.sampleRgba.at(4 * sample + 1)}, unorm(kOffsets[s][1])) << y << " sample " << s;
      EXPECT_EQ(int{msaa.sampleRgba.at(4 * sample + 2)}, unorm(0.25f * static_cast<float>(s))) << y << " sample " << s;
    }
  }
  const crosscheck::Frame single = renderAgreeing("builtins_sample", {});
  const std::size_t pixel = static_cast<std::size_t>(60) * single.width + 30;
  EXPECT_EQ(int{single.rgba.at(4 * pixel)}, unorm(0.5f));
  EXPECT_EQ(int{single.rgba.at(4 * pixel + 1)}, unorm(0.5f));
  EXPECT_EQ(int{single.rgba.at(4 * pixel + 2)}, 0);
  EXPECT_EQ(int{single.stencil.at(pixel)}, 1);
}
