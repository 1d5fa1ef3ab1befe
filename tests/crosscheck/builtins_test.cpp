// The fragment built-in scenes, cross-checked: both renderers to the bit (the fast path's
// dispatch and the scalar exact path) under the validation layer, stencil included, over
// single-sample, 4x MSAA and two depth/stencil formats; then what each scene is about, checked
// against values worked out here rather than softraster's code: gl_FragCoord.xy is the pixel
// centre (the colour of a kept front-facing pixel is round(255 * (x + 0.5) / 128)), a discarded
// pixel keeps the stencil and depth under it, a kept one is written, and the draw behind shows
// through the holes; gl_FragDepth lands in the depth buffer clamped to [0, 1], or with depth
// clamp to the viewport's range, over D16, D24, D32 and 4x MSAA; the lines and points of unfilled
// polygons take their polygon's facing when the shader reads gl_FrontFacing; gl_SampleMask keeps
// the samples its bits name and gl_SampleMaskIn holds the covered ones.
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

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

// Unfilled polygons with a shader that reads gl_FrontFacing (builtins_polygon_modes): lavapipe's
// unfilled stage gives their lines and points the polygon's facing, which picks the stencil state
// too (front writes 128 or 3, back 55 or 56); the vertex_color polygon keeps the front state (66,
// never its back state's 77), and the discard pattern holds on lines and points as on triangles.
// Following the spec (Deviations::Spec) changes only that polygon: its back-facing lines write 77.
TEST(FragmentBuiltins, UnfilledPolygonsTakeTheirFacingWhenTheShaderReadsIt) {
  for (const std::string name : {"builtins_polygon_modes", "builtins_polygon_modes_msaa"}) {
    const crosscheck::Frame f = renderAgreeing(name, {});
    ASSERT_FALSE(f.rgba.empty()) << name;
    const std::vector<std::uint8_t>& stencil = f.samples == 1 ? f.stencil : f.sampleStencil;
    ASSERT_EQ(stencil.size(), std::size_t{f.width} * f.height * f.samples) << name;
    std::map<int, std::size_t> written;
    for (std::size_t i = 0; i < stencil.size(); ++i) {
      const std::size_t pixel = i / f.samples;
      const auto x = static_cast<std::uint32_t>(pixel % f.width), y = static_cast<std::uint32_t>(pixel / f.width);
      const int value = stencil[i];
      ++written[value];
      if (value == 128 || value == 55 || value == 3) {
        EXPECT_FALSE(discardedBy(x, y)) << name << ": a discarded fragment wrote stencil " << value << " at " << x
                                        << ", " << y;
      }
    }
    EXPECT_GT(written[128], 50u) << name << ": the front-facing polygon's lines";
    EXPECT_GT(written[55], 80u) << name << ": the back-facing polygons' lines and points take the back state";
    EXPECT_GT(written[3], 0u) << name << ": clockwise points with front_face clockwise are front-facing";
    EXPECT_EQ(written[56], 0u) << name << ": the clockwise front polygon used its back state";
    EXPECT_GT(written[66], 80u) << name << ": vertex_color's back-facing lines take the front state";
    EXPECT_EQ(written[77], 0u) << name << ": vertex_color's lines took the back state";
    // gl_FrontFacing false on the back-facing lines: coloured by their vertex colour (0.9, 0.6, 0.1).
    std::size_t vertexColoured = 0;
    for (std::size_t i = 0; i + 3 < f.rgba.size(); i += 4) vertexColoured += f.rgba[i] == 230 && f.rgba[i + 1] == 153;
    EXPECT_GT(vertexColoured, 30u) << name;

    const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode(name);
    ASSERT_EQ(specFrames.size(), 2u) << name;
    for (const crosscheck::Frame& spec : specFrames) {
      const std::vector<std::uint8_t>& specStencil = spec.samples == 1 ? spec.stencil : spec.sampleStencil;
      ASSERT_EQ(specStencil.size(), stencil.size()) << name;
      std::size_t changed = 0;
      for (std::size_t i = 0; i < stencil.size(); ++i) {
        if (specStencil[i] == stencil[i]) continue;
        ++changed;
        EXPECT_EQ(stencil[i], 66) << name << " sample " << i;
        EXPECT_EQ(specStencil[i], 77) << name << " sample " << i;
      }
      EXPECT_EQ(changed, written[66]) << name << ": following the spec, all of vertex_color's lines face back";
    }
  }
}

// gl_SampleMask and gl_SampleMaskIn (builtins_sample_mask): the shader keeps the samples of
// mask (x + 3y) & 15 and colours red gl_SampleMaskIn / 16. Inside the first triangle (stencil
// incremented from the background's 2 to 3 where a sample is kept) and the one drawn with the
// sample mask state 0xb, each sample s is kept iff bit s of the mask (and of 0xb) is set: with
// one sample bit 0 decides for the pixel; with 4x MSAA shaded once per pixel the red is the
// covered samples (15, or 0xb = 11) over 16; with sample shading each invocation sees its own bit.
TEST(FragmentBuiltins, SampleMaskKeepsTheSamplesItsBitsName) {
  struct Region {
    std::uint32_t x0, x1, y0, y1;
    unsigned stateMask;
  };
  const Region regions[] = {{25, 45, 25, 45, 0xfu}, {65, 80, 145, 158, 0xbu}};
  for (const std::string name : {"builtins_sample_mask", "builtins_sample_mask_msaa", "builtins_sample_mask_sample_shading"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame f = renderAgreeing(name, {});
    ASSERT_FALSE(f.rgba.empty());
    const bool perSample = name == "builtins_sample_mask_sample_shading";
    const std::vector<std::uint8_t>& stencil = f.samples == 1 ? f.stencil : f.sampleStencil;
    const std::vector<std::uint8_t>& rgba = f.samples == 1 ? f.rgba : f.sampleRgba;
    std::size_t kept = 0, dropped = 0;
    for (const Region& r : regions) {
      for (std::uint32_t y = r.y0; y < r.y1; ++y) {
        for (std::uint32_t x = r.x0; x < r.x1; ++x) {
          const unsigned mask = (x + 3 * y) & 15u & (f.samples == 1 ? 1u : r.stateMask);
          for (std::uint32_t s = 0; s < f.samples; ++s) {
            const std::size_t i = (static_cast<std::size_t>(y) * f.width + x) * f.samples + s;
            const bool keep = (mask >> s) & 1u;
            EXPECT_EQ(int{stencil.at(i)}, keep ? 3 : 2) << x << ", " << y << " sample " << s;
            if (!keep) {
              ++dropped;
              continue;
            }
            ++kept;
            const unsigned maskIn = f.samples == 1 ? 1u : perSample ? 1u << s : r.stateMask;
            if (maskIn == 8u) continue;  // 127.5: the rounding of a tie is not what this checks
            EXPECT_EQ(int{rgba.at(4 * i)}, static_cast<int>(std::nearbyint(255.0 * maskIn / 16.0)))
                << x << ", " << y << " sample " << s;
          }
        }
      }
    }
    EXPECT_GT(kept, 100u);
    EXPECT_GT(dropped, 100u);
  }
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
