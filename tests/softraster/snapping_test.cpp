// Snapping to 1/256 px: round half to even after subtracting the pixel-centre offset in float.
#include <softraster/detail/exact/triangle_setup.hpp>

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>

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
  // Against the library's round-half-even of the same product: exhaustively where the result
  // changes (the 4096 floats around each of the 255 steps (k + 0.5) / 255), and every 97th float
  // of [0, 1] elsewhere (subnormals included). Visiting all 2^30 floats of [0, 1] took 35 s and
  // added nothing: between two steps the expected value is constant.
  const auto check = [&](float v) { ASSERT_EQ(unorm8FromFloat(v), static_cast<int>(std::nearbyint(v * 255.0f))) << v; };
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  for (int k = 0; k < 255; ++k) {
    const std::uint32_t step = bits((static_cast<float>(k) + 0.5f) / 255.0f);
    for (std::uint32_t b = step - 2048; b < step + 2048; ++b) check(std::bit_cast<float>(b));
  }
  for (std::uint32_t b = 0; b <= bits(1.0f); b += 97) check(std::bit_cast<float>(b));
  check(std::numeric_limits<float>::denorm_min());
  check(std::numeric_limits<float>::min());
  // Exact ties after scaling: 0.5/255 * 255 etc. land on .5 only where representable; check k + 0.5.
  for (int k = 0; k < 255; ++k) {
    const float tie = (static_cast<float>(k) + 0.5f) / 255.0f;
    EXPECT_EQ(unorm8FromFloat(tie), static_cast<int>(std::nearbyint(tie * 255.0f))) << k;
  }
}
