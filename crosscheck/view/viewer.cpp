// crosscheck view's loop (see viewer.hpp).
#include "view/viewer.hpp"

#include "compare/compare.hpp"
#include "output/image_io.hpp"
#include "output/metric_text.hpp"

#include <shading_models.hpp>

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <fstream>
#include <thread>

namespace crosscheck::view {
namespace {

using Clock = std::chrono::steady_clock;
double now() { return std::chrono::duration<double>(Clock::now().time_since_epoch()).count(); }

[[gnu::format(printf, 1, 2)]] std::string format(const char* pattern, ...) {
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  return buffer;
}

int maxOf(const std::array<int, 4>& v) { return *std::max_element(v.begin(), v.end()); }

std::string joined(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : separator) + s;
  return out;
}

// The metrics as `crosscheck compare` spells them.
std::string metricsLine(const Comparison& c) {
  return format("coverage mismatches %llu, colour max %s RGBA %d %d %d %d, depth max %s %s",
                static_cast<unsigned long long>(c.coverageMismatches), kAbsDelta, c.colourMaxDelta[0], c.colourMaxDelta[1],
                c.colourMaxDelta[2], c.colourMaxDelta[3], kAbsDelta, depthText(c.depthMaxDelta).c_str());
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options, vkref::Renderer& vulkan, Display& display)
    : options_(options), vulkan_(vulkan), display_(display), method_(options.softraster.method) {}

Viewer::~Viewer() {
  soft_.reset();
  prepared_.reset();  // before the renderer goes
}

softraster::Result<std::unique_ptr<Viewer>> Viewer::create(const ViewerOptions& options, vkref::Renderer& vulkan,
                                                           Display& display) {
  std::unique_ptr<Viewer> viewer(new Viewer(options, vulkan, display));
  auto scene = loadScene(options.scene, options.overrides);
  if (!scene) return scene.status();
  viewer->original_ = poseOf(*scene);
  for (const Draw& draw : scene->draws) {
    viewer->lit_ = viewer->lit_ || (draw.shading->meshInputs & shaders::kReadsNormals) != 0;
    viewer->animated_ = viewer->animated_ || draw.spins;
  }
  if (const softraster::Status loaded = viewer->load(viewer->original_); !loaded) return loaded;
  return viewer;
}

std::vector<std::string> Viewer::overrides() const {
  std::vector<std::string> all = options_.overrides;
  for (std::string& o : poseOverrides(original_, pose_)) all.push_back(std::move(o));
  return all;
}

softraster::Status Viewer::load(const Pose& pose) {
  const double start = now();
  std::vector<std::string> all = options_.overrides;
  for (std::string& o : poseOverrides(original_, pose)) all.push_back(std::move(o));
  auto scene = loadScene(options_.scene, all);
  if (!scene) return scene.status();
  soft_.reset();
  prepared_.reset();
  scene_ = std::make_unique<Scene>(std::move(*scene));
  pose_ = pose;
  if (const softraster::Status s = prepareSoftraster(); !s) return s;
  auto prepared = prepareVulkan(*scene_, vulkan_);
  if (!prepared) return prepared.status().prefixed(scene_->path.string());
  prepared_ = std::make_unique<vkref::PreparedFrame>(std::move(*prepared));
  prepareMs_ = (now() - start) * 1e3;
  return {};
}

softraster::Status Viewer::prepareSoftraster() {
  soft_.reset();
  softraster::ContextOptions context = options_.softraster;
  context.method = method_;
  soft_ = std::make_unique<SoftrasterScene>(*scene_, context);
  return {};
}

void Viewer::setMethod(softraster::Method method) {
  if (method == method_) return;
  method_ = method;
  prepareSoftraster();
}

softraster::Status Viewer::frame(const std::vector<std::string>& held, const std::vector<std::string>& pressed) {
  const double start = now();
  if (lastFrameStart_ >= 0) frameMs_ = (start - lastFrameStart_) * 1e3;
  lastFrameStart_ = start;

  bool saveScene = false, takeScreenshot = false;
  Pose pose = pose_;
  for (const std::string& key : pressed) {
    const Control* c = controlForKey(key);
    if (!c) continue;
    switch (c->action) {
      case Action::PlayPause: playing_ = !playing_ && animated_; break;
      case Action::NextMethod: setMethod(nextMethod(method_)); break;
      case Action::ShowView: view_ = c->view; break;
      case Action::ToggleHelp: help_ = !help_; break;
      case Action::SaveScene: saveScene = true; break;
      case Action::Screenshot: takeScreenshot = true; break;
      case Action::Reset: pose = original_; playing_ = false; break;
      case Action::Quit: quit_ = true; break;
      default: break;
    }
  }
  for (const std::string& key : held) {
    const Control* c = controlForKey(key);
    if (!c || !isHeld(c->action)) continue;
    const bool lightKey = c->action >= Action::LightForward && c->action <= Action::LightDown;
    const bool timeKey = c->action == Action::TimeForward || c->action == Action::TimeBack;
    if ((lightKey && !lit_) || (timeKey && !animated_)) continue;  // nothing here reads it: keep the scene as it is
    applyStep(c->action, pose);
  }
  if (playing_) pose.time += kTimeStep;
  const bool poseChanged = !(pose == pose_);
  if (poseChanged) {
    const Pose before = pose_;
    if (const softraster::Status loaded = load(pose); !loaded) {
      message_ = "refused: " + loaded.message();  // e.g. a camera the loader does not accept
      if (const softraster::Status back = load(before); !back) return back;
    }
  }

  if (const softraster::Status s = soft_->render(); !s) return s.prefixed(scene_->path.string());
  softMs_ = soft_->milliseconds();
  const double submitStart = now();
  if (const softraster::Status s = vulkan_.submit(*prepared_); !s) return s.prefixed(scene_->path.string() + ": vulkan");
  vulkanMs_ = (now() - submitStart) * 1e3;
  auto vulkanFrame = readVulkan(*scene_, vulkan_, *prepared_);
  if (!vulkanFrame) return vulkanFrame.status().prefixed(scene_->path.string());
  vulkanFrame_ = std::move(*vulkanFrame);
  softFrame_ = soft_->frame();
  comparison_ = compareFrames(softFrame_, vulkanFrame_, *scene_);
  const Picture picture = composeView(view_, softFrame_, vulkanFrame_, *scene_, frames_, std::string(softraster::methodName(method_)));
  const double shownAt = now();
  readMs_ = (shownAt - submitStart) * 1e3 - vulkanMs_;
  if (const softraster::Status shown = display_.show(picture, overlay()); !shown) return shown;
  showMs_ = (now() - shownAt) * 1e3;
  ++frames_;
  samples_.push_back({softMs_, vulkanMs_, (now() - start) * 1e3, poseChanged});
  if (saveScene) {
    if (const softraster::Status s = save(nextFreeName("view-", ".json")); !s) return s;
  }
  if (takeScreenshot) {
    if (const softraster::Status s = screenshot(nextFreeName("screenshot-", ".png")); !s) return s;
  }
  return {};
}

std::string Viewer::nextFreeName(const char* stem, const char* extension) const {
  for (unsigned n = 1;; ++n) {
    const std::string name = stem + std::to_string(n) + extension;
    std::error_code error;
    if (!std::filesystem::exists(options_.outDir / name, error)) return name;
  }
}

softraster::Status Viewer::save(const std::string& name) {
  using softraster::Status;
  const std::filesystem::path path = options_.outDir / name;
  const std::vector<std::string> all = overrides();
  const std::vector<std::string> pose = poseOverrides(original_, pose_);
  std::string description = "Saved by crosscheck view from " + options_.scene.filename().string();
  description += all.empty() ? " as it is" : " with --set " + joined(all, " --set ");
  description += " (softraster " + std::string(softraster::methodName(method_)) + ": " + metricsLine(comparison_) + ")";
  const std::string original = scene_->description.empty() ? "" : ". The original: " + scene_->description;
  auto text = sceneFileText(options_.scene, all, options_.outDir, description + original);
  if (!text) return text.status();
  std::error_code error;
  std::filesystem::create_directories(options_.outDir, error);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << *text;
    if (!out.flush()) return Status::error(path.string() + ": cannot write the scene file");
  }
  // The file must load as it is: check it now rather than when a suite runs it.
  if (const auto check = loadScene(path); !check) return Status::error("the saved scene does not load: " + check.status().message());
  const std::filesystem::path stem = options_.outDir / path.stem();
  for (const auto& [suffix, rgba] : {std::pair{".soft.png", &softFrame_.rgba}, std::pair{".vulkan.png", &vulkanFrame_.rgba}}) {
    if (Status s = writePng(stem.string() + suffix, scene_->width, scene_->height, *rgba); !s) return s;
  }
  if (Status s = writePng(stem.string() + ".diff.png", scene_->width, scene_->height,
                          diffHeatmap(softFrame_, vulkanFrame_, *scene_));
      !s) {
    return s;
  }
  std::fprintf(options_.log, "saved %s: softraster %s, %s%s%s\n", path.string().c_str(),
               std::string(softraster::methodName(method_)).c_str(), metricsLine(comparison_).c_str(),
               pose.empty() ? "" : "; --set ", joined(pose, " --set ").c_str());
  std::fflush(options_.log);
  message_ = "saved " + path.string();
  return {};
}

