// crosscheck view without a display: the key script's parser and its one-line errors, the camera,
// light and time controls and the overrides they become, the saved scene's text, the views'
// pictures, and the loop itself (a scripted walk through the room on lavapipe, shown on a
// stand-in Display) whose saved scene loads back with the pose it was saved at.
// The window (SDL2, under Xvfb) is tested by view_cli_test.sh.
#include "compare/compare.hpp"
#include "output/artifacts.hpp"
#include "output/image_io.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"
#include "view/controls.hpp"
#include "view/script.hpp"
#include "view/viewer.hpp"
#include "view/views.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace crosscheck;
using namespace crosscheck::view;

const std::filesystem::path kScenes = SCENES_DIR;
const std::filesystem::path kArtifacts = ARTIFACTS_DIR;

std::string scriptError(const std::string& text) {
  const auto parsed = parseScript(text, "walk.txt");
  EXPECT_FALSE(parsed) << text;
  if (parsed) return "";
  EXPECT_EQ(parsed.error().find('\n'), std::string::npos) << parsed.error();
  return parsed.error();
}

Pose roomPose() {
  const auto scene = loadScene(kScenes / "room.json");
  EXPECT_TRUE(scene) << scene.error();
  return poseOf(*scene);
}

}  // namespace

TEST(ViewScript, ParsesEveryCommand) {
  const auto parsed = parseScript(
      "# a walk\n\nkey Up 10\nkey Right   # once\nframe\nframe 3\nview diff\nmethod exact-scalar\n"
      "screenshot start\nsave walk.json\nsave here\nquit\n",
      "walk.txt");
  ASSERT_TRUE(parsed) << parsed.error();
  const std::vector<ScriptCommand>& c = *parsed;
  ASSERT_EQ(c.size(), 10u);
  EXPECT_EQ(c[0].kind, ScriptCommand::Kind::Key);
  EXPECT_EQ(c[0].key, "Up");
  EXPECT_EQ(c[0].frames, 10u);
  EXPECT_EQ(c[0].line, 3u);
  EXPECT_EQ(c[1].key, "Right");
  EXPECT_EQ(c[1].frames, 1u);
  EXPECT_EQ(c[2].kind, ScriptCommand::Kind::Frame);
  EXPECT_EQ(c[2].frames, 1u);
  EXPECT_EQ(c[3].frames, 3u);
  EXPECT_EQ(c[4].kind, ScriptCommand::Kind::View);
  EXPECT_EQ(c[4].view, ViewKind::Diff);
  EXPECT_EQ(c[5].kind, ScriptCommand::Kind::Method);
  EXPECT_EQ(c[5].method, softraster::Method::ExactScalar);
  EXPECT_EQ(c[6].kind, ScriptCommand::Kind::Screenshot);
  EXPECT_EQ(c[6].name, "start.png");
  EXPECT_EQ(c[7].kind, ScriptCommand::Kind::Save);
  EXPECT_EQ(c[7].name, "walk.json");
  EXPECT_EQ(c[8].name, "here.json");
  EXPECT_EQ(c[9].kind, ScriptCommand::Kind::Quit);
}

TEST(ViewScript, EveryErrorIsOneLineNamingFileAndLine) {
  EXPECT_EQ(scriptError("frame\n\njump 3\n").rfind("walk.txt:3: unknown command 'jump' (expected key, frame, view", 0), 0u);
  EXPECT_EQ(scriptError("key Upp 2\n").rfind("walk.txt:1: unknown key 'Upp' (keys: Up Down Left Right PageUp", 0), 0u);
  EXPECT_EQ(scriptError("key Up 0\n"), "walk.txt:1: '0': expected a whole number of frames from 1 to 100000");
  EXPECT_EQ(scriptError("frame x\n"), "walk.txt:1: 'x': expected a whole number of frames from 1 to 100000");
  EXPECT_EQ(scriptError("frame 100001\n"), "walk.txt:1: '100001': expected a whole number of frames from 1 to 100000");
  EXPECT_EQ(scriptError("frame -1\n"), "walk.txt:1: '-1': expected a whole number of frames from 1 to 100000");
  EXPECT_EQ(scriptError("key\n"), "walk.txt:1: expected 'key NAME [FRAMES]'");
  EXPECT_EQ(scriptError("key Up 2 3\n"), "walk.txt:1: expected 'key NAME [FRAMES]'");
  EXPECT_EQ(scriptError("view\n"), "walk.txt:1: expected 'view NAME'");
  EXPECT_EQ(scriptError("view wide\n").rfind("walk.txt:1: unknown view 'wide' (expected one of side, soft, vulkan, diff", 0), 0u);
  EXPECT_EQ(scriptError("method fast\n").rfind("walk.txt:1: unknown method 'fast' (expected one of exact, exact-scalar", 0), 0u);
  EXPECT_EQ(scriptError("screenshot ../x\n"),
            "walk.txt:1: '../x': expected a file name (letters, digits, '-', '_', '.'; no folders)");
  EXPECT_EQ(scriptError("save\n"), "walk.txt:1: expected 'save NAME'");
  EXPECT_EQ(scriptError("quit now\n"), "walk.txt:1: expected 'quit'");
}

