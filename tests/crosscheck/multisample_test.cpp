// The multisample-state scenes (the sample mask, alpha to coverage, alpha to one), cross-checked:
// both renderers to the bit (the fast path's dispatch and the scalar exact path) under the
// validation layer, every sample of colour, depth and stencil; then what each scene is about,
// checked against values worked out here from the rules rather than from softraster's code:
// a sample the mask drops keeps the background and its stencil 0; alpha to coverage keeps sample s
// where alpha > s / 4 with 4x MSAA and a fragment where alpha > 0.5 with one sample; alpha to one
// writes alpha 255; the single-sample mask deviation, in driver and spec mode; and 4x MSAA lines
// as lavapipe bins them (and as the spec draws them); Bresenham lines, drawn by lavapipe with
// multisampling off, whole whatever the sample mask; a NaN alpha keeps every sample (an unordered
// compare).
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using agreement::renderAgreeing;

std::size_t sampleIndex(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t s) {
  return (static_cast<std::size_t>(y) * f.width + x) * f.samples + s;
}

std::array<std::uint8_t, 4> sampleColour(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t s) {
  const std::size_t i = 4 * sampleIndex(f, x, y, s);
  return {f.sampleRgba.at(i), f.sampleRgba.at(i + 1), f.sampleRgba.at(i + 2), f.sampleRgba.at(i + 3)};
}

std::array<std::uint8_t, 4> pixelColour(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y) {
  const std::size_t i = 4 * (static_cast<std::size_t>(y) * f.width + x);
  return {f.rgba.at(i), f.rgba.at(i + 1), f.rgba.at(i + 2), f.rgba.at(i + 3)};
}

bool sameRgb(const std::array<std::uint8_t, 4>& a, const std::array<std::uint8_t, 4>& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// The flat quads' colour (0.9, 0.8, 0.1) as UNORM8.
constexpr std::array<std::uint8_t, 4> kFlatQuad = {230, 204, 26, 0};

}  // namespace

// sample_mask_msaa: triangle i has mask kMasks[i]; pixel (x + 5, y + 6) lies inside it on every
// sample and outside the triangle drawn across it. Each sample the mask keeps was counted by the
// stencil (0 -> 1) and took the triangle's colour; each it drops kept stencil 0 and the
// background, which is the same on every sample of the pixel.
TEST(Multisample, SampleMaskDropsSamplesBeforeTheTests) {
  const crosscheck::Frame f = renderAgreeing("sample_mask_msaa", {});
  ASSERT_EQ(f.samples, 4u);
  ASSERT_FALSE(f.sampleStencil.empty());
  constexpr std::array<std::uint32_t, 12> kMasks = {0x1, 0x2, 0x4, 0x8, 0x5, 0xA, 0x6, 0x9, 0xE, 0x0, 0xFFFFFFF3, 0xF};
  for (std::uint32_t i = 0; i < kMasks.size(); ++i) {
    const std::uint32_t x = 6 + (i % 6) * 25 + 5, y = 6 + (i / 6) * 44 + 6;
    const std::uint32_t mask = kMasks[i] & 0xF;
    std::array<std::uint8_t, 4> kept{}, dropped{};
    bool anyKept = false, anyDropped = false;
    for (std::uint32_t s = 0; s < 4; ++s) {
      const bool keep = (mask >> s) & 1u;
      EXPECT_EQ(int{f.sampleStencil.at(sampleIndex(f, x, y, s))}, keep ? 1 : 0) << "mask " << kMasks[i] << " sample " << s;
      const auto c = sampleColour(f, x, y, s);
      if (keep) {
        if (anyKept) {
          EXPECT_TRUE(sameRgb(c, kept)) << "mask " << kMasks[i] << " sample " << s;
        }
        kept = c, anyKept = true;
      } else {
        if (anyDropped) {
          EXPECT_TRUE(sameRgb(c, dropped)) << "mask " << kMasks[i] << " sample " << s;
        }
        dropped = c, anyDropped = true;
      }
    }
    if (anyKept && anyDropped) {
      EXPECT_FALSE(sameRgb(kept, dropped)) << "mask " << kMasks[i];
    }
  }
}

