// The stencil scenes, cross-checked: both renderers to the bit (the fast and the scalar exact
// paths) under the validation layer, stencil included, with what each scene is about shown to be
// there: every op on every path gives the value the Vulkan specification says (an independent
// table here, not softraster's code), the front and back states both reach the image, lines and
// points of unfilled polygons take the front state (lavapipe's rule), the mask pass masks. Then
// the loader's errors for stencil and the depth bounds test.
#include "agreement.hpp"

#include <softraster/formats.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace {

using agreement::expectSceneError;
using agreement::pixelsDiffering;
using agreement::renderAgreeing;

std::uint8_t stencilAt(const crosscheck::Frame& f, std::uint32_t x, std::uint32_t y) {
  return f.stencil.at(static_cast<std::size_t>(y) * f.width + x);
}

std::size_t count(const crosscheck::Frame& f, std::uint8_t value) {
  std::size_t n = 0;
  for (std::uint8_t s : f.stencil) n += s == value;
  return n;
}

// VkStencilOp on stored value s with reference r, as the specification's table defines it.
std::uint8_t specOp(int op, std::uint8_t s, std::uint8_t r) {
  switch (op) {
    case 0: return s;                                   // KEEP
    case 1: return 0;                                   // ZERO
    case 2: return r;                                   // REPLACE
    case 3: return s == 255 ? 255 : s + 1;              // INCREMENT_AND_CLAMP
    case 4: return s == 0 ? 0 : s - 1;                  // DECREMENT_AND_CLAMP
    case 5: return static_cast<std::uint8_t>(~s);       // INVERT
    case 6: return static_cast<std::uint8_t>(s + 1);    // INCREMENT_AND_WRAP
    default: return static_cast<std::uint8_t>(s - 1);   // DECREMENT_AND_WRAP
  }
}

}  // namespace

TEST(Stencil, EveryOpOnEveryPathIsTheSpecificationsValue) {
  const crosscheck::Frame f = renderAgreeing("stencil_ops", {});
  ASSERT_EQ(f.stencil.size(), std::size_t{256} * 288);
  const std::array<std::uint8_t, 3> initial = {0, 0x5a, 255};
  for (int path = 0; path < 3; ++path) {
    for (int k = 0; k < 3; ++k) {
      for (int op = 0; op < 8; ++op) {
        const std::uint32_t x = static_cast<std::uint32_t>(op) * 32 + 16, y = static_cast<std::uint32_t>(3 * path + k) * 32 + 16;
        EXPECT_EQ(int{stencilAt(f, x, y)}, int{specOp(op, initial[static_cast<std::size_t>(k)], 0x3c)})
            << "path " << path << ", initial " << int{initial[static_cast<std::size_t>(k)]} << ", op " << op;
      }
    }
  }
}

TEST(Stencil, CompareOpsCompareTheReferenceWithTheStoredValue) {
  const crosscheck::Frame f = renderAgreeing("stencil_compare", {});
  // Rows: reference 0x40, 0x80, 0xc0 against the stored 0x80; columns: Vulkan's compare ops.
  const bool passes[8][3] = {{false, false, false}, {true, false, false}, {false, true, false}, {true, true, false},
                             {false, false, true},  {true, false, true},  {false, true, true},  {true, true, true}};
  for (int op = 0; op < 8; ++op) {
    for (int r = 0; r < 3; ++r) {
      const std::uint8_t expected = passes[op][r] ? 0x81 : 0x7f;  // incremented, or inverted
      EXPECT_EQ(int{stencilAt(f, static_cast<std::uint32_t>(op) * 32 + 16, static_cast<std::uint32_t>(r) * 32 + 16)},
                int{expected})
          << "compare op " << op << ", row " << r;
    }
  }
}

