// The colour formats, cross-checked: a B8G8R8A8_UNORM target agrees with lavapipe to the bit (the
// fast and the scalar exact paths, every sample) on its own scene and on the blending scenes drawn
// into it; its frame, read back as R, G, B, A, is the R8G8B8A8 frame of the same scene byte for
// byte (lavapipe blends both in the same 8-bit arithmetic per channel). sRGB targets (R8G8B8A8 and
// B8G8R8A8) agree to the bit on theirs and on the blending scenes, one sample and four, and differ
// from the UNORM frames (the blending is in linear values); their clear uses the clear's own
// encoding. A2B10G10R10, R16G16B16A16_SFLOAT and R32G32B32A32_SFLOAT targets agree on every
// stored bit, on their scenes and the blending scenes. Then the loader's errors: colours out of
// the target's range, an unknown format; and the outputs name the unit of a colour delta (8-bit
// steps, 10-bit steps, half or float ULPs). (softraster's BGRA byte order:
// tests/softraster/api_test.cpp.)
#include "agreement.hpp"
#include "output/compare_text.hpp"
#include "output/junit.hpp"
#include "output/summary.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
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

// An A2B10G10R10 target agrees with lavapipe on every stored 10-bit and 2-bit value (every sample
// and the resolve), not only on the bytes of its view; its clear is packed by the clear's own
// rounding.
TEST(ColourFormat, TenBitAgreesOnEveryStoredBit) {
  const crosscheck::Frame tenBit = renderAgreeing("colour_format_10bit", {});
  ASSERT_EQ(tenBit.colourWords.size(), std::size_t{256} * 136);
  ASSERT_EQ(tenBit.sampleColourWords.size(), std::size_t{256} * 136 * 4);
  // The clear strip: [0.9995, 0.25, 0.6, 0.5] -> 1022, 256, 614, 2.
  EXPECT_EQ(tenBit.colourWords[std::size_t{256} * 130 + 100], softraster::packTenBit(1022, 256, 614, 2));
  // The stored words carry more than their byte view: some pixels differ in the low bits alone.
  const crosscheck::Frame unorm = renderAgreeing("colour_format_10bit", {"framebuffer.colour_format=r8g8b8a8_unorm"});
  EXPECT_TRUE(unorm.colourWords.empty());
  std::set<std::uint32_t> lowBits;
  for (const std::uint32_t w : tenBit.colourWords) lowBits.insert(w & 3u);
  EXPECT_EQ(lowBits.size(), 4u) << "red's two bits below the byte view take every value";
}

TEST(ColourFormat, SingleSampleTenBitAgrees) {
  const crosscheck::Frame tenBit = renderAgreeing("colour_format_10bit", {"framebuffer.samples=1"});
  EXPECT_EQ(tenBit.colourWords.size(), std::size_t{256} * 136);
  EXPECT_TRUE(tenBit.sampleColourWords.empty());
}

// Every blend factor pair and every logic op into an A2B10G10R10 target (lavapipe's 16-bit integer
// path, logic ops applied). Ops, write masks and MSAA: colour_format_10bit's cells. (Two scenes,
// not the six the 8-bit formats run: each costs seconds of CI under the validation layer.)
TEST(ColourFormat, BlendingScenesAgreeOnTenBit) {
  for (const std::string name : {"blend_factors", "logic_ops"}) {
    SCOPED_TRACE(name);
    const crosscheck::Frame tenBit = renderAgreeing(name, {"framebuffer.colour_format=a2b10g10r10_unorm"});
    EXPECT_FALSE(tenBit.colourWords.empty());
  }
}