softraster::Status Viewer::screenshot(const std::string& name) {
  const std::filesystem::path path = options_.outDir / name;
  auto shot = display_.screenshot();
  if (!shot) return shot.status();
  if (const softraster::Status s = writePng(path, shot->width, shot->height, shot->rgba); !s) return s;
  std::fprintf(options_.log, "screenshot %s: view %s, softraster %s, %s\n", path.string().c_str(),
               std::string(viewName(view_)).c_str(), std::string(softraster::methodName(method_)).c_str(),
               metricsLine(comparison_).c_str());
  std::fflush(options_.log);
  message_ = "screenshot " + path.string();
  return {};
}

unsigned Viewer::softrasterThreads() const {
  return method_ == softraster::Method::ExactScalar ? 1 : soft_->threads();  // the scalar method draws on one thread
}

unsigned Viewer::lavapipeThreads() const {
  return options_.lavapipeThreads != 0 ? options_.lavapipeThreads : std::max(1u, std::thread::hardware_concurrency());
}

std::string Viewer::summary() const {
  std::vector<double> soft, vulkan, busy, moving;
  for (const FrameSample& f : samples_) {
    if (f.poseChanged) {  // a new pose also loads the scene and prepares both renderers again
      moving.push_back(f.frameMs);
      continue;
    }
    soft.push_back(f.softMs);
    vulkan.push_back(f.vulkanMs);
    busy.push_back(f.frameMs);
  }
  const auto median = [](std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
  };
  const double s = median(soft), v = median(vulkan), b = median(busy);
  return format("view: %zu frames (%zu steady) of %s at %ux%u: softraster %s median %.2f ms (%.0f fps, %u thread%s), "
                "Vulkan median %.2f ms (%.0f fps, %u thread%s), whole frame median %.2f ms (%.0f fps)%s",
                samples_.size(), soft.size(), options_.scene.filename().string().c_str(), scene_->width, scene_->height,
                std::string(softraster::methodName(method_)).c_str(), s, s > 0 ? 1e3 / s : 0, softrasterThreads(),
                softrasterThreads() == 1 ? "" : "s", v, v > 0 ? 1e3 / v : 0, lavapipeThreads(),
                lavapipeThreads() == 1 ? "" : "s", b, b > 0 ? 1e3 / b : 0,
                moving.empty() ? ""
                               : format("; %zu frames with a new pose: median %.2f ms", moving.size(), median(moving)).c_str());
}

