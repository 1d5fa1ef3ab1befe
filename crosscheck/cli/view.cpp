// crosscheck view: a scene in a window, rendered live by softraster and Vulkan (lavapipe), with
// the course's keys or a --script (view/viewer.hpp); see commands.hpp.
// Checks come before the window opens, in the order a user fixes them: the script (one line
// naming the file and line), the scene, then the window (no display: one line), then Vulkan.
#include "cli/commands.hpp"

#include "render/render.hpp"
#include "scene/scene.hpp"
#include "view/script.hpp"
#include "view/viewer.hpp"
#include "view/window.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

namespace crosscheck::cli {

int viewCommand(const ViewCommand& command) {
  const SceneOptions& options = command.options;
  std::vector<view::ScriptCommand> script;
  if (!command.script.empty()) {
    auto loaded = view::loadScript(command.script);
    if (!loaded) return failWith(loaded.status());
    script = std::move(*loaded);
  }
  const auto scene = loadScene(options.scene, options.overrides);
  if (!scene) return failWith(scene.status());

  // lavapipe reads LP_NUM_THREADS when its device is created: --threads N sets it, as bench does.
  unsigned lavapipeThreads = 0;
  if (options.softraster.threads != 0) {
    setenv("LP_NUM_THREADS", std::to_string(options.softraster.threads).c_str(), 1);
    lavapipeThreads = options.softraster.threads;
  } else if (const char* env = std::getenv("LP_NUM_THREADS")) {
    std::from_chars(env, env + std::strlen(env), lavapipeThreads);
  }

  auto window = view::openWindow(scene->width, scene->height, "crosscheck view " + scene->path.filename().string());
  if (!window) return failWith(window.status());
  auto vulkan = openVulkan(options.device);
  if (!vulkan) return failWith(vulkan.status());

  view::ViewerOptions viewerOptions;
  viewerOptions.scene = options.scene;
  viewerOptions.overrides = options.overrides;
  viewerOptions.softraster = options.softraster;
  viewerOptions.lavapipeThreads = lavapipeThreads;
  viewerOptions.outDir = command.outDir;
  softraster::Status status;
  {
    auto viewer = view::Viewer::create(viewerOptions, **vulkan, **window);
    if (!viewer) return failWith(viewer.status());
    status = command.script.empty() ? view::runInteractive(**viewer, **window)
                                    : view::runScript(**viewer, **window, script);
    if (status) std::printf("%s\n", (*viewer)->summary().c_str());
  }  // the viewer's prepared frames go before the renderer
  if (!status) return failWith(status);
  return 0;
}

}  // namespace crosscheck::cli
