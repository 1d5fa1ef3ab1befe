// crosscheck view's loop: a scene rendered live by softraster and by Vulkan (lavapipe) frame after
// frame, compared, and shown through a Display (display.hpp). The keys (controls.hpp) edit a Pose
// (camera, light, time) that is turned into --set overrides of the scene file and loaded again
// (loadScene), so what is shown is exactly what `crosscheck compare SCENE --set ...` renders,
// and "save as scene" writes those overrides into a new scene file (sceneFileText).
// Each frame: softraster's prepared scene (SoftrasterScene) draws once, vkref submits its prepared
// frame once, both are read back and compared (compare.hpp); when the pose or the method changes,
// the scene is loaded again and both are prepared again (timed: "prepare" in the status).
// Deliberately no SDL here (window.hpp) and no argument parsing (cli/view.cpp).
#pragma once

#include "compare/metrics.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"
#include "view/controls.hpp"
#include "view/display.hpp"
#include "view/script.hpp"

#include <softraster/options.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace crosscheck::view {

struct ViewerOptions {
  std::filesystem::path scene;
  std::vector<std::string> overrides;   // --set, applied before the pose's own
  softraster::ContextOptions softraster;
  unsigned lavapipeThreads = 0;         // LP_NUM_THREADS as set, for the status; 0: every core
  std::filesystem::path outDir;         // screenshots and saved scenes
  std::FILE* log = stdout;              // one line per saved scene or screenshot
};

class Viewer {
 public:
  // Loads the scene and prepares both renderers; the error is the loader's or a renderer's line.
  static softraster::Result<std::unique_ptr<Viewer>> create(const ViewerOptions& options, vkref::Renderer& vulkan,
                                                            Display& display);
  ~Viewer();

  // One frame: applies the keys (held: steps; pressed: the one-shot controls), renders both,
  // compares, shows. An error is a renderer's or a writer's line.
  softraster::Status frame(const std::vector<std::string>& held, const std::vector<std::string>& pressed);
  void setView(ViewKind view) { view_ = view; }
  void setMethod(softraster::Method method);
  // Save as scene: OUT/NAME (a .json name) with NAME's stem + .soft.png, .vulkan.png, .diff.png, and one
  // line on the log with the metrics of the frame last shown.
  softraster::Status save(const std::string& name);
  softraster::Status screenshot(const std::string& name);  // OUT/NAME (a .png name)
  bool quitRequested() const { return quit_; }

  const Pose& pose() const { return pose_; }
  const Comparison& comparison() const { return comparison_; }
  ViewKind view() const { return view_; }
  softraster::Method method() const { return method_; }
  std::vector<std::string> overrides() const;  // --set and the pose's
  std::uint64_t frames() const { return frames_; }
  // "view: N frames (M steady) of SCENE at WxH: softraster METHOD median ... ms (fps, threads),
  // Vulkan median ..., whole frame median ...[; K frames with a new pose: median ... ms]": the
  // medians over the frames whose pose did not change, then the whole frame's median over those
  // that loaded and prepared a new pose (the method named is the current one: switch methods
  // mid-run and the medians mix them).
  std::string summary() const;

 private:
  Viewer(const ViewerOptions& options, vkref::Renderer& vulkan, Display& display);
  softraster::Status load(const Pose& pose);      // the scene at `pose`, both renderers prepared
  softraster::Status prepareSoftraster();
  Overlay overlay() const;
  unsigned softrasterThreads() const;
  unsigned lavapipeThreads() const;
  std::string nextFreeName(const char* stem, const char* extension) const;

  ViewerOptions options_;
  vkref::Renderer& vulkan_;
  Display& display_;
  Pose original_, pose_;
  bool lit_ = false, animated_ = false;  // whether any draw reads the light / moves with time
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<SoftrasterScene> soft_;
  std::unique_ptr<vkref::PreparedFrame> prepared_;
  softraster::Method method_ = softraster::Method::Exact;
  ViewKind view_ = ViewKind::Side;
  bool help_ = false, playing_ = false, quit_ = false;
  Frame softFrame_, vulkanFrame_;
  Comparison comparison_;
  double softMs_ = 0, vulkanMs_ = 0, prepareMs_ = 0, frameMs_ = 0, readMs_ = 0, showMs_ = 0;
  struct FrameSample {
    double softMs, vulkanMs, frameMs;  // frameMs: frame() from its start to the picture shown
    bool poseChanged;
  };
  std::vector<FrameSample> samples_;
  double lastFrameStart_ = -1;  // seconds on a steady clock
  std::uint64_t frames_ = 0;
  std::string message_;         // the last save, screenshot or refused step, for the status
};

// Runs a script (script.hpp) on the viewer: one frame first, then the commands.
softraster::Status runScript(Viewer& viewer, Display& display, const std::vector<ScriptCommand>& script);
// Frames from the keyboard until Escape or the window is closed.
softraster::Status runInteractive(Viewer& viewer, Display& display);

}  // namespace crosscheck::view