Overlay Viewer::overlay() const {
  Overlay o;
  const Comparison& c = comparison_;
  const std::string method(softraster::methodName(method_));
  const unsigned softThreads = softrasterThreads(), lavapipeThreads = this->lavapipeThreads();
  const double fps = frameMs_ > 0 ? 1e3 / frameMs_ : 0;
  const bool within = c.passed();
  const std::string sceneName = options_.scene.filename().string();
  o.status.push_back(format("%s %ux%u   view %s (1-7)   method %s (M)   %s   H: help", sceneName.c_str(), scene_->width,
                            scene_->height, std::string(viewName(view_)).c_str(), method.c_str(),
                            animated_ ? format("time %.3f %s (Space)", pose_.time, playing_ ? "playing" : "paused").c_str()
                                      : format("time %.3f", pose_.time).c_str()));
  o.status.push_back(format("softraster %s %.2f ms (%u thread%s)   Vulkan %.2f ms (%u thread%s)", method.c_str(), softMs_,
                            softThreads, softThreads == 1 ? "" : "s", vulkanMs_, lavapipeThreads,
                            lavapipeThreads == 1 ? "" : "s"));
  o.status.push_back(format("frame %.1f ms = %.1f fps   of it: read back + compare %.1f ms, show %.1f ms;  last prepare %.1f ms",
                            frameMs_, fps, readMs_, showMs_, prepareMs_));
  o.status.push_back(format("coverage mismatches %llu   colour max |d| %d %d %d %d   depth max |d| %s   %s",
                            static_cast<unsigned long long>(c.coverageMismatches), c.colourMaxDelta[0], c.colourMaxDelta[1],
                            c.colourMaxDelta[2], c.colourMaxDelta[3], depthText(c.depthMaxDelta).c_str(),
                            within ? "within tolerance" : "OVER TOLERANCE"));
  std::string camera;
  switch (pose_.camera.type) {
    case CameraSettings::Type::Pinhole: {
      const PinholeCamera& p = pose_.camera.pinhole;
      camera = format("camera position %.3f %.3f %.3f  yaw %.1f  pitch %.1f", p.position[0], p.position[1], p.position[2],
                      p.yawDegrees, p.pitchDegrees);
      break;
    }
    case CameraSettings::Type::LookAt: {
      const LookAtCamera& l = pose_.camera.lookAt;
      camera = format("camera eye %.3f %.3f %.3f  target %.3f %.3f %.3f", l.eye[0], l.eye[1], l.eye[2], l.target[0],
                      l.target[1], l.target[2]);
      break;
    }
    case CameraSettings::Type::ClipSpace: camera = "camera clip_space (no camera to move)"; break;
  }
  const auto& lp = pose_.lightPosition;
  o.status.push_back(camera + (lit_ ? format("   light %.3f %.3f %.3f", lp[0], lp[1], lp[2]) : "   light not read (unlit)"));
  o.status.push_back(message_);
  if (help_) {
    o.help.push_back("crosscheck view: keys (H hides this; held keys step once a frame)");
    for (const Control& c : controls()) o.help.push_back(std::string(c.key) + "\t" + std::string(c.description));
  }
  o.title = format("crosscheck view %s: softraster %s %.1f ms | Vulkan %.1f ms | coverage %llu | colour %s %d | depth %s %s | %.0f fps",
                   sceneName.c_str(), method.c_str(), softMs_, vulkanMs_, static_cast<unsigned long long>(c.coverageMismatches),
                   kAbsDelta, maxOf(c.colourMaxDelta), kAbsDelta, depthText(c.depthMaxDelta).c_str(), fps);
  return o;
}