// Float targets agree with lavapipe on every stored half and float (every sample and the resolve):
// unclamped values, halves rounded toward zero and held at 65504, tiny values as half denormals.
TEST(ColourFormat, HalfFloatAgreesOnEveryStoredBit) {
  const crosscheck::Frame half = renderAgreeing("colour_format_float", {});
  ASSERT_EQ(half.colourWords.size(), std::size_t{256} * 136 * 2);
  ASSERT_EQ(half.sampleColourWords.size(), std::size_t{256} * 136 * 4 * 2);
  // The clear strip: [100000, -2.5, 0.3, 3] -> halves 0x7bff (65504), 0xc100, 0x34cc (0.2998, toward
  // zero; the nearest half is 0x34cd), 0x4200.
  const std::size_t clear = 2 * (std::size_t{256} * 130 + 100);
  EXPECT_EQ(half.colourWords[clear], 0xc1007bffu);
  EXPECT_EQ(half.colourWords[clear + 1], 0x420034ccu);
  // Values beyond [0, 1], half denormals and the largest half all occur among the stored red halves.
  bool above = false, negative = false, denormal = false, largest = false;
  for (std::size_t i = 0; i < half.colourWords.size(); i += 2) {
    const std::uint32_t red = half.colourWords[i] & 0xffffu;
    above = above || (red >= 0x3c01u && red < 0x7c00u);
    negative = negative || (red > 0x8000u && red < 0xfc00u);
    denormal = denormal || (red > 0u && red < 0x0400u);
    largest = largest || red == 0x7bffu;
  }
  EXPECT_TRUE(above);
  EXPECT_TRUE(negative);
  EXPECT_TRUE(denormal);
  EXPECT_TRUE(largest);
}

TEST(ColourFormat, FloatAgreesOnEveryStoredBit) {
  const crosscheck::Frame f32 = renderAgreeing("colour_format_float", {"framebuffer.colour_format=r32g32b32a32_sfloat"});
  ASSERT_EQ(f32.colourWords.size(), std::size_t{256} * 136 * 4);
  const std::size_t clear = 4 * (std::size_t{256} * 130 + 100);
  EXPECT_EQ(f32.colourWords[clear], 0x47c35000u) << "100000 as given";
  EXPECT_EQ(f32.colourWords[clear + 2], 0x3e99999au) << "0.3 as given";
}

TEST(ColourFormat, SingleSampleFloatTargetsAgree) {
  for (const std::string format : {"r16g16b16a16_sfloat", "r32g32b32a32_sfloat"}) {
    SCOPED_TRACE(format);
    const crosscheck::Frame f =
        renderAgreeing("colour_format_float", {"framebuffer.samples=1", "framebuffer.colour_format=" + format});
    EXPECT_FALSE(f.colourWords.empty());
  }
}

// Every blend factor pair into both float targets (ops, write masks, logic ops and MSAA:
// colour_format_float's cells).
TEST(ColourFormat, BlendingScenesAgreeOnFloatTargets) {
  for (const std::string format : {"r16g16b16a16_sfloat", "r32g32b32a32_sfloat"}) {
    SCOPED_TRACE(format);
    const crosscheck::Frame f = renderAgreeing("blend_factors", {"framebuffer.colour_format=" + format});
    EXPECT_FALSE(f.colourWords.empty());
  }
}

// The comparison sees the stored bits of a wider format, not its byte view: one 10-bit step in one
// sample (not 0), one unit in the last place of a half or a float, and the sign of a zero are each
// caught, though the bytes of the view stay the same.
TEST(ColourFormat, ADifferenceBelowTheByteViewIsCaught) {
  for (const std::string format : {"a2b10g10r10_unorm", "r16g16b16a16_sfloat", "r32g32b32a32_sfloat"}) {
    SCOPED_TRACE(format);
    const std::string file = format == "a2b10g10r10_unorm" ? "colour_format_10bit.json" : "colour_format_float.json";
    auto scene = crosscheck::loadScene(agreement::kScenes / file, {"framebuffer.colour_format=" + format,
                                                                    "draws.1.colours=[[0.5, 0.25, 0.75, 1], "
                                                                    "[0.5, 0.25, 0.75, 1], [0.5, 0.25, 0.75, 1]]"});
    ASSERT_TRUE(scene) << scene.error();
    auto frame = crosscheck::renderSoftraster(*scene);
    ASSERT_TRUE(frame) << frame.error();
    const crosscheck::Frame& a = *frame;
    ASSERT_FALSE(a.sampleColourWords.empty());
    const std::size_t words = a.colourWords.size() / (std::size_t{a.width} * a.height);
    // A pixel inside draw 1's triangle (cell 0, a plain store of one colour), every sample alike.
    std::size_t pixel = 0;
    while (pixel < a.colourWords.size() / words &&
           !(a.rgba[4 * pixel] == 128 && a.rgba[4 * pixel + 1] == 64 && a.rgba[4 * pixel + 2] == 191)) {
      ++pixel;
    }
    ASSERT_LT(pixel, a.colourWords.size() / words) << "no pixel of draw 1 found";
    crosscheck::Frame b = a;
    b.sampleColourWords[(pixel * 4 + 2) * words] ^= 1u;  // sample 2: red's lowest bit
    crosscheck::Comparison c = crosscheck::compareFrames(a, b, *scene);
    EXPECT_EQ(c.colourMaxDelta[0], 1);
    EXPECT_EQ(c.colourUnit, format == "a2b10g10r10_unorm"     ? "10-bit steps (alpha 2-bit)"
                            : format == "r16g16b16a16_sfloat" ? "half ULPs"
                                                              : "float ULPs");
    EXPECT_EQ(c.resolvedColourMaxDelta[0], 0);
    EXPECT_EQ(c.coverageMismatches, 0u);
    EXPECT_EQ(b.sampleRgba, a.sampleRgba) << "the byte view does not show it";
    b = a;
    b.colourWords[pixel * words] ^= 1u;  // the resolve
    EXPECT_EQ(crosscheck::colourDifferingPixels(a, b), 1u);
    EXPECT_EQ(crosscheck::compareFrames(a, b, *scene).resolvedColourMaxDelta[0], 1);
    EXPECT_EQ(crosscheck::colourDifferingPixels(a, a), 0u);
  }
  // -0 and +0 differ by one step.
  crosscheck::Frame zero;
  zero.width = zero.height = 1;
  zero.rgba = {0, 0, 0, 0};
  zero.colourFormat = softraster::ColourFormat::R32G32B32A32Sfloat;
  zero.colourWords = {0u, 0u, 0u, 0u};
  zero.depthStorage = {0u};
  zero.depth = {0.0f};
  crosscheck::Frame negative = zero;
  negative.colourWords[1] = 0x80000000u;
  auto scene = crosscheck::loadScene(agreement::kScenes / "colour_format_float.json", {});
  ASSERT_TRUE(scene);
  EXPECT_EQ(crosscheck::compareFrames(zero, negative, *scene).colourMaxDelta[1], 1);
}

