// Scene files: defaults, overrides, and one clear error line for every kind of bad input.
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

const std::filesystem::path kData = TEST_DATA_DIR;
const std::filesystem::path kScenes = SCENES_DIR;

std::string loadError(const std::filesystem::path& file) {
  const auto scene = crosscheck::loadScene(file);
  EXPECT_FALSE(scene.ok()) << file;
  const std::string error = scene.error();
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  EXPECT_NE(error.find(file.string()), std::string::npos) << "names the file: " << error;
  return error;
}

}  // namespace

TEST(SceneFile, RoomLoadsWithItsMeshAndTolerance) {
  const auto scene = crosscheck::loadScene(kScenes / "room.json");
  ASSERT_TRUE(scene) << scene.error();
  EXPECT_EQ(scene->width, 320u);
  EXPECT_EQ(scene->height, 240u);
  ASSERT_EQ(scene->draws.size(), 1u);
  EXPECT_EQ(scene->draws[0].indices.size(), 30u * 3);  // 5 walls + 2 boxes of 5 faces, 2 triangles each
  EXPECT_EQ(scene->draws[0].state.rasterization.cullMode, softraster::CullMode::Back);
  EXPECT_EQ(scene->tolerance.colourThreshold, 1);
  EXPECT_FLOAT_EQ(static_cast<float>(scene->tolerance.depthThreshold), 0x1p-24f);
  EXPECT_FALSE(scene->description.empty());
}

TEST(SceneFile, OverrideTurnsTheCamera) {
  const auto straight = crosscheck::loadScene(kScenes / "room.json");
  const auto turned = crosscheck::loadScene(kScenes / "room.json", {"camera.yaw=90"});
  ASSERT_TRUE(straight && turned) << straight.error() << turned.error();
  EXPECT_NE(straight->viewProjection.at(0, 0), turned->viewProjection.at(0, 0));
  const auto bad = crosscheck::loadScene(kScenes / "room.json", {"camera.yaw"});
  EXPECT_FALSE(bad);
  const std::string& error = bad.error();
  EXPECT_NE(error.find("KEY.PATH=VALUE"), std::string::npos) << error;
}

TEST(SceneFile, SyntaxErrorNamesLineAndColumn) {
  const std::string error = loadError(kData / "malformed_syntax.json");
  EXPECT_NE(error.find("line 3"), std::string::npos) << error;
}

TEST(SceneFile, UnknownFieldIsAnErrorWithItsPlace) {
  const std::string error = loadError(kData / "unknown_field.json");
  EXPECT_NE(error.find("/draws/0/colr"), std::string::npos) << error;
}

TEST(SceneFile, BadEnumListsTheChoices) {
  const std::string error = loadError(kData / "bad_enum.json");
  EXPECT_NE(error.find("/draws/0/cull"), std::string::npos) << error;
  EXPECT_NE(error.find("front_and_back"), std::string::npos) << error;
}

TEST(SceneFile, IndexPastTheVerticesIsAnError) {
  const std::string error = loadError(kData / "bad_index.json");
  EXPECT_NE(error.find("/draws/0/indices/2"), std::string::npos) << error;
}

TEST(SceneFile, MissingAndMalformedObjFiles) {
  EXPECT_NE(loadError(kData / "missing_obj.json").find("does_not_exist.obj: file not found"), std::string::npos);
  EXPECT_NE(loadError(kData / "malformed_obj.json").find("malformed.obj"), std::string::npos);
}

TEST(SceneFile, MissingSceneFile) {
  EXPECT_NE(loadError(kData / "no_such_scene.json").find("cannot open"), std::string::npos);
}