// alpha_to_coverage_msaa's top row: quad i of one alpha, no blending; sample s of a pixel inside
// it has the quad's colour iff alpha > s / 4 (lavapipe: no dither, a strict compare).
TEST(Multisample, AlphaToCoverageKeepsSampleSWhereAlphaExceedsSQuarters) {
  const crosscheck::Frame f = renderAgreeing("alpha_to_coverage_msaa", {});
  ASSERT_EQ(f.samples, 4u);
  constexpr std::array<float, 9> kAlphas = {0.0f, 0.1f, 0.25f, 0.3f, 0.5f, 0.6f, 0.75f, 0.8f, 1.0f};
  for (std::uint32_t i = 0; i < kAlphas.size(); ++i) {
    const auto x = static_cast<std::uint32_t>(4 + i * 20.5 + 9), y = 13u;
    for (std::uint32_t s = 0; s < 4; ++s) {
      const bool expected = kAlphas[i] > 0.25f * static_cast<float>(s);
      EXPECT_EQ(sameRgb(sampleColour(f, x, y, s), kFlatQuad), expected) << "alpha " << kAlphas[i] << " sample " << s;
    }
  }
  // Second row, quads 1 and 3 have alpha to one: every sample they wrote holds alpha 255; the
  // plain gradient (quad 0) writes its own alpha, below 255 left of its right edge.
  for (std::uint32_t x = 12; x < 44; x += 3) {
    const auto plain = sampleColour(f, x, 44, 0);
    EXPECT_LT(int{plain[3]}, 255) << "plain gradient at x " << x;
  }
  std::size_t opaque = 0;
  for (std::uint32_t x = 52; x < 92; ++x) {
    for (std::uint32_t s = 0; s < 4; ++s) {
      const auto c = sampleColour(f, x, 44, s);
      // A sample the quad wrote has alpha 255; the background's alphas there are below 255.
      opaque += c[3] == 255;
    }
  }
  EXPECT_GT(opaque, 40u);
}

// alpha_to_coverage_per_sample: alpha to coverage with per-sample invocations (sample shading and
// builtins_discard, whose back-face alpha is 1 - gl_FragCoord.z at the sample). lavapipe keeps
// sample s where every *other* invocation's alpha > s/4 (uncovered samples' invocations too) and
// never tests its own: softraster agrees on every sample. In spec mode each sample is narrowed by
// its own invocation's alpha instead (the known deviation alpha_to_coverage_per_sample): the
// samples near the thresholds differ, the fast and the scalar paths alike.
TEST(Multisample, AlphaToCoverageWithPerSampleInvocationsNarrowsByTheOtherSamples) {
  const crosscheck::Frame driver = renderAgreeing("alpha_to_coverage_per_sample", {});
  ASSERT_EQ(driver.samples, 4u);
  std::size_t written = 0;
  for (std::size_t i = 3; i < driver.sampleRgba.size(); i += 4) written += driver.sampleRgba[i] != 0;
  EXPECT_GT(written, 2000u);
  const std::vector<crosscheck::Frame> spec = agreement::renderInSpecMode("alpha_to_coverage_per_sample");
  ASSERT_EQ(spec.size(), 2u);
  EXPECT_EQ(spec[0].sampleRgba, spec[1].sampleRgba) << "the fast and the scalar path differ in spec mode";
  std::size_t differing = 0;
  for (std::size_t i = 0; i + 3 < driver.sampleRgba.size(); i += 4) {
    differing += !std::equal(driver.sampleRgba.begin() + static_cast<std::ptrdiff_t>(i),
                             driver.sampleRgba.begin() + static_cast<std::ptrdiff_t>(i + 4),
                             spec[0].sampleRgba.begin() + static_cast<std::ptrdiff_t>(i));
  }
  EXPECT_GT(differing, 20u);
  EXPECT_LT(differing, written / 4) << "only samples near the alpha thresholds differ";
}

