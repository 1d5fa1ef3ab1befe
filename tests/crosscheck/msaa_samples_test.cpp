// Every sample of a 4x MSAA frame compared, not only the resolve and sample 0: scene msaa_samples
// has pixels whose samples 1..3 hold what sample 0 does not (an edge between sample rows or
// columns), and both renderers agree there on every sample (colour, depth, stencil) under the
// validation layer. Then the comparison itself: a difference planted in one sample other than 0
// (colour, depth, stencil, coverage) is caught, though the resolve and sample 0 do not show it,
// and the metrics say how many samples were compared. Last, the scene in all five depth formats.
#include "agreement.hpp"

#include <softraster/formats.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>
#include <vector>

namespace {

using agreement::kScenes;
using agreement::renderAgreeing;

constexpr std::uint32_t kSamples = 4;

std::size_t sampleAt(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t s) {
  return (static_cast<std::size_t>(y) * f.width + x) * kSamples + s;
}

// The clear depth (1.0 as D32_SFLOAT's bits): a sample no draw reached.
bool reached(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y, std::uint32_t s) {
  return f.sampleDepthStorage.at(sampleAt(f, x, y, s)) != std::bit_cast<std::uint32_t>(1.0f);
}

}  // namespace

TEST(MsaaSamples, BothRenderersAgreeOnEverySampleWhereSampleZeroIsEmpty) {
  const crosscheck::Frame f = renderAgreeing("msaa_samples", {});
  ASSERT_EQ(f.samples, kSamples);
  ASSERT_EQ(f.sampleRgba.size(), std::size_t{4} * f.width * f.height * kSamples);
  ASSERT_EQ(f.sampleDepthStorage.size(), std::size_t{f.width} * f.height * kSamples);
  ASSERT_EQ(f.sampleStencil.size(), std::size_t{f.width} * f.height * kSamples);
  // Row 8 (the rectangle's top edge at y = 8.2): samples 1, 2, 3 (y + 0.375, 0.625, 0.875) drawn,
  // sample 0 (y + 0.125) not: sample 0 and its resolve of depth and stencil say "clear".
  for (std::uint32_t x = 12; x < 50; ++x) {
    EXPECT_FALSE(reached(f, x, 8, 0)) << x;
    for (std::uint32_t s = 1; s < 4; ++s) EXPECT_TRUE(reached(f, x, 8, s)) << x << " sample " << s;
    EXPECT_EQ(int{f.sampleStencil[sampleAt(f, x, 8, 0)]}, 0);
    EXPECT_EQ(int{f.sampleStencil[sampleAt(f, x, 8, 2)]}, 1);
    EXPECT_EQ(int{f.stencil[std::size_t{8} * f.width + x]}, 0);  // the resolve: sample 0
  }
  // Column 10 (the left edge at x = 10.4): samples 1 and 3 (x + 0.875, 0.625) drawn, 0 and 2 not.
  for (std::uint32_t y = 10; y < 25; ++y) {
    EXPECT_FALSE(reached(f, 10, y, 0)) << y;
    EXPECT_TRUE(reached(f, 10, y, 1)) << y;
    EXPECT_FALSE(reached(f, 10, y, 2)) << y;
    EXPECT_TRUE(reached(f, 10, y, 3)) << y;
  }
}