TEST(ViewScript, UnreadableFileIsOneLine) {
  const auto missing = loadScript(kArtifacts / "view-unit" / "no_such_script.txt");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("no_such_script.txt: cannot read script: file not found"), std::string::npos)
      << missing.error();
  const auto directory = loadScript(kScenes);
  ASSERT_FALSE(directory);
  EXPECT_NE(directory.error().find(": cannot read script: "), std::string::npos) << directory.error();
}

TEST(ViewControls, EveryKeyOnceAndEveryViewAndMethodReachable) {
  std::vector<std::string> keys;
  for (const Control& c : controls()) {
    for (const std::string& k : keys) EXPECT_NE(k, c.key);
    keys.emplace_back(c.key);
    EXPECT_EQ(controlForKey(c.key), &c);
  }
  for (ViewKind v : kViews) {
    bool found = false;
    for (const Control& c : controls()) found = found || (c.action == Action::ShowView && c.view == v);
    EXPECT_TRUE(found) << viewName(v);
    EXPECT_EQ(viewFromName(viewName(v)), v);
  }
  EXPECT_EQ(controlForKey("Z"), nullptr);
  // M cycles over every method and comes back.
  softraster::Method m = softraster::kMethods.front();
  for (std::size_t i = 0; i < softraster::kMethods.size(); ++i) {
    EXPECT_EQ(m, softraster::kMethods[i]);
    m = nextMethod(m);
  }
  EXPECT_EQ(m, softraster::kMethods.front());
  EXPECT_EQ(controlLines().size(), controls().size());
}

TEST(ViewControls, PinholeStepsFollowTheCameraAxes) {
  Pose pose = roomPose();
  ASSERT_EQ(pose.camera.type, CameraSettings::Type::Pinhole);
  const Pose original = pose;
  PinholeCamera& c = pose.camera.pinhole;
  // The room looks down 20 degrees: forward is (0, sin 20, cos 20) (y is down).
  ASSERT_TRUE(applyStep(Action::MoveForward, pose));
  const double p = -20 * M_PI / 180;
  EXPECT_NEAR(c.position[0], 0, 1e-15);
  EXPECT_NEAR(c.position[1], -0.45 - kMoveStep * std::sin(p), 1e-15);
  EXPECT_NEAR(c.position[2], -0.98 + kMoveStep * std::cos(p), 1e-15);
  ASSERT_TRUE(applyStep(Action::MoveBack, pose));
  EXPECT_NEAR(c.position[2], -0.98, 1e-15);
  ASSERT_TRUE(applyStep(Action::TurnRight, pose));
  EXPECT_EQ(c.yawDegrees, kTurnStep);
  ASSERT_TRUE(applyStep(Action::TurnLeft, pose));
  ASSERT_TRUE(applyStep(Action::TurnLeft, pose));
  EXPECT_EQ(c.yawDegrees, -kTurnStep);
  ASSERT_TRUE(applyStep(Action::PitchUp, pose));
  EXPECT_EQ(c.pitchDegrees, -20 + kTurnStep);
  // Turned 90 degrees right and level, forward is +x.
  c.yawDegrees = 90;
  c.pitchDegrees = 0;
  c.position = {0, 0, 0};
  ASSERT_TRUE(applyStep(Action::MoveForward, pose));
  EXPECT_NEAR(c.position[0], kMoveStep, 1e-15);
  EXPECT_NEAR(c.position[2], 0, 1e-15);
  // Pitch stops at its limit.
  c.pitchDegrees = kMaxPitch - 1;
  EXPECT_FALSE(applyStep(Action::PitchUp, pose));
  EXPECT_EQ(c.pitchDegrees, kMaxPitch - 1);
  EXPECT_TRUE(applyStep(Action::PitchDown, pose));
  // The light moves along the axes; y is down, so up is -y.
  pose = original;
  for (Action a : {Action::LightForward, Action::LightRight, Action::LightUp}) ASSERT_TRUE(applyStep(a, pose));
  EXPECT_EQ(pose.lightPosition[0], original.lightPosition[0] + kLightStep);
  EXPECT_EQ(pose.lightPosition[1], original.lightPosition[1] - kLightStep);
  EXPECT_EQ(pose.lightPosition[2], original.lightPosition[2] + kLightStep);
  ASSERT_TRUE(applyStep(Action::TimeForward, pose));
  EXPECT_EQ(pose.time, kTimeStep);
}