// alpha_to_coverage_nan: lavapipe's alpha > t is an unordered compare, so where the left quad's
// alpha is NaN (inf - inf from vertex alphas of +-3e38) every sample is kept and stores the NaN,
// with four samples and with one; the control quad keeps samples by threshold as usual.
TEST(Multisample, AlphaToCoverageKeepsEverySampleOfANanAlpha) {
  for (const std::uint32_t samples : {4u, 1u}) {
    SCOPED_TRACE(samples);
    const crosscheck::Frame f =
        renderAgreeing("alpha_to_coverage_nan", {"framebuffer.samples=" + std::to_string(samples)});
    ASSERT_EQ(f.samples, samples);
    const std::vector<std::uint32_t>& words = samples == 4 ? f.sampleColourWords : f.colourWords;
    ASSERT_EQ(words.size(), std::size_t{f.width} * f.height * samples * 4);
    const auto word = [&](std::uint32_t x, std::uint32_t y, std::uint32_t s, int channel) {
      float v;
      const std::uint32_t w = words[((std::size_t{y} * f.width + x) * samples + s) * 4 + channel];
      std::memcpy(&v, &w, sizeof v);
      return v;
    };
    std::size_t nanPixels = 0;
    for (std::uint32_t y = 0; y < f.height; ++y) {
      for (std::uint32_t x = 0; x < f.width / 2; ++x) {
        bool allNan = true;
        for (std::uint32_t s = 0; s < samples; ++s) allNan = allNan && std::isnan(word(x, y, s, 3));
        if (!allNan) continue;
        ++nanPixels;
        for (std::uint32_t s = 0; s < samples; ++s) {
          EXPECT_EQ(word(x, y, s, 0), 0.9f) << x << "," << y << " sample " << s;
        }
      }
    }
    EXPECT_GT(nanPixels, std::size_t{f.width / 2} * f.height / 2) << "most of the left quad has a NaN alpha, kept";
  }
}

// alpha_to_coverage (one sample): the quads of alpha 0, 0.49, 0.5, 0.51 and 1 are drawn iff
// alpha > 0.5; a killed fragment leaves the stencil the second quad tests.
TEST(Multisample, AlphaToCoverageWithOneSampleKeepsAlphaAboveOneHalf) {
  const crosscheck::Frame f = renderAgreeing("alpha_to_coverage", {});
  ASSERT_EQ(f.samples, 1u);
  constexpr std::array<float, 5> kAlphas = {0.0f, 0.49f, 0.5f, 0.51f, 1.0f};
  for (std::uint32_t i = 0; i < kAlphas.size(); ++i) {
    const auto x = static_cast<std::uint32_t>(4 + i * 20.5 + 9);
    EXPECT_EQ(sameRgb(pixelColour(f, x, 13), kFlatQuad), kAlphas[i] > 0.5f) << "alpha " << kAlphas[i];
  }
  // The depth-and-stencil quad (alpha 1 on the left, 0 on the right, x 4.4 .. 64.5): its left
  // part counted the stencil to 1 and the nearer-is-less quad over it then failed there (fail_op
  // zero), its right part was killed and left stencil 0, which the second quad inverted to 255.
  EXPECT_EQ(int{f.stencil.at(static_cast<std::size_t>(70) * f.width + 12)}, 0);
  EXPECT_EQ(int{f.stencil.at(static_cast<std::size_t>(70) * f.width + 56)}, 255);
  EXPECT_TRUE(sameRgb(pixelColour(f, 56, 70), {51, 230, 230, 255}));  // the second quad, drawn where the first was killed
  EXPECT_FALSE(sameRgb(pixelColour(f, 12, 70), {51, 230, 230, 255}));
}

// sample_mask_single_sample: lavapipe draws the quad of mask 0xfffffffe (only a whole mask of 0
// discards), the spec does not (bit 0 is the one sample's); mask 0x1 is drawn and mask 0 is not
// in both. Driver mode agrees with lavapipe to the bit; spec mode differs exactly on the first
// quad, which keeps the background and stencil 0.
TEST(Multisample, OneSampleMaskDeviationDriverAndSpec) {
  const crosscheck::Frame driver = renderAgreeing("sample_mask_single_sample", {});
  ASSERT_FALSE(driver.stencil.empty());
  const auto at = [&](const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y) {
    return int{f.stencil.at(static_cast<std::size_t>(y) * f.width + x)};
  };
  EXPECT_EQ(at(driver, 20, 30), 7);
  const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode("sample_mask_single_sample");
  ASSERT_EQ(specFrames.size(), 2u);
  for (const crosscheck::Frame& spec : specFrames) {
    EXPECT_EQ(at(spec, 20, 30), 0);
    EXPECT_TRUE(sameRgb(pixelColour(spec, 60, 30), pixelColour(driver, 60, 30)));  // mask 0x1: drawn by both
    std::size_t differing = 0, outsideFirstQuad = 0;
    for (std::uint32_t y = 0; y < driver.height; ++y) {
      for (std::uint32_t x = 0; x < driver.width; ++x) {
        if (!sameRgb(pixelColour(spec, x, y), pixelColour(driver, x, y))) {
          ++differing;
          outsideFirstQuad += !(x >= 8 && x <= 49 && y >= 8 && y <= 55);
        }
      }
    }
    EXPECT_GT(differing, 1500u);  // about 40 x 46 pixels
    EXPECT_EQ(outsideFirstQuad, 0u);
  }
}

