// The texture scenes' parameters, cross-checked: the normal-mapped quad under a moving light and
// the textured cube at other times (--set style overrides), both renderers compared to the bit
// under the validation layer, and the change shown in the image (so agreement is not both
// renderers ignoring the normal map or the time). Then the texture inputs' errors: a missing,
// corrupt or oversized PNG, a texture given to a model that samples none, a missing one, bad
// sampler fields, texture coordinates missing or of the wrong count — each one line naming the
// scene file and the place.
#include "agreement.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using agreement::kScenes;
using agreement::pixelsDiffering;
using agreement::renderAgreeing;

TEST(Textures, NormalMapUnderAMovingLightMatchesAndRelightsTheBumps) {
  const crosscheck::Frame left = renderAgreeing("texture_normal_map", {});
  const crosscheck::Frame right = renderAgreeing("texture_normal_map", {"light.position=[1.2,0.4,-1.0]"});
  const crosscheck::Frame below = renderAgreeing("texture_normal_map", {"light.position=[0,1.4,-0.6]"});
  EXPECT_GT(pixelsDiffering(left, right), 20000u) << "moving the light should relight the bumps";
  EXPECT_GT(pixelsDiffering(left, below), 20000u);
}

TEST(Textures, NormalMapChangesTheImage) {
  // The same quad with the flat normal map of a plain texture would shade smoothly; the bumps
  // must show: neighbouring pixels on the lit quad differ far more often than a smooth gradient.
  const crosscheck::Frame f = renderAgreeing("texture_normal_map", {});
  const crosscheck::Frame flat =
      renderAgreeing("texture_normal_map", {"draws.0.normal_map.file=textures/arrows_16.png"});
  EXPECT_GT(pixelsDiffering(f, flat), 20000u);
}

TEST(Textures, TimeTurnsTheTexturedCubeAndMatches) {
  const crosscheck::Frame early = renderAgreeing("texture_lit_obj", {"time=0"});
  const crosscheck::Frame late = renderAgreeing("texture_lit_obj", {"time=1.9"});
  EXPECT_GT(pixelsDiffering(early, late), 5000u) << "time should turn the cube";
}

void expectError(const std::vector<std::string>& overrides, const std::string& scene, const std::string& expected) {
  agreement::expectSceneError(overrides, scene, expected);
}

TEST(Textures, BadTextureInputsAreOneErrorLine) {
  const std::string s = "texture_magnify.json";
  expectError({"draws.0.texture.file=textures/missing.png"}, s, "/draws/0/texture/file: ");
  expectError({"draws.0.texture.file=textures/missing.png"}, s, "cannot open texture: file not found");
  expectError({"draws.0.texture.file=meshes/cornell_box.obj"}, s, "not a PNG image");
  expectError({"draws.0.texture.file=textures"}, s, "is a directory");
  expectError({"draws.0.texture.mag_filter=cubic"}, s, "/draws/0/texture/mag_filter: 'cubic' is not one of nearest, linear");
  expectError({"draws.0.texture.address_mode=wrap"}, s, "'wrap' is not one of repeat, mirrored_repeat");
  expectError({"draws.0.texture.format=float"}, s, "'float' is not one of unorm, srgb");
  expectError({"draws.0.texture.min_lod=3", "draws.0.texture.max_lod=2"}, s, "minLod must not exceed maxLod");
  expectError({"draws.0.texture.mip_lod_bias=20"}, s, "maxSamplerLodBias (16)");
  expectError({"draws.0.texture.wrap=1"}, s, "/draws/0/texture/wrap: unknown field");
  expectError({"draws.0.texture=\"textures/noise_8.png\""}, s, "/draws/0/texture: expected an object");
  expectError({"draws.0.texture.format=srgb", "draws.0.texture.mag_filter=linear"}, s,
              "different min and mag filters");
  expectError({"draws.0.shading=vertex_color"}, s, "shading 'vertex_color' reads no texture coordinates");
  expectError({"draws.0.texcoords=[[0,0]]"}, s, "expected one [u, v] per position (4)");
  expectError({"draws.0.texcoords.1=[0,1e39]"}, s, "finite");
  expectError({"draws.0.normal_map={\"file\":\"textures/bumps_64.png\"}"}, s, "samples no normal map");
  expectError({"draws.0.shading=blinn_phong_normal_mapped", "draws.0.normals=[[0,0,-1],[0,0,-1],[0,0,-1],[0,0,-1]]"},
              s, "samples a normal map: give \"normal_map\"");
}

TEST(Textures, AMissingTextureOrTexcoordsOnATexturedModelIsAnError) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "crosscheck_texture_test";
  std::filesystem::create_directories(dir);
  const std::filesystem::path scene = dir / "no_texture.json";
  std::ofstream(scene) << R"({"camera": {"type": "clip_space"},
    "draws": [{"shading": "textured", "positions": [[0,0,0],[1,0,0],[0,1,0]], "texcoords": [[0,0],[1,0],[0,1]]}]})";
  auto loaded = crosscheck::loadScene(scene);
  ASSERT_FALSE(loaded);
  EXPECT_NE(loaded.error().find("/draws/0: shading 'textured' samples a texture: give \"texture\""), std::string::npos)
      << loaded.error();
  const std::filesystem::path obj = dir / "no_vt.json";
  std::ofstream(obj) << R"({"draws": [{"shading": "textured", "obj": ")" << (kScenes / "meshes/cornell_box.obj").string()
                     << R"(", "texture": {"file": ")" << (kScenes / "textures/noise_8.png").string() << R"("}}]})";
  loaded = crosscheck::loadScene(obj);
  ASSERT_FALSE(loaded);
  EXPECT_NE(loaded.error().find("reads texture coordinates: give \"texcoords\" or an OBJ whose every face corner has a vt"),
            std::string::npos)
      << loaded.error();
  // A PNG whose data is cut short: stb_image's reason, in one line.
  const std::filesystem::path png = kScenes / "textures/checker_64.png";
  std::ifstream in(png, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir / "cut.png", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const std::filesystem::path cut = dir / "cut.json";
  std::ofstream(cut) << R"({"camera": {"type": "clip_space"}, "draws": [{"shading": "textured",
    "positions": [[0,0,0],[1,0,0],[0,1,0]], "texcoords": [[0,0],[1,0],[0,1]], "texture": {"file": "cut.png"}}]})";
  loaded = crosscheck::loadScene(cut);
  ASSERT_FALSE(loaded);
  EXPECT_NE(loaded.error().find("cut.png: corrupt PNG image"), std::string::npos) << loaded.error();
  EXPECT_EQ(loaded.error().find('\n'), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