TEST(ViewControls, LookAtTurnsKeepTheEyeAndDistanceAndStopBeforeUp) {
  const auto scene = loadScene(kScenes / "camera_look_at.json");
  ASSERT_TRUE(scene) << scene.error();
  Pose pose = poseOf(*scene);
  ASSERT_EQ(pose.camera.type, CameraSettings::Type::LookAt);
  const LookAtCamera before = pose.camera.lookAt;
  const auto distance = [](const LookAtCamera& c) {
    return std::hypot(c.target[0] - c.eye[0], c.target[1] - c.eye[1], c.target[2] - c.eye[2]);
  };
  ASSERT_TRUE(applyStep(Action::TurnRight, pose));
  EXPECT_EQ(pose.camera.lookAt.eye, before.eye);
  EXPECT_NEAR(distance(pose.camera.lookAt), distance(before), 1e-12);
  EXPECT_NE(pose.camera.lookAt.target, before.target);
  // Turning right moves the target towards the camera's right axis, as camera.cpp makes it.
  const auto matrices = cameraMatrices(pose.camera.lookAt, 320, 240);
  const auto old = cameraMatrices(before, 320, 240);
  const glm::dvec4 target(before.target[0], before.target[1], before.target[2], 1);
  EXPECT_LT((matrices.view * target).x, (old.view * target).x);  // the old target is now on the left
  ASSERT_TRUE(applyStep(Action::MoveForward, pose));
  EXPECT_NEAR(distance(pose.camera.lookAt), distance(before), 1e-12);
  // Pitching up until the view nearly meets the up vector stops there; the scene still loads.
  int steps = 0;
  while (applyStep(Action::PitchUp, pose) && steps < 200) ++steps;
  EXPECT_LT(steps, 200);
  const auto still = loadScene(kScenes / "camera_look_at.json", poseOverrides(poseOf(*scene), pose));
  EXPECT_TRUE(still) << still.error();
  // A clip_space scene has no camera to move.
  Pose clip;
  clip.camera.type = CameraSettings::Type::ClipSpace;
  EXPECT_FALSE(applyStep(Action::MoveForward, clip));
  EXPECT_FALSE(applyStep(Action::TurnLeft, clip));
}

TEST(ViewControls, OverridesNameOnlyWhatChangedAndReadBackExactly) {
  const Pose original = roomPose();
  EXPECT_TRUE(poseOverrides(original, original).empty());
  Pose pose = original;
  for (int i = 0; i < 7; ++i) applyStep(Action::MoveForward, pose);
  for (int i = 0; i < 3; ++i) applyStep(Action::TurnRight, pose);
  const std::vector<std::string> overrides = poseOverrides(original, pose);
  ASSERT_EQ(overrides.size(), 2u);
  EXPECT_EQ(overrides[0].rfind("camera.position=[", 0), 0u) << overrides[0];
  EXPECT_EQ(overrides[1], "camera.yaw=6.0");
  const auto moved = loadScene(kScenes / "room.json", overrides);
  ASSERT_TRUE(moved) << moved.error();
  EXPECT_TRUE(poseOf(*moved) == pose);  // every double as it was
  applyStep(Action::LightLeft, pose);
  applyStep(Action::TimeBack, pose);
  const auto all = poseOverrides(original, pose);
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[2].rfind("light.position=[", 0), 0u);
  EXPECT_EQ(all[3].rfind("time=-0.0333", 0), 0u) << all[3];
}

