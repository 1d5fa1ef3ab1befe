// The lit scenes' parameters, cross-checked: the light moved and the time changed with --set
// style overrides (loadScene's), both renderers compared to the bit, and the override shown to
// change the image (so agreement is not two renderers ignoring it). Also the lavapipe built-ins
// the twins call (shaders/lavapipe_builtins.hpp) against libm, to their polynomials' accuracy.
#include "compare/compare.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <lavapipe_builtins.hpp>
#include <softraster/detail/fast/batch.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kScenes = SCENES_DIR;

struct Rendered {
  crosscheck::Frame soft, vulkan;
};

// softraster and lavapipe (validation on, any message fails) agree to the bit on the scene.
Rendered renderAgreeing(const std::string& name, const std::vector<std::string>& overrides) {
  Rendered r;
  auto scene = crosscheck::loadScene(kScenes / (name + ".json"), overrides);
  EXPECT_TRUE(scene) << scene.error();
  if (!scene) return r;
  vkref::DeviceOptions device;
  device.validation = true;
  auto vulkan = crosscheck::openVulkan(device);
  EXPECT_TRUE(vulkan) << vulkan.error();
  if (!vulkan) return r;
  auto soft = crosscheck::renderSoftraster(*scene, {});
  auto reference = crosscheck::renderVulkan(*scene, **vulkan);
  EXPECT_TRUE(soft && reference);
  if (!soft || !reference) return r;
  for (const std::string& m : (*vulkan)->validationMessages()) ADD_FAILURE() << "validation: " << m;
  const crosscheck::Comparison c = crosscheck::compareFrames(*soft, *reference, *scene);
  EXPECT_EQ(c.coverageMismatches, 0u);
  for (int ch = 0; ch < 4; ++ch) EXPECT_EQ(c.colourMaxDelta[ch], 0) << "channel " << ch;
  r.soft = std::move(*soft);
  r.vulkan = std::move(*reference);
  return r;
}

std::size_t pixelsDiffering(const crosscheck::Frame& a, const crosscheck::Frame& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i + 3 < a.rgba.size() && i + 3 < b.rgba.size(); i += 4) {
    n += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
  }
  return n;
}

TEST(Lighting, LightMovedWithSetMatchesAndChangesTheImage) {
  const Rendered still = renderAgreeing("light_room_pixel", {});
  const Rendered moved = renderAgreeing("light_room_pixel", {"light.position=[0.6,0.3,-0.2]", "light.power=[6,10,18]"});
  EXPECT_GT(pixelsDiffering(still.soft, moved.soft), 10000u) << "moving the light should relight most of the room";
}

TEST(Lighting, TimeTurnsTheModelAndMatches) {
  const Rendered early = renderAgreeing("blinn_phong_obj", {"time=0"});
  const Rendered late = renderAgreeing("blinn_phong_obj", {"time=2.25"});
  EXPECT_GT(pixelsDiffering(early.soft, late.soft), 1000u) << "time should turn the torus";
}

TEST(Lighting, UnknownLightFieldIsOneErrorLine) {
  auto scene = crosscheck::loadScene(kScenes / "light_room_pixel.json", {"light.brightness=3"});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("light_room_pixel.json: /light/brightness: unknown field"), std::string::npos)
      << scene.error();
  EXPECT_EQ(scene.error().find('\n'), std::string::npos);
}

TEST(Lighting, NormalsOnAnUnlitModelAreAnError) {
  auto scene = crosscheck::loadScene(kScenes / "light_room_pixel.json", {"draws.0.shading=vertex_color",
                                                                        "draws.0.normals=smooth"});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("/draws/0/normals: shading 'vertex_color' reads no normals"), std::string::npos)
      << scene.error();
}

TEST(Lighting, FileNormalsNeedAMeshWithVn) {
  auto scene = crosscheck::loadScene(kScenes / "light_room_pixel.json", {"draws.0.normals=file"});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("/draws/0/normals: 'file': the mesh has no normals of its own"), std::string::npos)
      << scene.error();
}

