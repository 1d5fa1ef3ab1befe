// Scene files: defaults, overrides, and one clear error line for every kind of bad input.
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

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

// The procedural sphere ("sphere": {segments, rings, radius, centre}).
namespace {

const std::filesystem::path kTinySphere = kData / "bench" / "tiny_sphere.json";

// The error of loading the tiny sphere with `overrides`: one line naming the file.
std::string sphereError(const std::vector<std::string>& overrides) {
  const auto scene = crosscheck::loadScene(kTinySphere, overrides);
  EXPECT_FALSE(scene.ok()) << "overrides accepted";
  if (scene.ok()) return {};
  const std::string error = scene.error();
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  EXPECT_NE(error.find(kTinySphere.string()), std::string::npos) << "names the file: " << error;
  return error;
}

}  // namespace

TEST(SceneFile, SphereIsAnIndexedClosedMeshColouredByItsNormals) {
  const auto scene = crosscheck::loadScene(kTinySphere, {"draws.0.sphere.centre=[1, 2, 3]", "draws.0.sphere.radius=0.5"});
  ASSERT_TRUE(scene) << scene.error();
  const crosscheck::Draw& draw = scene->draws[0];
  EXPECT_TRUE(draw.indexed);
  EXPECT_EQ(draw.state.topology, softraster::Topology::TriangleList);
  EXPECT_EQ(draw.mesh.vertexCount(), 16u * (9 - 1) + 2);
  EXPECT_EQ(draw.indices.size(), 3u * 2 * 16 * (9 - 1));
  for (std::uint32_t index : draw.indices) ASSERT_LT(index, draw.mesh.vertexCount());
  for (std::size_t i = 0; i < draw.mesh.vertexCount(); ++i) {
    const softraster::Vec3 p = draw.mesh.positions[i];
    const softraster::Vec4 c = draw.mesh.colours[i];
    const float nx = (p.x - 1) / 0.5f, ny = (p.y - 2) / 0.5f, nz = (p.z - 3) / 0.5f;
    EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0f, 1e-5f) << "vertex " << i << " on the sphere";
    EXPECT_NEAR(c.x, 0.5f + 0.5f * nx, 1e-5f) << "vertex " << i;
    EXPECT_NEAR(c.y, 0.5f + 0.5f * ny, 1e-5f) << "vertex " << i;
    EXPECT_NEAR(c.z, 0.5f + 0.5f * nz, 1e-5f) << "vertex " << i;
    EXPECT_EQ(c.w, 1.0f);
  }
  // Closed: every edge is shared by exactly two triangles, in opposite directions.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < draw.indices.size(); t += 3) {
    for (int k = 0; k < 3; ++k) ++edges[{draw.indices[t + k], draw.indices[t + (k + 1) % 3]}];
  }
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1) << edge.first << "->" << edge.second;
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << edge.first << "->" << edge.second << " has no twin";
  }
}

TEST(SceneFile, SphereBadValuesAreOneErrorLineEach) {
  EXPECT_NE(sphereError({"draws.0.sphere.segments=2.5"}).find("/draws/0/sphere/segments: expected an integer"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.rings=\"ten\""}).find("/draws/0/sphere/rings: expected an integer"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.segments=2"}).find("/draws/0/sphere/segments: must be at least 3"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.rings=-4"}).find("/draws/0/sphere/rings: must be at least 3"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.rings=20000"}).find("/draws/0/sphere/rings: must be at most 10000"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.segments=10000", "draws.0.sphere.rings=10000"}).find("triangles, more than"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.radius=-1"}).find("/draws/0/sphere/radius: must be a positive number"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.radius=0"}).find("/draws/0/sphere/radius: must be a positive number"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.centre=[0, 0]"}).find("/draws/0/sphere/centre: expected an array of 3"),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere={}"}).find("/draws/0/sphere/segments: missing"), std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere.size=3"}).find("/draws/0/sphere/size: unknown field"), std::string::npos);
  EXPECT_NE(sphereError({"draws.0.sphere=4"}).find("/draws/0/sphere: expected an object"), std::string::npos);
  EXPECT_NE(sphereError({"draws.0.positions=[[0, 0, 1]]"}).find("either \"sphere\" or \"positions\""),
            std::string::npos);
  EXPECT_NE(sphereError({"draws.0.topology=line_list"}).find("/draws/0/topology: a sphere is a triangle list"),
            std::string::npos);
}

// The draw's "blend" object: the short form, the colour and alpha sides, constants, write mask.
namespace {

const std::filesystem::path kBlendTriangle = kData / "blend_triangle.json";

softraster::BlendState blendWith(const std::vector<std::string>& overrides) {
  const auto scene = crosscheck::loadScene(kBlendTriangle, overrides);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? scene->draws.at(0).state.blend : softraster::BlendState{};
}

std::string blendError(const std::vector<std::string>& overrides) {
  const auto scene = crosscheck::loadScene(kBlendTriangle, overrides);
  EXPECT_FALSE(scene.ok()) << "overrides accepted";
  if (scene.ok()) return {};
  const std::string error = scene.error();
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  EXPECT_NE(error.find(kBlendTriangle.string()), std::string::npos) << "names the file: " << error;
  return error;
}

}  // namespace