// Every output that prints a colour delta names its unit with it.
TEST(ColourFormat, ColourDeltasNameTheirUnit) {
  using softraster::ColourFormat;
  EXPECT_EQ(crosscheck::colourDeltaUnit(ColourFormat::R8G8B8A8Unorm), "8-bit steps");
  EXPECT_EQ(crosscheck::colourDeltaUnit(ColourFormat::B8G8R8A8Srgb), "8-bit steps");
  EXPECT_EQ(crosscheck::colourDeltaUnit(ColourFormat::A2B10G10R10Unorm), "10-bit steps (alpha 2-bit)");
  EXPECT_EQ(crosscheck::colourDeltaUnit(ColourFormat::R16G16B16A16Sfloat), "half ULPs");
  EXPECT_EQ(crosscheck::colourDeltaUnit(ColourFormat::R32G32B32A32Sfloat), "float ULPs");
  crosscheck::SceneResult r;
  r.entry = {"colour_format_float", "scenes/colour_format_float.json"};
  r.outcome = r.actual = crosscheck::Outcome::Fail;
  r.tolerance.colourThreshold = 0;
  r.comparison = crosscheck::Comparison{};
  r.comparison->colourMaxDelta = {3, 0, 0, 0};
  r.comparison->colourPixelsOver = 1;
  r.comparison->colourUnit = "float ULPs";
  r.comparison->failures = {"colour_pixels_over 1 > 0"};
  crosscheck::RunResults run;
  run.scenes = {r};
  EXPECT_NE(crosscheck::compareText(run).find("colour max |\xCE\x94| RGBA  3 0 0 0 (threshold 0; float ULPs)"),
            std::string::npos)
      << crosscheck::compareText(run);
  EXPECT_EQ(crosscheck::resultDetail(r), "colour_pixels_over 1 > 0 (colour max |\xCE\x94| 3 float ULPs, threshold 0)");
  EXPECT_NE(crosscheck::junitXml(run).find("colour_max_delta_rgba: 3 0 0 0 (threshold 0; float ULPs)"), std::string::npos);
}

// Colours beyond [0, 1] are refused for targets that clamp, and non-finite ones for any.
TEST(ColourFormat, ColourRangeFollowsTheTarget) {
  expectSceneError({"framebuffer.colour_format=r8g8b8a8_unorm", "framebuffer.clear_colour=[2, 0, 0, 1]"},
                   "colour_format_float.json", "/framebuffer/clear_colour/0: must be in [0, 1]");
  expectSceneError({"draws.1.colours=[[0, 0, 0, 1], [0, 1e300, 0, 1], [0, 0, 0, 1]]"}, "colour_format_float.json",
                   "/draws/1/colours/1/1: must be a finite float");
}

