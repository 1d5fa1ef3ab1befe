// crosscheck view's controls: the keys, what each does, and the pose they edit (the scene's
// camera, light position and time, as the scene file states them). A pose is written back as
// --set overrides of the original scene (poseOverrides), so the viewer renders exactly what
// loadScene makes of those overrides and "save as scene" writes the same change.
// Course-style controls, one step per frame a key is held: arrow keys move forward/back along
// the view direction and turn (yaw), Page Up/Down pitch; W/S, A/D, Q/E move the light along z, x
// and y (y is down, so Q is up); Space plays and pauses time, '.' and ',' step it.
// Deliberately no SDL here: keys are SDL's key names ("Up", "PageUp", "W"), which the window
// maps its key codes to and a key script (script.hpp) spells, so all of this is unit-tested.
#pragma once

#include "scene/scene.hpp"

#include <softraster/options.hpp>

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace crosscheck::view {

// Step sizes, per frame a key is held.
inline constexpr double kMoveStep = 0.02;         // scene units along the view direction
inline constexpr double kTurnStep = 2.0;          // degrees of yaw or pitch
inline constexpr double kMaxPitch = 89.0;         // a pinhole camera's pitch stops at +-89 degrees
inline constexpr double kLightStep = 0.02;        // scene units along x, y or z
inline constexpr double kTimeStep = 1.0 / 30.0;   // seconds of scene time per frame
inline constexpr unsigned kFlickerFrames = 8;     // the flicker view swaps renderers every N frames

// What the keys edit: the scene file's camera settings, light position and time.
struct Pose {
  CameraSettings camera;
  std::array<double, 3> lightPosition{};
  double time = 0;
  bool operator==(const Pose&) const;
};
Pose poseOf(const Scene& scene);

// What the window shows (views.hpp composes each).
enum class ViewKind { Side, Soft, Vulkan, Diff, Flicker, Depth, DepthDiff };
inline constexpr std::array kViews{ViewKind::Side, ViewKind::Soft,  ViewKind::Vulkan,   ViewKind::Diff,
                                   ViewKind::Flicker, ViewKind::Depth, ViewKind::DepthDiff};
std::string_view viewName(ViewKind view);            // "side", "soft", "vulkan", "diff", "flicker", "depth", "depth-diff"
std::optional<ViewKind> viewFromName(std::string_view name);
std::string_view viewTitle(ViewKind view);           // "softraster | Vulkan", ... for the overlay

enum class Action {
  MoveForward, MoveBack, TurnLeft, TurnRight, PitchUp, PitchDown,                  // camera, while held
  LightForward, LightBack, LightLeft, LightRight, LightUp, LightDown,              // light, while held
  TimeForward, TimeBack,                                                           // time, while held
  PlayPause, NextMethod, ShowView, ToggleHelp, SaveScene, Screenshot, Reset, Quit  // once, when pressed
};
// Whether the action repeats every frame its key is held (else it acts once when pressed).
bool isHeld(Action action);

struct Control {
  std::string_view key;          // SDL's key name
  Action action;
  std::string_view description;  // for --help and the help overlay
  ViewKind view = ViewKind::Side;  // ShowView's view
};
// Every key, in the order --help lists them.
std::span<const Control> controls();
const Control* controlForKey(std::string_view key);  // nullptr: a key that does nothing
// "  Up / Down        move forward / back" lines for --help and the overlay.
std::vector<std::string> controlLines();

// Applies one step of a held action to the pose; false (pose unchanged) where it does not apply
// (a clip_space camera has nothing to move, a pitch past its stop, a look-at turned onto its up).
bool applyStep(Action action, Pose& pose);

// The --set overrides that turn `original`'s pose into `pose`: one per field that differs, in
// the order camera, light, time ("camera.yaw=12", "light.position=[0.1,-0.5,-0.7]", "time=1.5"),
// numbers written so that they read back as the same doubles.
std::vector<std::string> poseOverrides(const Pose& original, const Pose& pose);

// The next method after `method` in softraster::kMethods, wrapping around.
softraster::Method nextMethod(softraster::Method method);

}  // namespace crosscheck::view
