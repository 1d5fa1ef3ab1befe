// Hostile input to the scene and OBJ loaders: each class of bad input the robustness issue found
// (overflowing numbers, paths that are not regular files, integers that would wrap, values Vulkan
// forbids, degenerate cameras, malformed OBJ statements) is one error line that names the file and
// the place, and never an exception, a hang or a silently different scene.
// Deliberately only the loaders: the command line's exit statuses are in hostile_cli_test.sh.
#include "scene/scene.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// A fresh folder for one test's files, removed afterwards.
class HostileInput : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("crosscheck-hostile-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_ / "locked", fs::perms::owner_all, ec);
    fs::remove_all(dir_, ec);
  }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  // A valid one-triangle scene, to be broken by overrides.
  fs::path triangle() {
    return write("triangle.json", R"({"camera": {"type": "clip_space"},
      "draws": [{"positions": [[-0.5, -0.5, 0.5], [0.5, -0.5, 0.5], [0, 0.5, 0.5]], "cull": "none"}]})");
  }

  // The error of loading `path` with `overrides`: one line that names the file and contains `expected`.
  void expectError(const fs::path& path, const std::vector<std::string>& overrides, const std::string& expected) {
    const auto scene = crosscheck::loadScene(path, overrides);
    ASSERT_FALSE(scene.ok()) << "accepted: " << path << (overrides.empty() ? "" : " --set " + overrides[0]);
    const std::string error = scene.error();
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
    EXPECT_EQ(error.rfind(path.string(), 0), 0u) << "starts with the file: " << error;
    EXPECT_NE(error.find(expected), std::string::npos) << "expected '" << expected << "' in: " << error;
  }
  void expectOverrideError(const std::string& assignment, const std::string& expected) {
    expectError(triangle(), {assignment}, expected);
  }

  fs::path dir_;
};

TEST_F(HostileInput, TheBaseSceneLoads) { ASSERT_TRUE(crosscheck::loadScene(triangle()).ok()); }

TEST_F(HostileInput, NumbersThatOverflowADouble) {
  expectError(write("yaw.json", R"({"camera": {"yaw": 1e400}, "draws": []})"), {}, "number overflow");
  // Through --set the text is not a JSON number, so it is a string where a number belongs.
  expectOverrideError("camera={\"yaw\":1e400}", "expected an object");
  expectOverrideError("draws.0.point_size=1e400", "/draws/0/point_size: expected a number");
}

TEST_F(HostileInput, ScenePathsThatAreNotRegularFiles) {
  fs::create_directories(dir_ / "a_directory.json");
  expectError(dir_ / "a_directory.json", {}, "cannot open scene file: is a directory");
  ASSERT_EQ(::mkfifo((dir_ / "fifo.json").c_str(), 0600), 0);
  expectError(dir_ / "fifo.json", {}, "is not a regular file");  // and does not block
  fs::create_symlink(dir_ / "loop_b.json", dir_ / "loop_a.json");
  fs::create_symlink(dir_ / "loop_a.json", dir_ / "loop_b.json");
  expectError(dir_ / "loop_a.json", {}, "cannot be read: Too many levels of symbolic links");
  expectError("/dev/zero", {}, "is not a regular file");
  expectError(dir_ / "missing.json", {}, "cannot open scene file: file not found");
}

TEST_F(HostileInput, SceneInAFolderThatCannotBeSearched) {
  if (::geteuid() == 0) GTEST_SKIP() << "root searches every folder";
  fs::create_directories(dir_ / "locked");
  write("locked/scene.json", "{}");
  fs::permissions(dir_ / "locked", fs::perms::none);
  expectError(dir_ / "locked" / "scene.json", {}, "cannot be read: Permission denied");
}

