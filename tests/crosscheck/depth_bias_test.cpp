// Depth bias with polygon modes line and point (Mesa's offset stage, softraster's
// geometry/polygon_offset.hpp), cross-checked: both renderers to the bit (the fast and the scalar
// exact paths) under the validation layer in every depth format, with the bias shown to matter
// (the same scene without it draws a different picture).
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using agreement::pixelsDiffering;
using agreement::renderAgreeing;

TEST(DepthBias, PolygonModesLineAndPointInEveryDepthFormat) {
  for (const char* format : {"\"d32_sfloat\"", "\"d16_unorm\"", "\"x8_d24_unorm\"", "\"d24_unorm_s8_uint\"",
                             "\"d32_sfloat_s8_uint\""}) {
    SCOPED_TRACE(format);
    const std::string set = std::string("framebuffer.depth_format=") + format;
    const crosscheck::Frame biased = renderAgreeing("depth_bias_polygon_modes", {set});
    // The bias decides which edges pass against the filled copies: without it the picture changes.
    std::vector<std::string> unbiased = {set};
    for (int d = 4; d < 12; ++d) unbiased.push_back("draws." + std::to_string(d) + ".depth_bias={\"constant\": 0}");
    const crosscheck::Frame plain = renderAgreeing("depth_bias_polygon_modes", unbiased);
    EXPECT_GT(pixelsDiffering(biased, plain), 100u);
  }
}
