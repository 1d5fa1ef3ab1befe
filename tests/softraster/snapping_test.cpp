// Snapping to 1/256 px: round half to even after subtracting the pixel-centre offset in float.
#include <softraster/detail/exact/triangle_setup.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using softraster::detail::snapToSubpixel;

TEST(Snapping, PixelCentresMapToMultiplesOf256) {
  EXPECT_EQ(snapToSubpixel(0.5f), 0);
  EXPECT_EQ(snapToSubpixel(1.5f), 256);
  EXPECT_EQ(snapToSubpixel(10.5f), 2560);
  EXPECT_EQ(snapToSubpixel(0.0f), -128);
  EXPECT_EQ(snapToSubpixel(-3.5f), -1024);
}

TEST(Snapping, HalfwayRoundsToEven) {
  // (x - 0.5) * 256 = k + 0.5 exactly: ties go to the even neighbour, in both directions.
  EXPECT_EQ(snapToSubpixel(0.5f + 0.5f / 256), 0);
  EXPECT_EQ(snapToSubpixel(0.5f + 1.5f / 256), 2);
  EXPECT_EQ(snapToSubpixel(0.5f + 2.5f / 256), 2);
  EXPECT_EQ(snapToSubpixel(0.5f - 0.5f / 256), 0);
  EXPECT_EQ(snapToSubpixel(0.5f - 1.5f / 256), -2);
  // Just off the tie rounds to nearest.
  EXPECT_EQ(snapToSubpixel(std::nextafter(0.5f + 0.5f / 256, 1.0f)), 1);
}

TEST(Snapping, SubtractionHappensInFloat) {
  // 1e6 + 0.3 is not representable: the float subtraction rounds before scaling.
  const float x = 1000000.3f;  // stored as 1000000.3125
  EXPECT_EQ(snapToSubpixel(x), static_cast<int>(std::nearbyint((x - 0.5f) * 256.0f)));
  EXPECT_EQ(snapToSubpixel(x), 255999952);
}

TEST(Snapping, OutOfRangeAndNaNGiveIntMin) {
  EXPECT_EQ(snapToSubpixel(std::numeric_limits<float>::quiet_NaN()), INT32_MIN);
  EXPECT_EQ(snapToSubpixel(std::numeric_limits<float>::infinity()), INT32_MIN);
  EXPECT_EQ(snapToSubpixel(1e8f), INT32_MIN);
  EXPECT_EQ(snapToSubpixel(-1e8f), INT32_MIN);
}

#include <softraster/detail/fragment/colour.hpp>

TEST(ColourStore, Unorm8RoundsHalfToEvenAfterScaling) {
  using softraster::detail::unorm8FromFloat;
  EXPECT_EQ(unorm8FromFloat(0.0f), 0);
  EXPECT_EQ(unorm8FromFloat(1.0f), 255);
  EXPECT_EQ(unorm8FromFloat(-3.0f), 0);
  EXPECT_EQ(unorm8FromFloat(7.0f), 255);
  EXPECT_EQ(unorm8FromFloat(std::numeric_limits<float>::quiet_NaN()), 0);
  // Every float in [0, 1] against the library's round-half-even of the same product.
  for (float v = 0.0f; v <= 1.0f; v = std::nextafter(v, 2.0f)) {
    ASSERT_EQ(unorm8FromFloat(v), static_cast<int>(std::nearbyint(v * 255.0f))) << v;
    if (v > 1e-3f) v = std::nextafter(v + 1e-5f, 2.0f);  // denser near 0, sampled above
  }
  // Exact ties after scaling: 0.5/255 * 255 etc. land on .5 only where representable; check k + 0.5.
  for (int k = 0; k < 255; ++k) {
    const float tie = (static_cast<float>(k) + 0.5f) / 255.0f;
    EXPECT_EQ(unorm8FromFloat(tie), static_cast<int>(std::nearbyint(tie * 255.0f))) << k;
  }
}