TEST(ColourFormat, UnknownFormatIsOneLineNamingTheFile) {
  expectSceneError({"framebuffer.colour_format=r16g16b16a16_unorm"}, "colour_format_bgra.json",
                   "/framebuffer/colour_format: 'r16g16b16a16_unorm' is not one of r8g8b8a8_unorm, b8g8r8a8_unorm, "
                   "r8g8b8a8_srgb, b8g8r8a8_srgb, a2b10g10r10_unorm, r16g16b16a16_sfloat, r32g32b32a32_sfloat");
}

// Several colour attachments (scenes colour_attachments and colour_attachments_msaa): every
// attachment agrees with lavapipe on every stored bit of every sample and of the resolve
// (renderAgreeing compares each), and each holds its own output, format and blending.
TEST(ColourAttachments, FourFormatsAgreeOnEveryStoredBit) {
  const crosscheck::Frame frame = renderAgreeing("colour_attachments", {});
  ASSERT_EQ(frame.moreColour.size(), 3u);
  const std::size_t pixels = std::size_t{160} * 120;
  EXPECT_EQ(frame.moreColour[0].colourFormat, softraster::ColourFormat::R16G16B16A16Sfloat);
  EXPECT_EQ(frame.moreColour[0].colourWords.size(), pixels * 2);
  EXPECT_EQ(frame.moreColour[1].colourWords.size(), pixels);
  EXPECT_TRUE(frame.moreColour[2].colourWords.empty()) << "sRGB is 8-bit: its bytes are exact";
  // The float attachment keeps what UNORM would clamp: additive blending takes it past 1.
  bool beyondOne = false;
  for (std::size_t i = 0; i < pixels * 4; ++i) {
    const std::uint32_t word = frame.moreColour[0].colourWords[i / 2];
    const std::uint16_t half = static_cast<std::uint16_t>(i % 2 ? word >> 16 : word & 0xffffu);
    beyondOne = beyondOne || (half < 0x8000u && half > 0x3c00u);  // positive and above 1.0
  }
  EXPECT_TRUE(beyondOne);
  // Each attachment holds its own output: no two of the four views are the same image.
  const std::vector<const std::vector<std::uint8_t>*> views = {&frame.rgba, &frame.moreColour[0].rgba,
                                                               &frame.moreColour[1].rgba, &frame.moreColour[2].rgba};
  for (std::size_t a = 0; a < views.size(); ++a) {
    for (std::size_t b = a + 1; b < views.size(); ++b) EXPECT_NE(*views[a], *views[b]) << a << " and " << b;
  }
}

TEST(ColourAttachments, FourFormatsAgreeWithMsaa) {
  const crosscheck::Frame frame = renderAgreeing("colour_attachments", {"framebuffer.samples=4"});
  ASSERT_EQ(frame.moreColour.size(), 3u);
  EXPECT_EQ(frame.moreColour[1].sampleColourWords.size(), std::size_t{160} * 120 * 4);
}

TEST(ColourAttachments, MsaaAgreesOnEverySampleOfEveryAttachment) {
  const crosscheck::Frame frame = renderAgreeing("colour_attachments_msaa", {});
  ASSERT_EQ(frame.moreColour.size(), 2u);
  ASSERT_EQ(frame.moreColour[0].sampleColourWords.size(), std::size_t{128} * 96 * 4 * 4);
  // Edges split pixels: some pixel's samples differ in the float attachment.
  bool split = false;
  const std::vector<std::uint32_t>& words = frame.moreColour[0].sampleColourWords;
  for (std::size_t p = 0; p < std::size_t{128} * 96 && !split; ++p) {
    for (std::size_t s = 1; s < 4; ++s) {
      split = split || !std::equal(words.begin() + static_cast<std::ptrdiff_t>((p * 4) * 4),
                                   words.begin() + static_cast<std::ptrdiff_t>((p * 4 + 1) * 4),
                                   words.begin() + static_cast<std::ptrdiff_t>((p * 4 + s) * 4));
    }
  }
  EXPECT_TRUE(split);
}

