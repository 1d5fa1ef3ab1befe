// The one spelling of each metric (output/metric_text.hpp) and the limit lines built from counts
// (compare/metrics.hpp): PSNR, depth values, and counts too large for a double's six digits.
#include "compare/metrics.hpp"
#include "output/metric_text.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace crosscheck {
namespace {

TEST(MetricText, PsnrOfIdenticalImagesIsInfAndOthersHaveTwoDecimals) {
  EXPECT_EQ(psnrText(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(psnrText(48.126), "48.13");
  EXPECT_EQ(psnrText(0), "0.00");
}

TEST(MetricText, DepthIsSpelledAsTheSceneFilesSpellIt) {
  EXPECT_EQ(depthText(0x1p-24), "5.9604645e-08");  // the default threshold, as the scene files write it
  EXPECT_EQ(depthText(0x1p-16), "1.5258789e-05");
  EXPECT_EQ(depthText(0.75), "0.75");
  EXPECT_EQ(depthText(0), "0");
  EXPECT_EQ(depthText(1.0 / 3.0), "0.333333333");  // not a float: nine significant digits
  EXPECT_EQ(depthText(std::numeric_limits<double>::infinity()), "inf");
}

TEST(MetricText, LimitFailuresCarryWholeCounts) {
  Comparison c;
  c.colourPixelsOver = 12345678;
  c.coverageMismatches = 1;
  Tolerance t;
  t.maxColourPixelsOver = 1000000;
  const std::vector<std::string> failures = limitFailures(c, t);
  ASSERT_EQ(failures.size(), 2u);
  EXPECT_EQ(failures[0], "coverage_mismatches 1 > 0");
  EXPECT_EQ(failures[1], "colour_pixels_over 12345678 > 1000000");  // was "1.23457e+07 > 1e+06"
}

}  // namespace
}  // namespace crosscheck