TEST_F(HostileInput, IntegersThatWouldWrapTo32Bits) {
  expectOverrideError("framebuffer.width=4294967297", "/framebuffer/width: 4294967297 is more than 8192");
  expectOverrideError("framebuffer.height=8193", "/framebuffer/height: 8193 is more than 8192");
  expectOverrideError("framebuffer.samples=4294967300", "/framebuffer/samples: 4294967300 is more than 64");
  expectOverrideError("framebuffer.samples=2", "/framebuffer/samples: must be 1 or 4");
  expectOverrideError("tolerance.colour=2147483648", "/tolerance/colour: 2147483648 is more than 255");
  expectOverrideError("tolerance.colour=-1", "/tolerance/colour: expected a non-negative integer");
  expectOverrideError("tolerance.coverage_mismatches=18446744073709551616", "expected a non-negative integer");
  expectOverrideError("draws.0.scissor={\"width\":4294967296,\"height\":1}", "/draws/0/scissor/width: 4294967296 is more than 4294967295");
  expectOverrideError("draws.0.scissor={\"x\":2147483648}", "/draws/0/scissor/x: 2147483648 is more than 2147483647");
  expectOverrideError("draws.0.scissor={\"x\":2147483647,\"width\":100,\"height\":1}",
                      "/draws/0/scissor: x + width and y + height must fit in a 32-bit signed integer");
}

TEST_F(HostileInput, ColoursOutsideZeroToOne) {
  expectOverrideError("framebuffer.clear_colour=[2,0,0]", "/framebuffer/clear_colour/0: must be in [0, 1]");
  expectOverrideError("draws.0.colour=[0,0,0,-0.5]", "/draws/0/colour/3: must be in [0, 1]");
  expectOverrideError("draws.0.colours=[[0,0,0],[0,1e300,0],[0,0,0]]", "/draws/0/colours/1/1: must be in [0, 1]");
}

TEST_F(HostileInput, StatesVulkanForbids) {
  expectOverrideError("draws.0.viewport={\"width\":0,\"height\":10}", "/draws/0/viewport/width: must be greater than 0 (VUID-VkViewport-width-01770");
  expectOverrideError("draws.0.viewport={\"width\":20000,\"height\":10}", "maxViewportDimensions");
  expectOverrideError("draws.0.viewport={\"x\":32000,\"width\":1000,\"height\":10}", "viewportBoundsRange");
  expectOverrideError("draws.0.viewport={\"x\":1e300,\"width\":10,\"height\":10}", "/draws/0/viewport/x: must be a finite number");
  expectOverrideError("draws.0.point_size=1e300", "/draws/0/point_size: must be a finite number within float range");
  expectOverrideError("draws.0.point_size=256", "/draws/0/point_size: must be in (0, 255]");
  expectOverrideError("draws.0.line_width=1e9", "/draws/0/line_width: must be in [1, 255]");
  expectOverrideError("draws.0.line_width=1e39", "/draws/0/line_width: must be a finite number within float range");
  expectOverrideError("draws.0.depth_bias={\"constant\":1e39}", "/draws/0/depth_bias/constant: must be a finite number");
  expectOverrideError("framebuffer.clear_depth=1e39", "/framebuffer/clear_depth: must be a finite number");
}

TEST_F(HostileInput, DegenerateCameras) {
  const auto lookAt = [&](const std::string& up) {
    return "camera={\"type\":\"look_at\",\"eye\":[0,0,-3],\"target\":[0,0,0],\"up\":" + up + "}";
  };
  ASSERT_TRUE(crosscheck::loadScene(triangle(), {lookAt("[0,-1,0]")}).ok());
  expectOverrideError(lookAt("[0,0,1]"), "/camera/up: is zero or parallel to the view direction");
  expectOverrideError(lookAt("[0,0,0]"), "/camera/up: is zero or parallel to the view direction");
  expectOverrideError("camera={\"focal_length\":1e300}", "/camera: its matrices are not finite in float");
  expectOverrideError("draws.0.transform={\"scale\":1e300}", "/draws/0/transform: the model-view-projection matrix is not finite");
}