TEST(ViewSceneFile, TheSavedTextIsTheSceneWithTheOverridesAndItsMeshFound) {
  const std::filesystem::path dir = kArtifacts / "view-unit" / "saved" / "deeper";
  std::filesystem::create_directories(dir);
  const std::vector<std::string> overrides = {"camera.yaw=12.5", "light.position=[0.25,-0.5,-0.7]", "time=0.75"};
  const auto text = sceneFileText(kScenes / "room.json", overrides, dir, "a view found by hand");
  ASSERT_TRUE(text) << text.error();
  const nlohmann::ordered_json document = nlohmann::ordered_json::parse(*text);
  EXPECT_EQ(document.begin().key(), "description");
  EXPECT_EQ(document["description"], "a view found by hand");
  EXPECT_EQ(document["camera"]["yaw"], 12.5);
  EXPECT_EQ(document["camera"]["pitch"], -20);  // the rest as the file has it
  EXPECT_EQ(document["time"], 0.75);
  EXPECT_EQ(document["draws"][0]["obj"], "../../../../../scenes/meshes/cornell_box.obj")
      << "relative to " << dir;
  // The file's own layout: one field per line, one draw per line.
  EXPECT_NE(text->find("\n  \"camera\": { \"type\": \"pinhole\", "), std::string::npos) << *text;
  {
    std::ofstream(dir / "room_saved.json") << *text;
  }
  const auto saved = loadScene(dir / "room_saved.json");
  const auto direct = loadScene(kScenes / "room.json", overrides);
  ASSERT_TRUE(saved && direct) << saved.error() << direct.error();
  EXPECT_TRUE(poseOf(*saved) == poseOf(*direct));
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) EXPECT_EQ(saved->viewProjection.at(r, c), direct->viewProjection.at(r, c));
  }
  // A texture's file moves with the new folder too (the text is not loaded here: only its paths).
  const std::filesystem::path textured = kArtifacts / "view-unit" / "textured.json";
  std::ofstream(textured) << R"({"draws": [{"obj": "meshes/a.obj", "texture": {"file": "textures/t.png", "mipmaps": true}}]})";
  const auto moved = sceneFileText(textured, {}, dir, "");
  ASSERT_TRUE(moved) << moved.error();
  const nlohmann::ordered_json texturedDocument = nlohmann::ordered_json::parse(*moved);
  EXPECT_EQ(texturedDocument["draws"][0]["obj"], "../../meshes/a.obj");
  EXPECT_EQ(texturedDocument["draws"][0]["texture"]["file"], "../../textures/t.png");
  EXPECT_EQ(texturedDocument["draws"][0]["texture"]["mipmaps"], true);
  // Errors are loadScene's lines.
  const auto bad = sceneFileText(kScenes / "room.json", {"draws.7.cull=none"}, dir, "");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("index 7 is out of range"), std::string::npos) << bad.error();
  const auto missing = sceneFileText(kScenes / "no_such.json", {}, dir, "");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("no_such.json: cannot open scene file"), std::string::npos);
}