// The scene format: "multisample" reads its four fields and refuses what is not one of them.
TEST(Multisample, SceneFieldsAndErrors) {
  auto scene = crosscheck::loadScene(agreement::kScenes / "sample_mask_msaa.json",
                                     {"draws.1.multisample={\"sample_mask\": 4294967295, \"alpha_to_coverage\": true, "
                                      "\"alpha_to_one\": true}"});
  ASSERT_TRUE(scene) << scene.error();
  const softraster::MultisampleState& m = scene->draws.at(1).state.multisample;
  EXPECT_EQ(m.sampleMask, 0xFFFFFFFFu);
  EXPECT_TRUE(m.alphaToCoverageEnable);
  EXPECT_TRUE(m.alphaToOneEnable);
  EXPECT_EQ(scene->draws.at(0).state.multisample.sampleMask, 0xFFFFFFFFu);  // the default
  agreement::expectSceneError({"draws.1.multisample.sample_mask=4294967296"}, "sample_mask_msaa.json",
                              "/draws/1/multisample/sample_mask: 4294967296 is more than 4294967295");
  agreement::expectSceneError({"draws.1.multisample.sample_mask=-1"}, "sample_mask_msaa.json",
                              "/draws/1/multisample/sample_mask: expected a non-negative integer");
  agreement::expectSceneError({"draws.1.multisample.coverage=1"}, "sample_mask_msaa.json",
                              "/draws/1/multisample");
  agreement::expectSceneError({"draws.1.multisample.alpha_to_one=\"yes\""}, "sample_mask_msaa.json",
                              "/draws/1/multisample/alpha_to_one");
  agreement::expectSceneError({"draws.1.multisample.min_sample_shading=1.5"}, "sample_mask_msaa.json",
                              "/draws/1/multisample/min_sample_shading: must be in [0, 1] (VUID-VkPipelineMultisampleStateCreateInfo-minSampleShading-00786");
  agreement::expectSceneError({"draws.1.multisample.min_sample_shading=\"half\""}, "sample_mask_msaa.json",
                              "/draws/1/multisample/min_sample_shading");
  agreement::expectSceneError({"draws.1.multisample.alpha_to_coverage=true", "draws.1.line_rasterization=bresenham"},
                              "sample_mask_msaa.json", "lineRasterizationMode-02766");
}

// points_msaa: with 4x MSAA lavapipe snaps a point's square without the half-pixel offset and
// covers each sample inside it. A size-1 point centred on the pixel corner (20, 30) covers
// [19.5, 20.5) x [29.5, 30.5): one sample in each of the four pixels around the corner, the one
// nearest it (pixel (19, 29): sample 3 at (0.625, 0.875); (20, 29): sample 2; (19, 30): sample 1;
// (20, 30): sample 0), stencil 9 there and 0 elsewhere; one centred on (30.5, 30.5) covers its
// pixel's four samples. A point across the scissor's top-left corner is cut exactly at it.
TEST(Multisample, PointsCoverSamplesOfTheirSquare) {
  const crosscheck::Frame f = renderAgreeing("points_msaa", {});
  ASSERT_EQ(f.samples, 4u);
  const auto stencilAt = [&](std::uint32_t x, std::uint32_t y, std::uint32_t s) {
    return int{f.sampleStencil.at(sampleIndex(f, x, y, s))};
  };
  const std::uint32_t corner[4][3] = {{19, 29, 3}, {20, 29, 2}, {19, 30, 1}, {20, 30, 0}};
  for (const auto& [x, y, covered] : corner) {
    for (std::uint32_t s = 0; s < 4; ++s) {
      EXPECT_EQ(stencilAt(x, y, s), s == covered ? 9 : 0) << x << ", " << y << " sample " << s;
      EXPECT_EQ(sameRgb(sampleColour(f, x, y, s), {242, 230, 26, 255}), s == covered) << x << ", " << y << " sample " << s;
    }
  }
  for (std::uint32_t s = 0; s < 4; ++s) {
    EXPECT_TRUE(sameRgb(sampleColour(f, 30, 30, s), {26, 230, 242, 255})) << "sample " << s;
    EXPECT_TRUE(sameRgb(sampleColour(f, 81, 11, s), {230, 51, 153, 255})) << "inside the scissor, sample " << s;
    EXPECT_FALSE(sameRgb(sampleColour(f, 79, 11, s), {230, 51, 153, 255})) << "left of the scissor, sample " << s;
    EXPECT_FALSE(sameRgb(sampleColour(f, 81, 9, s), {230, 51, 153, 255})) << "above the scissor, sample " << s;
  }
}