TEST(MsaaSamples, ADifferenceInOneSampleOtherThanZeroIsCaught) {
  auto scene = crosscheck::loadScene(kScenes / "msaa_samples.json", {});
  ASSERT_TRUE(scene) << scene.error();
  vkref::DeviceOptions device;
  device.validation = true;
  auto vulkan = crosscheck::openVulkan(device);
  ASSERT_TRUE(vulkan) << vulkan.error();
  auto reference = crosscheck::renderVulkan(*scene, **vulkan);
  ASSERT_TRUE(reference) << reference.error();
  auto soft = crosscheck::renderSoftraster(*scene);
  ASSERT_TRUE(soft) << soft.error();
  const crosscheck::Comparison same = crosscheck::compareFrames(*soft, *reference, *scene);
  EXPECT_EQ(same.samples, kSamples);
  EXPECT_TRUE(same.passed());

  const std::size_t k = sampleAt(*soft, 30, 8, 2);  // row 8: sample 0 is clear, sample 2 is drawn
  {
    crosscheck::Frame f = *soft;
    f.sampleRgba[4 * k + 1] ^= 0x40;  // 64 steps of green in sample 2; the resolve is left alone
    const crosscheck::Comparison c = crosscheck::compareFrames(f, *reference, *scene);
    EXPECT_EQ(c.colourMaxDelta[1], 64);
    EXPECT_EQ(c.resolvedColourMaxDelta[1], 0);
    EXPECT_EQ(c.colourPixelsOver, 1u);
    EXPECT_FALSE(c.passed());
  }
  {
    crosscheck::Frame f = *soft;
    f.sampleDepthStorage[k] = std::bit_cast<std::uint32_t>(std::bit_cast<float>(f.sampleDepthStorage[k]) + 0.125f);
    const crosscheck::Comparison c = crosscheck::compareFrames(f, *reference, *scene);
    EXPECT_EQ(c.depthMaxDelta, 0.125);
    EXPECT_EQ(c.depthPixelsOver, 1u);
    EXPECT_FALSE(c.passed());
  }
  {
    crosscheck::Frame f = *soft;
    f.sampleStencil[k] = 7;
    const crosscheck::Comparison c = crosscheck::compareFrames(f, *reference, *scene);
    EXPECT_EQ(c.stencilMismatches, 1u);
    EXPECT_FALSE(c.passed());
  }
  {
    crosscheck::Frame f = *soft;  // sample 2 back to the clear values: covered in one frame only
    const crosscheck::Frame& clear = *soft;
    const std::size_t empty = sampleAt(clear, 30, 8, 0);
    for (int ch = 0; ch < 4; ++ch) f.sampleRgba[4 * k + ch] = clear.sampleRgba[4 * empty + ch];
    f.sampleDepthStorage[k] = clear.sampleDepthStorage[empty];
    f.sampleStencil[k] = clear.sampleStencil[empty];
    const crosscheck::Comparison c = crosscheck::compareFrames(f, *reference, *scene);
    EXPECT_EQ(c.coverageMismatches, 1u);
    EXPECT_FALSE(c.passed());
  }
  {
    crosscheck::Frame f = *soft;  // a frame with one sample against one with four
    f.samples = 1;
    f.sampleRgba.clear();
    f.sampleDepthStorage.clear();
    f.sampleStencil.clear();
    const crosscheck::Comparison c = crosscheck::compareFrames(f, *reference, *scene);
    EXPECT_FALSE(c.passed());
  }
  for (const std::string& m : (*vulkan)->validationMessages()) ADD_FAILURE() << "validation: " << m;
}

// The same scene in every depth format: UNORM depth read back per sample from its sampled float
// (vkref/src/samples.hpp) agrees with softraster's stored values, stencil where there is one.
TEST(MsaaSamples, EveryDepthFormatAgreesOnEverySample) {
  for (const char* format : {"d16_unorm", "x8_d24_unorm", "d32_sfloat", "d24_unorm_s8_uint", "d32_sfloat_s8_uint"}) {
    SCOPED_TRACE(format);
    std::vector<std::string> overrides = {std::string("framebuffer.depth_format=") + format};
    if (!std::string(format).ends_with("_s8_uint")) {  // no stencil aspect: the draws' stencil off
      overrides.push_back("draws.0.stencil.enable=false");
      overrides.push_back("draws.1.stencil.enable=false");
    }
    const crosscheck::Frame f = renderAgreeing("msaa_samples", overrides);
    EXPECT_EQ(f.samples, kSamples);
    EXPECT_EQ(f.sampleDepthStorage.size(), std::size_t{f.width} * f.height * kSamples);
  }
}