TEST(SceneFile, BlendShortFormIsTheSameForColourAndAlphaWithAdd) {
  using softraster::BlendFactor;
  const softraster::BlendState b = blendWith({});
  EXPECT_TRUE(b.enable);
  EXPECT_EQ(b.srcColorBlendFactor, BlendFactor::SrcAlpha);
  EXPECT_EQ(b.dstColorBlendFactor, BlendFactor::OneMinusSrcAlpha);
  EXPECT_EQ(b.srcAlphaBlendFactor, BlendFactor::SrcAlpha);
  EXPECT_EQ(b.dstAlphaBlendFactor, BlendFactor::OneMinusSrcAlpha);
  EXPECT_EQ(b.colorBlendOp, softraster::BlendOp::Add);
  EXPECT_EQ(b.alphaBlendOp, softraster::BlendOp::Add);
  EXPECT_EQ(b.colorWriteMask, softraster::kColourRGBA);
  for (float k : b.blendConstants) EXPECT_EQ(k, 0.0f);
  const auto scene = crosscheck::loadScene(kBlendTriangle, {"draws.0.blend={}"});
  ASSERT_TRUE(scene) << scene.error();
  const softraster::BlendState empty = scene->draws[0].state.blend;
  EXPECT_TRUE(empty.enable);
  EXPECT_EQ(empty.srcColorBlendFactor, BlendFactor::One);
  EXPECT_EQ(empty.dstAlphaBlendFactor, BlendFactor::Zero);
}

TEST(SceneFile, BlendSidesConstantsAndWriteMask) {
  using softraster::BlendFactor;
  using softraster::BlendOp;
  const softraster::BlendState b = blendWith(
      {"draws.0.blend.op=reverse_subtract", "draws.0.blend.colour={\"source\": \"constant_color\", \"op\": \"max\"}",
       "draws.0.blend.alpha={\"destination\": \"src_alpha_saturate\"}", "draws.0.blend.constants=[0.25, 0.5, 0.75, 1]",
       "draws.0.blend.write_mask=bga"});
  EXPECT_EQ(b.srcColorBlendFactor, BlendFactor::ConstantColor);
  EXPECT_EQ(b.dstColorBlendFactor, BlendFactor::OneMinusSrcAlpha);  // from the short form
  EXPECT_EQ(b.colorBlendOp, BlendOp::Max);
  EXPECT_EQ(b.srcAlphaBlendFactor, BlendFactor::SrcAlpha);
  EXPECT_EQ(b.dstAlphaBlendFactor, BlendFactor::SrcAlphaSaturate);
  EXPECT_EQ(b.alphaBlendOp, BlendOp::ReverseSubtract);
  EXPECT_EQ(b.blendConstants[0], 0.25f);
  EXPECT_EQ(b.blendConstants[3], 1.0f);
  EXPECT_EQ(b.colorWriteMask, softraster::kColourG | softraster::kColourB | softraster::kColourA);
  const softraster::BlendState off = blendWith({"draws.0.blend={\"enable\": false, \"write_mask\": \"\"}"});
  EXPECT_FALSE(off.enable);
  EXPECT_EQ(off.colorWriteMask, 0);
}

TEST(SceneFile, LogicOpTurnsBlendingOff) {
  const softraster::BlendState x = blendWith({"draws.0.blend={\"logic_op\": \"xor\", \"write_mask\": \"rb\"}"});
  EXPECT_TRUE(x.logicOpEnable);
  EXPECT_EQ(x.logicOp, softraster::LogicOp::Xor);
  EXPECT_FALSE(x.enable) << "Vulkan treats blending as disabled with a logic op";
  EXPECT_EQ(x.colorWriteMask, softraster::kColourR | softraster::kColourB);
  const softraster::BlendState both = blendWith({"draws.0.blend.logic_op=or_inverted"});  // beside the file's factors
  EXPECT_TRUE(both.logicOpEnable);
  EXPECT_EQ(both.logicOp, softraster::LogicOp::OrInverted);
  EXPECT_FALSE(both.enable);
  EXPECT_FALSE(blendWith({}).logicOpEnable);
  EXPECT_NE(blendError({"draws.0.blend.logic_op=mix"})
                .find("/draws/0/blend/logic_op: 'mix' is not one of clear, and, and_reverse, copy"),
            std::string::npos);
}

TEST(SceneFile, BlendBadValuesAreOneErrorLineEach) {
  EXPECT_NE(blendError({"draws.0.blend.source=src1_color"})
                .find("/draws/0/blend/source: 'src1_color' is not one of zero, one, src_color"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.colour={\"destination\": \"dst_colour\"}"})
                .find("/draws/0/blend/colour/destination: 'dst_colour' is not one of"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.alpha={\"op\": \"multiply\"}"})
                .find("/draws/0/blend/alpha/op: 'multiply' is not one of add, subtract, reverse_subtract, min, max"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.alpha={\"factor\": \"one\"}"}).find("/draws/0/blend/alpha/factor: unknown field"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.equation=add"}).find("/draws/0/blend/equation: unknown field"), std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.colour=add"}).find("/draws/0/blend/colour: expected an object"), std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.constants=[1, 0, 0]"}).find("/draws/0/blend/constants: expected an array of 4"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.constants=[0, 1.5, 0, 0]"}).find("/draws/0/blend/constants/1: must be in [0, 1]"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.write_mask=rgbx"}).find("/draws/0/blend/write_mask: 'rgbx' is not a set of"),
            std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.write_mask=rr"}).find("/draws/0/blend/write_mask: 'rr'"), std::string::npos);
  EXPECT_NE(blendError({"draws.0.blend.enable=1"}).find("/draws/0/blend/enable: expected true or false"),
            std::string::npos);
}