TEST(Stencil, FrontAndBackStatesBothReachTheImage) {
  const crosscheck::Frame f = renderAgreeing("stencil_front_back", {});
  // First pass: front writes 1 through mask 0x0f (0x40 -> 0x41), back 0xe2 through 0xf3 (0x40 -> 0xe2).
  std::set<std::uint8_t> values(f.stencil.begin(), f.stencil.end());
  EXPECT_GE(values.size(), 5u) << "initial, both faces' first pass and both faces' second pass";
  EXPECT_GT(count(f, 0x41) + count(f, 0x42), 500u) << "front faces";
  EXPECT_GT(count(f, 0xe2) + count(f, 0xe1), 500u) << "back faces";
}

TEST(Stencil, MasksKeepTheUnwrittenBits) {
  const crosscheck::Frame f = renderAgreeing("stencil_masks", {});
  // Column 1: compare mask 0x0f, equal 0x0a, write mask 0xf0, pass invert, fail replace.
  // Row 1 holds 0x5a: 0x5a & 0x0f == 0x0a passes; invert through 0xf0 gives 0xaa.
  EXPECT_EQ(int{stencilAt(f, 48, 48)}, 0xaa);
  // Row 0 holds 0x00: fails; replace 0x0a through 0xf0 keeps 0x00.
  EXPECT_EQ(int{stencilAt(f, 48, 16)}, 0x00);
  // Column 7: write mask 0 writes nothing.
  const std::array<int, 4> initial = {0x00, 0x5a, 0xa5, 0xff};
  for (std::uint32_t row = 0; row < 4; ++row) EXPECT_EQ(int{stencilAt(f, 7 * 32 + 16, row * 32 + 16)}, initial[row]);
}

TEST(Stencil, D32SfloatS8UintCountsDepthFailures) {
  const crosscheck::Frame f = renderAgreeing("stencil_d32s8", {});
  EXPECT_EQ(f.depthFormat, softraster::DepthFormat::D32SfloatS8Uint);
  std::set<std::uint8_t> values(f.stencil.begin(), f.stencil.end());
  EXPECT_GE(values.size(), 5u);
  EXPECT_GT(count(f, 7), 1000u) << "the stencil clear value where nothing was drawn";
}

TEST(Stencil, TheMaskPassDrawsOnlyInsideTheStar) {
  const crosscheck::Frame masked = renderAgreeing("stencil_mask_two_pass", {});
  // The star's centre: 1 from the star, 2 after the textured quad's pass; a corner: 0, then 1 from
  // the last pass; the textured quad outside the star failed and inverted 0 to 255; nothing is 0.
  EXPECT_EQ(int{stencilAt(masked, 128, 128)}, 2);
  EXPECT_EQ(int{stencilAt(masked, 2, 2)}, 1);
  EXPECT_GT(count(masked, 255), 1000u);
  EXPECT_EQ(count(masked, 0), 0u);
  // Drawing the first colour pass where the stencil is not 1 instead changes the picture.
  const crosscheck::Frame inverted = renderAgreeing("stencil_mask_two_pass", {"draws.1.stencil.compare_op=\"not_equal\""});
  EXPECT_GT(pixelsDiffering(masked, inverted), 5000u);
}

TEST(Stencil, MsaaStencilPerSample) {
  const crosscheck::Frame f = renderAgreeing("stencil_msaa", {});
  std::set<std::uint8_t> values(f.stencil.begin(), f.stencil.end());
  EXPECT_GE(values.size(), 4u);
}

// lavapipe deviates from the specification here: Vulkan's stencil test uses "the back stencil
// state when processing fragments generated by back-facing polygons" whatever the polygon mode,
// but the lines and points of lavapipe's unfilled polygons are front-facing (Mesa's draw module
// injects the facing only when the fragment shader reads gl_FrontFacing). Both renderers agree,
// and no pixel takes the back state's value.
TEST(Stencil, LinesAndPointsOfUnfilledPolygonsTakeTheFrontState) {
  const crosscheck::Frame f = renderAgreeing("stencil_polygon_modes", {});
  EXPECT_GT(count(f, 0x11), 300u);
  EXPECT_EQ(count(f, 0x22), 0u) << "lavapipe gives back-facing unfilled polygons' edges the front state";
  // The same triangles filled: one winding of each pair is back-facing and takes the back state.
  std::vector<std::string> filled;
  for (int d = 0; d < 4; ++d) filled.push_back("draws." + std::to_string(d) + ".polygon_mode=\"fill\"");
  const crosscheck::Frame fill = renderAgreeing("stencil_polygon_modes", filled);
  EXPECT_GT(count(fill, 0x22), 1000u);
  EXPECT_GT(count(fill, 0x11), 1000u);
}

