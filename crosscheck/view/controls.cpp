// crosscheck view's keys and the pose they edit (see controls.hpp).
#include "view/controls.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace crosscheck::view {
namespace {

constexpr Control kControls[] = {
    {"Up", Action::MoveForward, "move forward (view direction)"},
    {"Down", Action::MoveBack, "move back"},
    {"Left", Action::TurnLeft, "turn left (yaw)"},
    {"Right", Action::TurnRight, "turn right (yaw)"},
    {"PageUp", Action::PitchUp, "look up (pitch)"},
    {"PageDown", Action::PitchDown, "look down (pitch)"},
    {"W", Action::LightForward, "light forward (+z)"},
    {"S", Action::LightBack, "light back (-z)"},
    {"A", Action::LightLeft, "light left (-x)"},
    {"D", Action::LightRight, "light right (+x)"},
    {"Q", Action::LightUp, "light up (-y; y is down)"},
    {"E", Action::LightDown, "light down (+y)"},
    {"Space", Action::PlayPause, "play / pause time (spinning draws)"},
    {".", Action::TimeForward, "time forward one step"},
    {",", Action::TimeBack, "time back one step"},
    {"1", Action::ShowView, "view: softraster | Vulkan side by side", ViewKind::Side},
    {"2", Action::ShowView, "view: softraster", ViewKind::Soft},
    {"3", Action::ShowView, "view: Vulkan (lavapipe)", ViewKind::Vulkan},
    {"4", Action::ShowView, "view: colour difference (report colours)", ViewKind::Diff},
    {"5", Action::ShowView, "view: flicker between softraster and Vulkan", ViewKind::Flicker},
    {"6", Action::ShowView, "view: depth, softraster | Vulkan", ViewKind::Depth},
    {"7", Action::ShowView, "view: depth difference heatmap", ViewKind::DepthDiff},
    {"M", Action::NextMethod, "next softraster method"},
    {"H", Action::ToggleHelp, "show / hide this help"},
    {"F2", Action::SaveScene, "save as scene: OUT/view-N.json + images"},
    {"F12", Action::Screenshot, "screenshot: OUT/screenshot-N.png"},
    {"R", Action::Reset, "back to the scene's camera, light, time"},
    {"Escape", Action::Quit, "quit"},
};

using Vec3 = std::array<double, 3>;
glm::dvec3 toGlm(const Vec3& v) { return {v[0], v[1], v[2]}; }
Vec3 fromGlm(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// v turned by `degrees` about the unit axis k (Rodrigues).
glm::dvec3 rotated(const glm::dvec3& v, const glm::dvec3& k, double degrees) {
  const double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  return v * c + glm::cross(k, v) * s + k * glm::dot(k, v) * (1 - c);
}

// One step of a camera action on a pinhole camera (yaw about y, positive turns right; pitch
// about x, positive looks up; the view direction as camera.cpp makes it).
bool stepPinhole(Action action, PinholeCamera& c) {
  const double yaw = glm::radians(c.yawDegrees), pitch = glm::radians(c.pitchDegrees);
  const glm::dvec3 forward{std::sin(yaw) * std::cos(pitch), -std::sin(pitch), std::cos(yaw) * std::cos(pitch)};
  switch (action) {
    case Action::MoveForward: c.position = fromGlm(toGlm(c.position) + kMoveStep * forward); return true;
    case Action::MoveBack: c.position = fromGlm(toGlm(c.position) - kMoveStep * forward); return true;
    case Action::TurnLeft: c.yawDegrees -= kTurnStep; return true;
    case Action::TurnRight: c.yawDegrees += kTurnStep; return true;
    case Action::PitchUp:
    case Action::PitchDown: {
      const double pitched = c.pitchDegrees + (action == Action::PitchUp ? kTurnStep : -kTurnStep);
      if (std::abs(pitched) > kMaxPitch) return false;
      c.pitchDegrees = pitched;
      return true;
    }
    default: return false;
  }
}

// One step on a look-at camera: eye and target move together; turns swing the target about the
// eye, yaw about `up` (towards the camera's right, cross(forward, up), as camera.cpp makes it),
// pitch about the right axis; never onto the up vector (the scene would be refused).
bool stepLookAt(Action action, LookAtCamera& c) {
  const glm::dvec3 eye = toGlm(c.eye), toTarget = toGlm(c.target) - eye;
  const double distance = glm::length(toTarget);
  const glm::dvec3 forward = toTarget / distance;
  const glm::dvec3 up = glm::normalize(toGlm(c.up));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
  glm::dvec3 direction = toTarget;
  switch (action) {
    case Action::MoveForward:
    case Action::MoveBack: {
      const glm::dvec3 step = (action == Action::MoveForward ? kMoveStep : -kMoveStep) * forward;
      c.eye = fromGlm(eye + step);
      c.target = fromGlm(toGlm(c.target) + step);
      return true;
    }
    case Action::TurnLeft: direction = rotated(toTarget, up, kTurnStep); break;    // cross(up, f) = -right
    case Action::TurnRight: direction = rotated(toTarget, up, -kTurnStep); break;
    case Action::PitchUp: direction = rotated(toTarget, right, kTurnStep); break;  // cross(right, f) is up's side
    case Action::PitchDown: direction = rotated(toTarget, right, -kTurnStep); break;
    default: return false;
  }
  const double angleToUp = glm::degrees(std::acos(std::clamp(glm::dot(glm::normalize(direction), up), -1.0, 1.0)));
  if (angleToUp < 90 - kMaxPitch || angleToUp > 90 + kMaxPitch) return false;
  c.target = fromGlm(eye + direction);
  return true;
}

bool stepLight(Action action, Vec3& p) {
  switch (action) {
    case Action::LightForward: p[2] += kLightStep; return true;
    case Action::LightBack: p[2] -= kLightStep; return true;
    case Action::LightLeft: p[0] -= kLightStep; return true;
    case Action::LightRight: p[0] += kLightStep; return true;
    case Action::LightUp: p[1] -= kLightStep; return true;
    case Action::LightDown: p[1] += kLightStep; return true;
    default: return false;
  }
}

// A number or a vector as JSON that reads back as the same doubles.
std::string jsonOf(double v) { return nlohmann::json(v).dump(); }
std::string jsonOf(const Vec3& v) { return nlohmann::json(v).dump(); }

}  // namespace

bool Pose::operator==(const Pose& o) const {
  if (camera.type != o.camera.type || lightPosition != o.lightPosition || time != o.time) return false;
  const PinholeCamera &p = camera.pinhole, &q = o.camera.pinhole;
  const LookAtCamera &l = camera.lookAt, &m = o.camera.lookAt;
  switch (camera.type) {
    case CameraSettings::Type::Pinhole:
      return p.position == q.position && p.yawDegrees == q.yawDegrees && p.pitchDegrees == q.pitchDegrees;
    case CameraSettings::Type::LookAt: return l.eye == m.eye && l.target == m.target;
    case CameraSettings::Type::ClipSpace: return true;
  }
  return true;
}

Pose poseOf(const Scene& scene) { return {scene.cameraSettings, scene.light.position, scene.time}; }

std::string_view viewName(ViewKind view) {
  switch (view) {
    case ViewKind::Side: return "side";
    case ViewKind::Soft: return "soft";
    case ViewKind::Vulkan: return "vulkan";
    case ViewKind::Diff: return "diff";
    case ViewKind::Flicker: return "flicker";
    case ViewKind::Depth: return "depth";
    case ViewKind::DepthDiff: return "depth-diff";
  }
  return "side";
}

std::optional<ViewKind> viewFromName(std::string_view name) {
  for (ViewKind v : kViews) {
    if (viewName(v) == name) return v;
  }
  return std::nullopt;
}

std::string_view viewTitle(ViewKind view) {
  switch (view) {
    case ViewKind::Side: return "softraster | Vulkan";
    case ViewKind::Soft: return "softraster";
    case ViewKind::Vulkan: return "Vulkan (lavapipe)";
    case ViewKind::Diff: return "colour difference";
    case ViewKind::Flicker: return "flicker";
    case ViewKind::Depth: return "depth: softraster | Vulkan";
    case ViewKind::DepthDiff: return "depth difference";
  }
  return "";
}

bool isHeld(Action action) {
  switch (action) {
    case Action::PlayPause:
    case Action::NextMethod:
    case Action::ShowView:
    case Action::ToggleHelp:
    case Action::SaveScene:
    case Action::Screenshot:
    case Action::Reset:
    case Action::Quit: return false;
    default: return true;
  }
}

std::span<const Control> controls() { return kControls; }

const Control* controlForKey(std::string_view key) {
  for (const Control& c : kControls) {
    if (c.key == key) return &c;
  }
  return nullptr;
}

std::vector<std::string> controlLines() {
  std::vector<std::string> lines;
  for (const Control& c : kControls) {
    std::string key(c.key);
    key.resize(std::max<std::size_t>(key.size(), 10), ' ');
    lines.push_back(key + std::string(c.description));
  }
  return lines;
}

bool applyStep(Action action, Pose& pose) {
  switch (action) {
    case Action::MoveForward:
    case Action::MoveBack:
    case Action::TurnLeft:
    case Action::TurnRight:
    case Action::PitchUp:
    case Action::PitchDown:
      if (pose.camera.type == CameraSettings::Type::Pinhole) return stepPinhole(action, pose.camera.pinhole);
      if (pose.camera.type == CameraSettings::Type::LookAt) return stepLookAt(action, pose.camera.lookAt);
      return false;  // clip_space: positions are clip coordinates, there is no camera
    case Action::TimeForward: pose.time += kTimeStep; return true;
    case Action::TimeBack: pose.time -= kTimeStep; return true;
    default: return stepLight(action, pose.lightPosition);
  }
}

std::vector<std::string> poseOverrides(const Pose& original, const Pose& pose) {
  std::vector<std::string> out;
  if (pose.camera.type == CameraSettings::Type::Pinhole) {
    const PinholeCamera &o = original.camera.pinhole, &p = pose.camera.pinhole;
    if (p.position != o.position) out.push_back("camera.position=" + jsonOf(p.position));
    if (p.yawDegrees != o.yawDegrees) out.push_back("camera.yaw=" + jsonOf(p.yawDegrees));
    if (p.pitchDegrees != o.pitchDegrees) out.push_back("camera.pitch=" + jsonOf(p.pitchDegrees));
  } else if (pose.camera.type == CameraSettings::Type::LookAt) {
    const LookAtCamera &o = original.camera.lookAt, &p = pose.camera.lookAt;
    if (p.eye != o.eye) out.push_back("camera.eye=" + jsonOf(p.eye));
    if (p.target != o.target) out.push_back("camera.target=" + jsonOf(p.target));
  }
  if (pose.lightPosition != original.lightPosition) out.push_back("light.position=" + jsonOf(pose.lightPosition));
  if (pose.time != original.time) out.push_back("time=" + jsonOf(pose.time));
  return out;
}

softraster::Method nextMethod(softraster::Method method) {
  const auto at = std::find(softraster::kMethods.begin(), softraster::kMethods.end(), method);
  if (at == softraster::kMethods.end() || at + 1 == softraster::kMethods.end()) return softraster::kMethods.front();
  return *(at + 1);
}

}  // namespace crosscheck::view