// gallivm's pow is a polynomial approximation: close to libm's (its own accuracy, ~1e-6
// relative over the range the lit models use), with lavapipe's edge cases.
TEST(LavapipeBuiltins, PowIsCloseToLibmWithLavapipesEdgeCases) {
  using shaders::glsl::pow;
  double worst = 0;
  for (float x = 0.001f; x <= 1.0f; x += 0.0137f) {
    for (float y : {1.0f, 2.5f, 8.0f, 32.0f, 60.0f}) {
      const double exact = std::pow(static_cast<double>(x), static_cast<double>(y));
      if (exact < 1e-30) continue;
      worst = std::max(worst, std::fabs(pow(x, y) - exact) / exact);
    }
  }
  EXPECT_LT(worst, 2e-5);
  EXPECT_EQ(pow(0.0f, 3.0f), 0.0f);
  EXPECT_EQ(pow(0.0f, 0.0f), 0.0f);                 // not 1: lavapipe selects 0 wherever x == 0
  EXPECT_EQ(pow(std::nanf(""), 2.0f), 0.0f);        // the unordered compare counts NaN as 0
  EXPECT_TRUE(std::isnan(pow(-2.0f, 2.0f)));        // log2 of a negative number is NaN
  EXPECT_EQ(pow(1e-30f, 60.0f), 0.0f);              // exp2 below -127 flushes to 0
  EXPECT_EQ(shaders::glsl::exp2(200.0f), INFINITY);
  EXPECT_EQ(shaders::glsl::log2Safe(0.0f), -INFINITY);
}

// The batch built-ins (on the fast path) give each lane the float version's bits, and the pair
// forms of pow and selectLessEqual each half's: over random bit patterns (NaN, infinities,
// negatives, denormals) and over the range the lit models use; exp2
// also over the clamp's edges and every integer step in between (x itself, not only log2's results). A batch is only evaluated on an AVX2 + FMA CPU, inside one
// flattened AVX2 function as the fast path does it (simd.hpp): without flatten, an optimizer that
// leaves a batch function out of line (-O1 with AddressSanitizer does) compiles it without AVX
// and passes its vectors by another ABI, which gave 286 867 wrong lanes there.
[[gnu::target("avx2,fma"), gnu::flatten]] int batchMismatches() {
  using softraster::FloatBatch;
  std::mt19937 random(2026);
  int mismatches = 0;
  const auto differ = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) != 0 && !(std::isnan(a) && std::isnan(b)); };
  for (int round = 0; round < 50000; ++round) {
    alignas(32) float x[softraster::kBatchLanes], y[softraster::kBatchLanes];
    for (int k = 0; k < softraster::kBatchLanes; ++k) {
      const std::uint32_t bits = random();
      std::memcpy(&x[k], &bits, sizeof bits);
      if (round % 2) x[k] = std::ldexp(static_cast<float>(random() % 100000) / 100000.0f, -static_cast<int>(random() % 20));
      y[k] = static_cast<float>(random() % 2000) / 10.0f;
    }
    x[3] = 0.0f;
    x[5] = static_cast<float>(random() % 280001) / 1000.0f - 140.0f;  // exp2's clamps and integer steps
    const FloatBatch bx = FloatBatch::load(x), by = FloatBatch::load(y);
    const FloatBatch p = shaders::glsl::pow(bx, by), s = softraster::sqrt(bx);
    const FloatBatch e = shaders::glsl::exp2(bx), l = shaders::glsl::log2Safe(bx);
    const FloatBatch sel = shaders::glsl::selectLessEqual(bx, by, FloatBatch(1.0f), FloatBatch(0.0f));
    // The pair forms: the same batches as the low half, and swapped as the high half.
    const softraster::FloatBatchPair px(bx, by), py(by, bx);
    const softraster::FloatBatchPair pp = shaders::glsl::pow(px, py);
    const softraster::FloatBatchPair psel = shaders::glsl::selectLessEqual(px, py, softraster::FloatBatchPair(1.0f), softraster::FloatBatchPair(0.0f));
    for (int k = 0; k < softraster::kBatchLanes; ++k) {
      mismatches += differ(p[k], shaders::glsl::pow(x[k], y[k]));
      mismatches += differ(s[k], shaders::glsl::sqrt(x[k]));
      mismatches += differ(e[k], shaders::glsl::exp2(x[k]));
      mismatches += differ(l[k], shaders::glsl::log2Safe(x[k]));
      mismatches += differ(sel[k], shaders::glsl::selectLessEqual(x[k], y[k], 1.0f, 0.0f));
      mismatches += differ(pp.low[k], p[k]) + differ(pp.high[k], shaders::glsl::pow(y[k], x[k]));
      mismatches += differ(psel.low[k], sel[k]) + differ(psel.high[k], shaders::glsl::selectLessEqual(y[k], x[k], 1.0f, 0.0f));
    }
  }
  return mismatches;
}

