// The shadow-map scenes' parameters, cross-checked: both renderers to the bit (the fast and the
// scalar exact paths) under the validation layer, with the shadows shown to be there (a bias that
// lights everything changes the image; the manual compare gives the comparison sampler's image to
// the bit; moving the light moves the shadows), and the depth view. Then the shadow inputs'
// errors, each one line naming the scene file and the place.
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using agreement::expectSceneError;
using agreement::pixelsDiffering;
using agreement::renderAgreeing;

TEST(ShadowMaps, TheRoomsShadowsMatchAndAreThere) {
  const crosscheck::Frame shadowed = renderAgreeing("shadow_room", {});
  // A bias of 1 puts every reference in front of the map: nothing is in shadow.
  const crosscheck::Frame lit = renderAgreeing("shadow_room", {"draws.0.shadow_map.bias=1"});
  const std::size_t shadowPixels = pixelsDiffering(shadowed, lit);
  EXPECT_GT(shadowPixels, 3000u) << "the blocks should cast shadows";
  EXPECT_LT(shadowPixels, 320u * 240u / 2) << "most of the room is lit";
}

TEST(ShadowMaps, TheManualCompareIsTheComparisonSamplersImage) {
  const crosscheck::Frame sampler = renderAgreeing("shadow_room", {});
  const crosscheck::Frame manual = renderAgreeing("shadow_room_manual", {});
  EXPECT_EQ(pixelsDiffering(sampler, manual), 0u) << "less_or_equal in the sampler is reference <= depth in the shader";
  EXPECT_EQ(sampler.rgba, manual.rgba);
}

TEST(ShadowMaps, MovingTheLightMovesTheShadows) {
  const crosscheck::Frame here = renderAgreeing("shadow_room", {});
  const std::vector<std::string> moved{"light.position=[0.4,-0.9,-0.2]", "passes.0.camera.eye=[0.4,-0.9,-0.2]",
                                       "passes.0.camera.target=[-0.1,1.0,0.4]"};
  const crosscheck::Frame there = renderAgreeing("shadow_room", moved);
  EXPECT_GT(pixelsDiffering(here, there), 5000u);
}

TEST(ShadowMaps, ComparisonOpsAndTheBorderMatch) {
  const crosscheck::Frame border = renderAgreeing("shadow_border", {});
  for (const char* op : {"never", "always", "greater", "equal", "not_equal", "greater_or_equal"}) {
    SCOPED_TRACE(op);
    const crosscheck::Frame other = renderAgreeing("shadow_border", {std::string("draws.0.shadow_map.compare=") + op});
    EXPECT_GT(pixelsDiffering(border, other), 1000u);
  }
  for (const char* mode : {"clamp_to_edge", "repeat", "mirrored_repeat"}) {
    SCOPED_TRACE(mode);
    renderAgreeing("shadow_border", {std::string("draws.0.shadow_map.address_mode=") + mode});
  }
  renderAgreeing("shadow_border", {"draws.0.shadow_map.border_colour=opaque_white"});
}

TEST(ShadowMaps, APassWithDepthBiasAndItsOwnSizeMatches) {
  renderAgreeing("shadow_room", {"passes.0.depth_bias={\"constant\":2,\"slope\":1.5}", "passes.0.width=200",
                                 "passes.0.height=130", "passes.0.cull=none", "draws.0.shadow_map.bias=0"});
}

TEST(ShadowMaps, TheDepthViewIsNearOverZ) {
  const crosscheck::Frame near = renderAgreeing("depth_view_room", {});
  const crosscheck::Frame far = renderAgreeing("depth_view_room", {"camera.near=0.25"});
  // Halving the near plane halves every grey: the view is near / z, not a fixed remap.
  std::size_t compared = 0;
  for (std::size_t i = 0; i + 3 < near.rgba.size(); i += 4) {
    if (near.rgba[i] < 40 || near.rgba[i] > 250) continue;
    ++compared;
    EXPECT_NEAR(far.rgba[i], near.rgba[i] / 2.0, 1.0) << "pixel " << i / 4;
  }
  EXPECT_GT(compared, 20000u);
}

TEST(ShadowMaps, BadShadowInputsAreOneErrorLine) {
  const std::string s = "shadow_room.json";
  expectSceneError({"draws.0.shadow_map.pass=sun"}, s, "/draws/0/shadow_map/pass: no depth pass is called 'sun' (passes: light)");
  expectSceneError({"draws.0.shadow_map.compare=lesser"}, s, "/draws/0/shadow_map/compare: 'lesser' is not one of");
  expectSceneError({"draws.0.shadow_map.filter=linear"}, s, "/draws/0/shadow_map/filter: unknown field");
  expectSceneError({"draws.0.shadow_map.bias=1e39"}, s, "/draws/0/shadow_map/bias");
  expectSceneError({"draws.0.shadow_map=\"light\""}, s, "/draws/0/shadow_map: expected an object");
  expectSceneError({"draws.0.shading=blinn_phong_pixel"}, s, "shading 'blinn_phong_pixel' samples no shadow map");
  expectSceneError({"draws.0.shading=blinn_phong_shadowed_manual", "draws.0.shadow_map.compare=less"}, s,
                   "/draws/0/shadow_map/compare: this model compares in its shader");
  expectSceneError({"draws.0.shading=depth_only"}, s, "/draws/0/shading: 'depth_only' writes no colour");
  expectSceneError({"passes.0.name=sun"}, s, "no depth pass is called 'light' (passes: sun)");
  expectSceneError({"passes=[]"}, s, "no depth pass is called 'light' (the scene has no \"passes\")");
  expectSceneError({"passes=[]"}, "light_room_pixel.json", "/passes: expected a non-empty array");
  expectSceneError({"passes=[{\"name\":\"light\",\"camera\":{\"type\":\"look_at\"}},"
                    "{\"name\":\"light\",\"camera\":{\"type\":\"look_at\"}}]"},
                   s, "/passes/1/name: two passes are called 'light'");
  expectSceneError({"passes.0.draws=[\"teapot\"]"}, s, "/passes/0/draws/0: no draw is called 'teapot'");
  expectSceneError({"passes.0.width=0"}, s, "/passes/0: width and height must be in 1..8192");
  expectSceneError({"passes.0.camera.fov_y=-3"}, s, "/passes/0/camera");
  expectSceneError({"passes.0.blend={}"}, s, "/passes/0/blend: unknown field");
  expectSceneError({"passes.0.clear_depth=2"}, s, "/passes/0/clear_depth: must be in [0, 1]");
}

TEST(ShadowMaps, AShadowedModelNeedsAShadowMapAndAPass) {
  auto scene = crosscheck::loadScene(agreement::kScenes / "light_room_pixel.json", {"draws.0.shading=blinn_phong_shadowed"});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("samples a shadow map: give \"shadow_map\""), std::string::npos) << scene.error();
  scene = crosscheck::loadScene(agreement::kScenes / "light_room_pixel.json",
                                {"draws.0.shading=blinn_phong_shadowed", "draws.0.shadow_map={\"pass\":\"light\"}"});
  ASSERT_FALSE(scene);
  EXPECT_NE(scene.error().find("(the scene has no \"passes\")"), std::string::npos) << scene.error();
}

}  // namespace
