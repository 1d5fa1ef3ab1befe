// crosscheck render: one scene with one renderer, written as a colour PNG and optionally a depth
// view (see commands.hpp); says on stdout which renderer drew it and what it wrote.
#include "cli/commands.hpp"

#include "output/artifacts.hpp"
#include "output/image_io.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <cstdio>

namespace crosscheck::cli {

int renderCommand(const RenderCommand& command) {
  const auto scene = loadScene(command.options.scene, command.options.overrides);
  if (!scene) return failWith(scene.status());
  softraster::Result<std::unique_ptr<vkref::Renderer>> vulkan = std::unique_ptr<vkref::Renderer>();
  if (command.renderer == "vulkan") {
    vulkan = openVulkan(command.options.device);
    if (!vulkan) return failWith(vulkan.status());  // no driver: not about the scene
  }
  const auto frame = command.renderer == "vulkan" ? renderVulkan(*scene, **vulkan)
                                                  : renderSoftraster(*scene, command.options.softraster);
  if (!frame) return failIn(scene->path, frame.status());
  if (const auto written = writePng(command.output, frame->width, frame->height, frame->rgba); !written) {
    return failWith(written);
  }
  if (!command.depthOutput.empty()) {
    const bool ranged = command.depthRange.size() == 2;
    const float lo = ranged ? command.depthRange[0] : 0.0f, hi = ranged ? command.depthRange[1] : 0.0f;
    if (const auto written = writeDepthView(command.depthOutput, *frame, scene->clearDepth, lo, hi); !written) {
      return failWith(written);
    }
  }
  // What was used and what was written, one line on stdout.
  std::string used = "softraster";
  if (command.renderer == "vulkan") {
    used = "Vulkan (" + (*vulkan)->deviceName() + ")";
  } else {
    const softraster::ContextOptions& o = command.options.softraster;
    used += std::string(" (") + std::string(softraster::methodName(o.method)) + ", " +
            (o.threads == 0 ? std::string("every core") : std::to_string(o.threads) + (o.threads == 1 ? " thread" : " threads")) +
            (o.depthMode == softraster::DepthMode::InverseZ ? ", 1/z depth" : "") +
            (o.affineVaryings ? ", affine varyings" : "") +
            (o.deviations == softraster::Deviations::Spec ? ", the spec where lavapipe deviates" : "") + ")";
  }
  std::printf("rendered %s with %s: wrote %s%s\n", command.options.scene.c_str(), used.c_str(), command.output.c_str(),
              command.depthOutput.empty() ? "" : (" and " + command.depthOutput).c_str());
  return 0;
}

}  // namespace crosscheck::cli