// The same scene with softraster following the spec (Deviations::Spec): the edges and corners of
// the back-facing unfilled polygons take the back state (0x22) where lavapipe writes 0x11, on the
// fast and the scalar path alike, and nothing else changes (the line and point lists stay front).
TEST(Stencil, SpecModeGivesUnfilledBackFacingPolygonsTheBackState) {
  const crosscheck::Frame driver = renderAgreeing("stencil_polygon_modes", {});
  const std::vector<crosscheck::Frame> specFrames = agreement::renderInSpecMode("stencil_polygon_modes");
  ASSERT_EQ(specFrames.size(), 2u);
  for (const crosscheck::Frame& spec : specFrames) {
    ASSERT_EQ(spec.stencil.size(), driver.stencil.size());
    std::size_t changed = 0;
    for (std::size_t i = 0; i < driver.stencil.size(); ++i) {
      if (spec.stencil[i] == driver.stencil[i]) continue;
      ++changed;
      EXPECT_EQ(driver.stencil[i], 0x11) << "pixel " << i;
      EXPECT_EQ(spec.stencil[i], 0x22) << "pixel " << i;
    }
    EXPECT_GT(changed, 100u);
    EXPECT_EQ(count(spec, 0x22), changed);
    EXPECT_GT(count(spec, 0x11), 300u) << "the front-facing polygons' and the lists' lines and points";
    EXPECT_NE(spec.rgba, driver.rgba) << "the scene shows its stencil values as colour";
  }
}

TEST(Stencil, SceneErrorsNameTheFileAndTheRule) {
  const std::string s = "stencil_ops.json";
  expectSceneError({"framebuffer.depth_format=\"d32_sfloat\""}, s,
                   "/draws/0/stencil: needs a framebuffer depth_format with stencil");
  expectSceneError({"framebuffer.depth_format=\"d32_sfloat\"", "framebuffer.clear_stencil=3"}, s,
                   "/framebuffer/clear_stencil: needs a depth_format with stencil");
  expectSceneError({"framebuffer.clear_stencil=256"}, s, "/framebuffer/clear_stencil: 256 is more than 255");
  expectSceneError({"draws.0.stencil.pass_op=\"increment\""}, s, "/draws/0/stencil/pass_op: 'increment' is not one of");
  expectSceneError({"draws.0.stencil.compare_op=\"lesser\""}, s, "/draws/0/stencil/compare_op: 'lesser' is not one of");
  expectSceneError({"draws.0.stencil.reference=256"}, s, "/draws/0/stencil/reference: 256 is more than 255");
  expectSceneError({"draws.0.stencil.front={\"write_mask\": -1}"}, s, "/draws/0/stencil/front/write_mask");
  expectSceneError({"draws.0.stencil.sideways={}"}, s, "/draws/0/stencil/sideways: unknown field");
  expectSceneError({"draws.0.depth_bounds_test=true"}, s,
                   "/draws/0/depth_bounds_test: lavapipe does not offer the depthBounds feature, and Vulkan says \"If "
                   "the depthBounds feature is not enabled, depthBoundsTestEnable must be VK_FALSE\" "
                   "(VUID-VkPipelineDepthStencilStateCreateInfo-depthBoundsTestEnable-00598)");
  // false is Vulkan's default and allowed.
  EXPECT_TRUE(crosscheck::loadScene(agreement::kScenes / s, {"draws.0.depth_bounds_test=false"}));
}