softraster::Status runScript(Viewer& viewer, Display& display, const std::vector<ScriptCommand>& script) {
  bool closed = false;  // the window was closed: the run ends there, as with quit
  const auto step = [&](const std::vector<std::string>& held, const std::vector<std::string>& pressed) -> softraster::Status {
    closed = closed || display.poll(false).closed;
    return closed ? softraster::Status() : viewer.frame(held, pressed);
  };
  softraster::Status status = step({}, {});
  for (const ScriptCommand& c : script) {
    if (!status || closed || viewer.quitRequested()) break;
    switch (c.kind) {
      case ScriptCommand::Kind::Key:
        for (unsigned i = 0; i < c.frames && status && !closed && !viewer.quitRequested(); ++i) {
          status = step({c.key}, i == 0 ? std::vector<std::string>{c.key} : std::vector<std::string>{});
        }
        break;
      case ScriptCommand::Kind::Frame:
        for (unsigned i = 0; i < c.frames && status && !closed; ++i) status = step({}, {});
        break;
      case ScriptCommand::Kind::View: viewer.setView(c.view); status = step({}, {}); break;
      case ScriptCommand::Kind::Method: viewer.setMethod(c.method); status = step({}, {}); break;
      case ScriptCommand::Kind::Screenshot: status = viewer.screenshot(c.name); break;
      case ScriptCommand::Kind::Save: status = viewer.save(c.name); break;
      case ScriptCommand::Kind::Quit: return status;
    }
  }
  return status;
}

softraster::Status runInteractive(Viewer& viewer, Display& display) {
  while (!viewer.quitRequested()) {
    const KeyInput input = display.poll(true);
    if (input.closed) return {};
    if (const softraster::Status s = viewer.frame(input.held, input.pressed); !s) return s;
  }
  return {};
}

}  // namespace crosscheck::view