// lines_msaa, driver mode (what lavapipe does) and spec mode. Against the scissor at x 70 (its
// column 69 is the partial column, 70 not being a multiple of 64):
//   - the line from x 66.6 (y 6.4) crosses the scissor's left edge, so it carries the scissor
//     plane with lavapipe's +127/256: pixel (69, 6), fully inside the line, gets samples 1 and 3
//     (x offsets 0.875, 0.625) and keeps the background in 0 and 2;
//   - the line from x 69.3 (y 10.4, width 2; its left edge runs from x 69.24 to 69.36) starts in
//     column 69, but its bounding box starts at the first pixel whose corner it covers, column 70,
//     the scissor's: no plane, and its tile (x 64..127) is walked whole, so pixel (69, 10)
//     gets every sample inside the line: 0, 1 and 3, not 2 (x offset 0.125);
//   - the line from x 70.3 leaves column 69 alone.
// The short line from x 63.05 (y 30.4, width 2) covers samples 1 and 3 of pixel (63, 30), but its
// box starts at x 64, in the next tile, and lavapipe walks only the tiles it bins: (63, 30) keeps
// the background there, and gets those samples in spec mode.
// The spec scissors whole fragments: column 69 keeps the background in spec mode. The Bresenham
// strip is drawn with multisampling off: its stencil (replace 77 where the depth test passes) is
// written at sample 0 only; in spec mode at every sample that passes.
TEST(Multisample, LinesAsLavapipeBinsThem) {
  const crosscheck::Frame driver = renderAgreeing("lines_msaa", {});
  ASSERT_EQ(driver.samples, 4u);
  ASSERT_FALSE(driver.sampleStencil.empty());
  // The samples of pixel (x, y) whose colour differs from sample `untouched`'s (the background).
  const auto drawnSamples = [](const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t untouched) {
    unsigned drawn = 0;
    for (std::uint32_t s = 0; s < 4; ++s) {
      if (!sameRgb(sampleColour(f, x, y, s), sampleColour(f, x, y, untouched))) drawn |= 1u << s;
    }
    return drawn;
  };
  EXPECT_EQ(drawnSamples(driver, 69, 6, 0), 0b1010u);
  EXPECT_EQ(drawnSamples(driver, 69, 10, 2), 0b1011u);
  EXPECT_EQ(drawnSamples(driver, 69, 14, 0), 0u);
  EXPECT_EQ(drawnSamples(driver, 71, 6, 0), 0u);  // inside the scissor and the line: every sample drawn alike
  EXPECT_FALSE(sameRgb(sampleColour(driver, 71, 6, 0), sampleColour(driver, 69, 6, 0)));
  EXPECT_EQ(drawnSamples(driver, 63, 30, 0), 0u);
  // 77 at sample 0 only: nothing else writes 77 (the other stencils count up from 0).
  const auto countStencil77 = [](const crosscheck::Frame& f, std::uint32_t s) {
    std::size_t n = 0;
    for (std::uint32_t y = 0; y < f.height; ++y) {
      for (std::uint32_t x = 0; x < f.width; ++x) n += f.sampleStencil.at(sampleIndex(f, x, y, s)) == 77;
    }
    return n;
  };
  EXPECT_GT(countStencil77(driver, 0), 100u);
  for (std::uint32_t s = 1; s < 4; ++s) EXPECT_EQ(countStencil77(driver, s), 0u) << "sample " << s;

  const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode("lines_msaa");
  ASSERT_EQ(specFrames.size(), 2u);
  for (const crosscheck::Frame& spec : specFrames) {
    for (const std::uint32_t y : {6u, 10u, 14u}) EXPECT_EQ(drawnSamples(spec, 69, y, 0), 0u) << "row " << y;
    for (const std::uint32_t s : {1u, 3u}) {
      EXPECT_FALSE(sameRgb(sampleColour(spec, 63, 30, s), sampleColour(driver, 63, 30, s))) << "sample " << s;
    }
    for (std::uint32_t s = 1; s < 4; ++s) EXPECT_GT(countStencil77(spec, s), 100u) << "sample " << s;
    std::size_t differing = 0;
    for (std::size_t i = 0; i < driver.sampleRgba.size(); i += 4) {
      differing += driver.sampleRgba[i] != spec.sampleRgba[i] || driver.sampleRgba[i + 1] != spec.sampleRgba[i + 1] ||
                   driver.sampleRgba[i + 2] != spec.sampleRgba[i + 2];
    }
    EXPECT_GT(differing, 500u);  // the half-pixel shift of every line's colours, the lost samples, the stencil
  }
}