TEST(ViewPictures, PanesAndFlicker) {
  const auto scene = loadScene(kScenes / "room.json");
  ASSERT_TRUE(scene) << scene.error();
  const auto soft = renderSoftraster(*scene);
  ASSERT_TRUE(soft) << soft.error();
  Frame other = *soft;
  other.rgba[0] ^= 0xff;  // one pixel differs
  const Picture side = composeView(ViewKind::Side, *soft, other, *scene, 0, "exact");
  EXPECT_EQ(side.width, 2 * scene->width);
  EXPECT_EQ(side.height, scene->height);
  ASSERT_EQ(side.panes.size(), 2u);
  EXPECT_EQ(side.panes[1].x, scene->width);
  EXPECT_EQ(side.panes[0].label, "softraster exact");
  EXPECT_EQ(side.rgba[4 * scene->width * 4 + 1], soft->rgba[4 * scene->width * 2 + 1]);  // row 2, left pane
  const Picture diff = composeView(ViewKind::Diff, *soft, other, *scene, 0, "exact");
  EXPECT_EQ(diff.rgba, diffHeatmap(*soft, other, *scene));  // the report's colours
  const Picture depth = composeView(ViewKind::Depth, *soft, other, *scene, 0, "exact");
  EXPECT_EQ(depth.width, 2 * scene->width);
  ASSERT_EQ(depth.rgba.size(), std::size_t{2} * scene->width * scene->height * 4);
  const auto [lo, hi] = sharedDepthRange(*soft, other, scene->clearDepth);
  const std::vector<std::uint8_t> grey = depthToGrey(soft->depth, scene->clearDepth, lo, hi);
  for (std::uint32_t y = 0; y < scene->height; y += 37) {  // the left pane is the softraster depth view, row by row
    for (std::uint32_t x = 0; x < scene->width; x += 13) {
      for (int k = 0; k < 4; ++k) {
        ASSERT_EQ(depth.rgba[(std::size_t{y} * 2 * scene->width + x) * 4 + k], grey[(std::size_t{y} * scene->width + x) * 4 + k])
            << x << "," << y;
      }
    }
  }
  EXPECT_EQ(composeView(ViewKind::DepthDiff, *soft, other, *scene, 0, "exact").rgba, depthDiffHeatmap(*soft, other, *scene));
  EXPECT_FALSE(flickerShowsVulkan(0));
  EXPECT_FALSE(flickerShowsVulkan(kFlickerFrames - 1));
  EXPECT_TRUE(flickerShowsVulkan(kFlickerFrames));
  EXPECT_FALSE(flickerShowsVulkan(2 * kFlickerFrames));
  EXPECT_EQ(composeView(ViewKind::Flicker, *soft, other, *scene, kFlickerFrames, "exact").rgba[0], other.rgba[0]);
}

namespace {

// A Display that keeps what it was shown.
class RecordingDisplay : public Display {
 public:
  KeyInput poll(bool) override { return {}; }
  softraster::Status show(const Picture& picture, const Overlay& overlay) override {
    last = picture;
    lastOverlay = overlay;
    ++shown;
    return {};
  }
  softraster::Result<Picture> screenshot() override { return last; }
  Picture last;
  Overlay lastOverlay;
  int shown = 0;
};

}  // namespace

