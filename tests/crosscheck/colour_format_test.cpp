// The colour formats, cross-checked: a B8G8R8A8_UNORM target agrees with lavapipe to the bit (the
// fast and the scalar exact paths, every sample) on its own scene and on the blending scenes drawn
// into it; its frame, read back as R, G, B, A, is the R8G8B8A8 frame of the same scene byte for
// byte (lavapipe blends both in the same 8-bit arithmetic per channel). sRGB targets (R8G8B8A8 and
// B8G8R8A8) agree to the bit on theirs and on the blending scenes, one sample and four, and differ
// from the UNORM frames (the blending is in linear values); their clear uses the clear's own
// encoding. Then the loader's error for an unknown format. (softraster's BGRA byte order:
// tests/softraster/api_test.cpp.)
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using agreement::expectSceneError;
using agreement::renderAgreeing;

// The vertex colours of colour_format_bgra put red and blue far apart: a frame with the two
// swapped would differ in most covered pixels.
std::size_t pixelsWithRedAboveBlue(const crosscheck::Frame& f) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < f.rgba.size(); i += 4) n += f.rgba[i] > f.rgba[i + 2];
  return n;
}

}  // namespace

TEST(ColourFormat, BgraAgreesAndEqualsTheRgbaFrame) {
  const crosscheck::Frame bgra = renderAgreeing("colour_format_bgra", {});
  const crosscheck::Frame rgba = renderAgreeing("colour_format_bgra", {"framebuffer.colour_format=r8g8b8a8_unorm"});
  ASSERT_EQ(bgra.rgba.size(), std::size_t{192} * 136 * 4);
  ASSERT_EQ(bgra.samples, 4u);
  EXPECT_EQ(bgra.rgba, rgba.rgba) << "the resolve";
  EXPECT_EQ(bgra.sampleRgba, rgba.sampleRgba) << "every sample";
  // The clear strip at the bottom: clear colour [0.93, 0.5, 0.08, 0.7] as R, G, B, A.
  const std::size_t clear = 4 * (std::size_t{192} * 130 + 100);
  EXPECT_EQ((std::array<int, 4>{bgra.rgba[clear], bgra.rgba[clear + 1], bgra.rgba[clear + 2], bgra.rgba[clear + 3]}),
            (std::array<int, 4>{237, 128, 20, 178}));
  // Both orders of red and blue are present, so a swap anywhere could not go unnoticed.
  const std::size_t redAbove = pixelsWithRedAboveBlue(bgra);
  EXPECT_GT(redAbove, 3000u);
  EXPECT_LT(redAbove, std::size_t{192} * 136 - 3000);
}

TEST(ColourFormat, SingleSampleBgraAgrees) {
  const crosscheck::Frame bgra = renderAgreeing("colour_format_bgra", {"framebuffer.samples=1"});
  const crosscheck::Frame rgba =
      renderAgreeing("colour_format_bgra", {"framebuffer.samples=1", "framebuffer.colour_format=r8g8b8a8_unorm"});
  EXPECT_EQ(bgra.rgba, rgba.rgba);
}

// Every blend factor, op, write mask and logic op, and MSAA blending, into a B8G8R8A8 target.
TEST(ColourFormat, BlendingScenesAgreeOnBgra) {
  for (const std::string name : {"blend_factors", "blend_ops", "blend_write_mask", "logic_ops", "msaa_blend"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame bgra = renderAgreeing(name, {"framebuffer.colour_format=b8g8r8a8_unorm"});
    EXPECT_FALSE(bgra.rgba.empty());
  }
}

TEST(ColourFormat, SrgbAgreesAndBlendsInLinearValues) {
  const crosscheck::Frame srgb = renderAgreeing("colour_format_srgb", {});
  ASSERT_EQ(srgb.rgba.size(), std::size_t{256} * 136 * 4);
  // The clear strip: [0.5, 0.2, 0.0031, 0.5] through the clear's table, 0.5 -> 188 (a fragment
  // store gives 187; the correctly rounded sRGB value is 187.53), 0.2 -> 124, alpha 0.5 -> 128.
  const std::size_t clear = 4 * (std::size_t{256} * 130 + 100);
  EXPECT_EQ(int{srgb.rgba[clear]}, 188);
  EXPECT_EQ(int{srgb.rgba[clear + 1]}, 124);
  EXPECT_EQ(int{srgb.rgba[clear + 3]}, 128);
  // The same scene into a UNORM target blends the stored bytes instead: most covered pixels differ.
  const crosscheck::Frame unorm = renderAgreeing("colour_format_srgb", {"framebuffer.colour_format=r8g8b8a8_unorm"});
  EXPECT_GT(agreement::pixelsDiffering(srgb, unorm), std::size_t{256} * 120 / 2);
  const crosscheck::Frame bgra = renderAgreeing("colour_format_srgb", {"framebuffer.colour_format=b8g8r8a8_srgb"});
  EXPECT_EQ(bgra.rgba, srgb.rgba);
  EXPECT_EQ(bgra.sampleRgba, srgb.sampleRgba);
}

TEST(ColourFormat, SingleSampleSrgbAgrees) {
  const crosscheck::Frame srgb = renderAgreeing("colour_format_srgb", {"framebuffer.samples=1"});
  EXPECT_FALSE(srgb.rgba.empty());
}

// Every blend factor, op and write mask, logic ops (not applied), MSAA blending and the course's
// transparency, into an sRGB target.
TEST(ColourFormat, BlendingScenesAgreeOnSrgb) {
  for (const std::string name : {"blend_factors", "blend_ops", "blend_write_mask", "logic_ops", "msaa_blend", "transparency"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame srgb = renderAgreeing(name, {"framebuffer.colour_format=r8g8b8a8_srgb"});
    EXPECT_FALSE(srgb.rgba.empty());
  }
}

TEST(ColourFormat, UnknownFormatIsOneLineNamingTheFile) {
  expectSceneError({"framebuffer.colour_format=r16g16b16a16_sfloat"}, "colour_format_bgra.json",
                   "/framebuffer/colour_format: 'r16g16b16a16_sfloat' is not one of r8g8b8a8_unorm, b8g8r8a8_unorm, "
                   "r8g8b8a8_srgb, b8g8r8a8_srgb");
}