// The 16-lane forms (the fast path's AVX-512 block pairs) give each lane the float version's
// bits, and pow's FloatBatch16Pair form each half's, over the same kinds of input; compiled as
// the fast path's wide functions are.
[[SOFTRASTER_WIDE_TARGET, gnu::flatten, gnu::noinline]] int wideMismatches() {
  using softraster::FloatBatch16;
  constexpr int kLanes = 2 * softraster::kBatchLanes;
  std::mt19937 random(2027);
  int mismatches = 0;
  const auto differ = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) != 0 && !(std::isnan(a) && std::isnan(b)); };
  for (int round = 0; round < 25000; ++round) {
    alignas(64) float x[kLanes], y[kLanes];
    for (int k = 0; k < kLanes; ++k) {
      const std::uint32_t bits = random();
      std::memcpy(&x[k], &bits, sizeof bits);
      if (round % 2) x[k] = std::ldexp(static_cast<float>(random() % 100000) / 100000.0f, -static_cast<int>(random() % 20));
      y[k] = static_cast<float>(random() % 2000) / 10.0f;
    }
    x[3] = 0.0f;
    x[12] = -0.0f;
    x[13] = std::numeric_limits<float>::infinity();
    x[5] = static_cast<float>(random() % 280001) / 1000.0f - 140.0f;  // exp2's clamps and integer steps
    x[14] = static_cast<float>(random() % 280001) / 1000.0f - 140.0f;
    const FloatBatch16 bx = FloatBatch16::load(x), by = FloatBatch16::load(y);
    const FloatBatch16 p = shaders::glsl::pow(bx, by), e = shaders::glsl::exp2(bx), l = shaders::glsl::log2Safe(bx);
    // Two pairs at once (FloatBatch16Pair): the batches as the low half, swapped as the high half.
    const softraster::FloatBatch16Pair pp = shaders::glsl::pow(softraster::FloatBatch16Pair(bx, by), softraster::FloatBatch16Pair(by, bx));
    for (int k = 0; k < kLanes; ++k) {
      mismatches += differ(p[k], shaders::glsl::pow(x[k], y[k]));
      mismatches += differ(e[k], shaders::glsl::exp2(x[k]));
      mismatches += differ(l[k], shaders::glsl::log2Safe(x[k]));
      mismatches += differ(pp.low[k], p[k]) + differ(pp.high[k], shaders::glsl::pow(y[k], x[k]));
    }
  }
  return mismatches;
}

TEST(LavapipeBuiltins, WideGivesTheFloatVersionsBits) {
  if (!softraster::detail::fast::cpuShadesWidePairs()) GTEST_SKIP() << "no AVX-512 F, VL, BW and DQ";
  EXPECT_EQ(wideMismatches(), 0);
}

TEST(LavapipeBuiltins, BatchGivesTheFloatVersionsBits) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) GTEST_SKIP() << "no AVX2 + FMA";
  EXPECT_EQ(batchMismatches(), 0);
}

}  // namespace