TEST(ViewLoop, ScriptedWalkThroughTheRoomSavesTheSceneItShows) {
  auto vulkan = openVulkan({});
  ASSERT_TRUE(vulkan) << vulkan.error();
  const std::filesystem::path out = kArtifacts / "view-unit" / "walk";
  std::filesystem::remove_all(out);
  RecordingDisplay display;
  ViewerOptions options;
  options.scene = kScenes / "room.json";
  options.outDir = out;
  options.softraster.threads = 2;
  std::FILE* log = std::tmpfile();
  options.log = log;
  auto viewer = Viewer::create(options, **vulkan, display);
  ASSERT_TRUE(viewer) << viewer.error();
  const auto script = parseScript("key Up 5\nkey Right 3\nkey PageDown 2\nkey W 4\nframe 2\nview diff\n"
                                  "screenshot diff\nmethod exact-scalar\nsave walk\nkey M\nquit\nkey Up 100\n",
                                  "walk.txt");
  ASSERT_TRUE(script) << script.error();
  const softraster::Status run = runScript(**viewer, display, *script);
  ASSERT_TRUE(run) << run.message();
  // 1 first frame + 5 + 3 + 2 + 4 + 2 + view + method + M; nothing after quit.
  EXPECT_EQ(display.shown, 1 + 5 + 3 + 2 + 4 + 2 + 1 + 1 + 1);
  EXPECT_EQ((*viewer)->method(), softraster::kMethods.size() > 2 ? softraster::kMethods[2] : softraster::Method::Exact);
  EXPECT_EQ((*viewer)->view(), ViewKind::Diff);

  // The pose is the steps the keys say; the room is unlit, so W left its light alone.
  Pose expected = roomPose();
  for (int i = 0; i < 5; ++i) applyStep(Action::MoveForward, expected);
  for (int i = 0; i < 3; ++i) applyStep(Action::TurnRight, expected);
  for (int i = 0; i < 2; ++i) applyStep(Action::PitchDown, expected);
  EXPECT_TRUE((*viewer)->pose() == expected);
  EXPECT_EQ((*viewer)->pose().camera.pinhole.yawDegrees, 3 * kTurnStep);
  EXPECT_EQ((*viewer)->pose().camera.pinhole.pitchDegrees, -20 - 2 * kTurnStep);
  EXPECT_EQ((*viewer)->pose().lightPosition, roomPose().lightPosition);

  // The saved scene loads with that pose, its images are beside it, and the log line has the metrics.
  const auto saved = loadScene(out / "walk.json");
  ASSERT_TRUE(saved) << saved.error();
  EXPECT_TRUE(poseOf(*saved) == expected);
  for (const char* file : {"walk.soft.png", "walk.vulkan.png", "walk.diff.png", "diff.png"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(out / file)) << file;
  }
  std::rewind(log);
  std::string lines;
  for (int ch; (ch = std::fgetc(log)) != EOF;) lines += static_cast<char>(ch);
  std::fclose(log);
  EXPECT_NE(lines.find("screenshot " + (out / "diff.png").string() + ": view diff, softraster exact"), std::string::npos)
      << lines;
  EXPECT_NE(lines.find("saved " + (out / "walk.json").string() +
                       ": softraster exact-scalar, coverage mismatches 0, colour max |\xCE\x94| RGBA 0 0 0 0, depth max "
                       "|\xCE\x94| 0; --set camera.position="),
            std::string::npos)
      << lines;
  // The saved scene cross-checks as the viewer showed it, with the method the viewer ended on.
  softraster::ContextOptions shownWith;
  shownWith.method = (*viewer)->method();
  const auto soft = renderSoftraster(*saved, shownWith);
  const auto reference = renderVulkan(*saved, **vulkan);
  ASSERT_TRUE(soft && reference);
  const Comparison c = compareFrames(*soft, *reference, *saved);
  EXPECT_EQ(c.coverageMismatches, (*viewer)->comparison().coverageMismatches);
  EXPECT_EQ(c.colourMaxDelta, (*viewer)->comparison().colourMaxDelta);
  EXPECT_EQ(c.depthMaxDelta, (*viewer)->comparison().depthMaxDelta);
  // The status names the metrics and both frame times.
  ASSERT_GE(display.lastOverlay.status.size(), 4u);
  EXPECT_NE(display.lastOverlay.status[1].find("softraster "), std::string::npos);
  EXPECT_NE(display.lastOverlay.status[1].find("Vulkan "), std::string::npos);
  EXPECT_NE(display.lastOverlay.status[3].find("coverage mismatches 0"), std::string::npos);
  EXPECT_NE(display.lastOverlay.title.find("coverage 0"), std::string::npos);
  viewer->reset();
}

TEST(ViewLoop, TimePlaysAndTheLightMovesInALitSpinningScene) {
  auto vulkan = openVulkan({});
  ASSERT_TRUE(vulkan) << vulkan.error();
  RecordingDisplay display;
  ViewerOptions options;
  options.scene = kScenes / "blinn_phong_obj.json";
  options.outDir = kArtifacts / "view-unit" / "spin";
  options.softraster.threads = 1;
  auto viewer = Viewer::create(options, **vulkan, display);
  ASSERT_TRUE(viewer) << viewer.error();
  const Pose original = (*viewer)->pose();
  // Space plays from its own frame on: 1 + 4 frames, then Space pauses before its frame's step.
  const auto script = parseScript("key Space\nframe 4\nkey Space\nframe 3\nkey A 2\nkey Q\nkey Left\n", "spin.txt");
  ASSERT_TRUE(script) << script.error();
  ASSERT_TRUE(runScript(**viewer, display, *script));
  double time = original.time;
  for (int i = 0; i < 5; ++i) time += kTimeStep;
  EXPECT_EQ((*viewer)->pose().time, time);
  EXPECT_EQ((*viewer)->pose().lightPosition[0], original.lightPosition[0] - kLightStep - kLightStep);
  EXPECT_EQ((*viewer)->pose().lightPosition[1], original.lightPosition[1] - kLightStep);
  EXPECT_NE((*viewer)->pose().camera.lookAt.target, original.camera.lookAt.target);
  EXPECT_EQ((*viewer)->pose().camera.lookAt.eye, original.camera.lookAt.eye);
  EXPECT_TRUE((*viewer)->comparison().passed());
  viewer->reset();
}