TEST(ColourAttachments, ADifferenceInALaterAttachmentFailsTheComparison) {
  auto scene = crosscheck::loadScene(agreement::kScenes / "colour_attachments.json", {});
  ASSERT_TRUE(scene) << scene.error();
  auto frame = crosscheck::renderSoftraster(*scene, {});
  ASSERT_TRUE(frame) << frame.error();
  crosscheck::Frame changed = *frame;
  changed.moreColour[1].colourWords[500] ^= 2u;  // two 10-bit steps of red (over the threshold, 1) in one pixel of attachment 2
  const crosscheck::Comparison c = crosscheck::compareFrames(changed, *frame, *scene);
  ASSERT_EQ(c.moreColour.size(), 3u);
  EXPECT_EQ(c.moreColour[1].colourMaxDelta[0], 2);
  EXPECT_EQ(c.moreColour[1].colourUnit, "10-bit steps (alpha 2-bit)");
  EXPECT_EQ(c.moreColour[1].colourPixelsOver, 1u);
  EXPECT_EQ(c.moreColour[0].colourPixelsOver, 0u);
  ASSERT_FALSE(c.passed());
  EXPECT_EQ(c.failures.front(), "colour_pixels_over (attachment 2) 1 > 0");
  crosscheck::RunResults run;
  crosscheck::SceneResult& r = run.scenes.emplace_back();
  r.entry.path = "colour_attachments.json";
  r.comparison = c;
  r.tolerance = scene->tolerance;
  EXPECT_NE(crosscheck::compareText(run).find("attachment 2 max"), std::string::npos) << crosscheck::compareText(run);
}

TEST(ColourAttachments, CourseMethodsFillEveryAttachment) {
  auto scene = crosscheck::loadScene(agreement::kScenes / "colour_attachments.json", {});
  ASSERT_TRUE(scene) << scene.error();
  softraster::ContextOptions exact, scanline;
  scanline.method = softraster::Method::Scanline;
  auto reference = crosscheck::renderSoftraster(*scene, exact);
  auto course = crosscheck::renderSoftraster(*scene, scanline);
  ASSERT_TRUE(reference && course);
  const crosscheck::Comparison c = crosscheck::compareFrames(*course, *reference, *scene);
  ASSERT_EQ(c.moreColour.size(), 3u);
  // The course's edges differ from the exact method's by a few pixels, not by an attachment left empty.
  EXPECT_LT(c.coverageMismatches, 400u);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_LT(c.moreColour[k].colourPixelsOver, 2000u) << "attachment " << k + 1;
}

TEST(ColourAttachments, SceneErrorsNameThePlace) {
  expectSceneError({"framebuffer.more_colour_attachments=[{}, {}, {}, {}, {}, {}, {}, {}]"}, "colour_attachments.json",
                   "/framebuffer/more_colour_attachments: expected an array of at most 7 attachments");
  expectSceneError({"framebuffer.more_colour_attachments.0.colour_format=r8_unorm"}, "colour_attachments.json",
                   "/framebuffer/more_colour_attachments/0/colour_format: 'r8_unorm' is not one of");
  expectSceneError({"draws.1.more_blend.0.constants=[1, 1, 1, 1]"}, "colour_attachments.json",
                   "/draws/1/more_blend/0/constants: is the pipeline's, for every colour attachment");
  expectSceneError({"draws.4.more_blend.1.write_mask=\"r\""}, "colour_attachments.json",
                   "/draws/4/shading: 'vertex_color' writes 1 colour output(s) but the framebuffer has 4 colour "
                   "attachments");
  expectSceneError({"framebuffer.more_colour_attachments.1.clear_colour=[2, 0, 0, 1]"}, "colour_attachments.json",
                   "/framebuffer/more_colour_attachments/1/clear_colour/0: must be in [0, 1]");
  // A float attachment 0's clear beyond [0, 1] is no default for a UNORM attachment.
  expectSceneError({"framebuffer.colour_format=r16g16b16a16_sfloat", "framebuffer.clear_colour=[2, 0, 0, 1]",
                    "framebuffer.more_colour_attachments=[{\"colour_format\": \"r8g8b8a8_unorm\"}]"},
                   "colour_attachments.json",
                   "/framebuffer/more_colour_attachments/0: needs its own clear_colour in [0, 1] "
                   "(the framebuffer's is not)");
  expectSceneError({"draws.1.more_blend=[{}, {}, {}, {}, {}, {}, {}, {}]"}, "colour_attachments.json",
                   "/draws/1/more_blend: expected an array of at most 7 blend objects");
}