// msaa_bresenham_sample_state: 4x MSAA Bresenham lines, which lavapipe draws with multisampling
// off. Checked against the same scene with those lines' sample mask 0 (nothing drawn: the
// background): in driver mode a line writes all four samples of a pixel alike whatever the mask
// (0x5, 0x10, 0x6, 0x8 blended); in spec mode the mask applies per sample (0x10: nothing; 0x5:
// samples 1 and 3 stay background).
TEST(Multisample, BresenhamLinesIgnoreTheSampleMaskAsLavapipeDoes) {
  const std::string name = "msaa_bresenham_sample_state";
  const crosscheck::Frame driver = renderAgreeing(name, {});
  std::vector<std::string> none;
  for (int d = 1; d <= 6; ++d) none.push_back("draws." + std::to_string(d) + ".multisample={\"sample_mask\":0}");
  const crosscheck::Frame background = renderAgreeing(name, none);
  ASSERT_EQ(driver.samples, 4u);
  ASSERT_EQ(background.sampleRgba.size(), driver.sampleRgba.size());
  const auto drawn = [&](const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t s) {
    return !sameRgb(sampleColour(f, x, y, s), sampleColour(background, x, y, s));
  };
  // Rows y0 - 2 .. y0 + 8 of a line row starting at y0, columns 0..109 (the polygon-mode draw lies right of them).
  const auto band = [&](std::uint32_t y0, auto&& visit) {
    for (std::uint32_t y = y0 - 2; y <= y0 + 8; ++y) {
      for (std::uint32_t x = 0; x < 110; ++x) visit(x, y);
    }
  };
  for (const std::uint32_t y0 : {6u, 18u, 30u, 42u}) {
    std::size_t pixels = 0;
    band(y0, [&](std::uint32_t x, std::uint32_t y) {
      const bool any = drawn(driver, x, y, 0) || drawn(driver, x, y, 1) || drawn(driver, x, y, 2) || drawn(driver, x, y, 3);
      if (!any) return;
      ++pixels;
      for (std::uint32_t s = 1; s < 4; ++s) {
        // (Blended lines keep differences the background's samples had: its diagonal edge.)
        if (sampleColour(background, x, y, s) != sampleColour(background, x, y, 0)) continue;
        EXPECT_EQ(sampleColour(driver, x, y, s), sampleColour(driver, x, y, 0)) << x << ", " << y << " sample " << s;
      }
    });
    EXPECT_GT(pixels, 150u) << "row " << y0;
  }
  const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode(name);
  ASSERT_EQ(specFrames.size(), 2u);
  for (const crosscheck::Frame& spec : specFrames) {
    std::size_t masked = 0, kept = 0;
    band(18, [&](std::uint32_t x, std::uint32_t y) {
      for (std::uint32_t s = 0; s < 4; ++s) masked += drawn(spec, x, y, s);
    });
    band(6, [&](std::uint32_t x, std::uint32_t y) {
      for (const std::uint32_t s : {1u, 3u}) masked += drawn(spec, x, y, s);
      kept += drawn(spec, x, y, 0);
    });
    EXPECT_EQ(masked, 0u) << "spec: the mask drops those samples";
    EXPECT_GT(kept, 150u);
  }
}