TEST_F(HostileInput, TooManyDraws) {
  std::string draws;
  for (int i = 0; i <= 100000; ++i) draws += std::string(i ? "," : "") + R"({"positions":[[0,0,0]],"topology":"point_list"})";
  expectError(write("draws.json", R"({"camera": {"type": "clip_space"}, "draws": [)" + draws + "]}"), {},
              "/draws: 100001 draws, more than 100000");
}

// A scene drawing `obj` (relative to the test folder).
class HostileObj : public HostileInput {
 protected:
  void expectObjError(const std::string& obj, const std::string& expected) {
    const fs::path scene = write("obj_scene.json", R"({"draws": [{"obj": ")" + obj + R"("}]})");
    expectError(scene, {}, "/draws/0/obj: ");
    expectError(scene, {}, expected);
  }
  void expectObjTextError(const std::string& text, const std::string& expected) {
    write("mesh.obj", text);
    expectObjError("mesh.obj", expected);
  }
};

TEST_F(HostileObj, ValidTriangleLoads) {
  write("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -3 -2 -1\n");
  const fs::path scene = write("obj_scene.json", R"({"draws": [{"obj": "mesh.obj"}]})");
  const auto loaded = crosscheck::loadScene(scene);
  ASSERT_TRUE(loaded.ok()) << loaded.error();
  EXPECT_EQ(loaded->draws[0].indices.size(), 6u);
}

TEST_F(HostileObj, FaceIndicesThatAreNotIntegersOrReferToNothing) {
  expectObjTextError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1e20\n", "mesh.obj:4: face corner '1e20': '1e20' is not an integer position index");
  expectObjTextError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "mesh.obj:4: face corner '4': position index 4 refers to no position (3 defined so far)");
  expectObjTextError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "position index 0 refers to no position");
  expectObjTextError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n", "is not an integer position index");
  expectObjTextError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", "normal index 1 refers to no normal (0 defined so far)");
  expectObjTextError("v 0 0 0\nv 1 0 0\nf 1 2\n", "mesh.obj:3: a face has 2 corners; expected at least 3");
}

TEST_F(HostileObj, PositionsWithTheWrongNumberOfValues) {
  expectObjTextError("v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "mesh.obj:1: a position (v) has 2 numbers; expected x y z");
  expectObjTextError("v 0 0 0 1\n", "mesh.obj:1: a position (v) has 4 numbers");
  expectObjTextError("v 0 0 1e39\n", "mesh.obj:1: '1e39' is not a finite number");
  expectObjTextError("v 0 0 nan\n", "mesh.obj:1: 'nan' is not a finite number");
  expectObjTextError("vn 0 1\n", "mesh.obj:1: a normal (vn) has 2 numbers; expected 3");
}

TEST_F(HostileObj, ColoursOutsideZeroToOne) {
  expectObjTextError("v 0 0 0 1 2 0\n", "mesh.obj:1: a vertex colour (r g b) must be in [0, 1]");
  write("bright.mtl", "newmtl bright\nKd 1.5 0 0\n");
  expectObjTextError("mtllib bright.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl bright\nf 1 2 3\n",
                     "mesh.obj: material 'bright': Kd must be in [0, 1]");
}

TEST_F(HostileObj, StatementsThatWouldBeDroppedSilently) {
  expectObjTextError("v 0 0 0\nv 1 0 0\nl 1 2\n", "mesh.obj:3: lines and points ('l') are not drawn");
  expectObjTextError("curv 0 1 2\n", "mesh.obj:1: 'curv' is not an OBJ statement this loader reads");
}

TEST_F(HostileObj, ObjPathsThatAreNotRegularFiles) {
  fs::create_directories(dir_ / "folder.obj");
  expectObjError("folder.obj", "folder.obj: is a directory, not a file");
  expectObjError("/dev/zero", "/dev/zero: is not a regular file");
  fs::create_symlink(dir_ / "b.obj", dir_ / "a.obj");
  fs::create_symlink(dir_ / "a.obj", dir_ / "b.obj");
  expectObjError("a.obj", "a.obj: cannot be read: Too many levels of symbolic links");
  expectObjError("missing.obj", "missing.obj: file not found");
}

}  // namespace
