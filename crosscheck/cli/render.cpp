// crosscheck render: one scene with one renderer, written as a colour PNG and optionally a depth
// view (see commands.hpp).
#include "cli/commands.hpp"

#include "output/artifacts.hpp"
#include "output/image_io.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <cstdio>

namespace crosscheck::cli {
namespace {

softraster::Result<Frame> renderWith(const RenderCommand& command, const Scene& scene) {
  if (command.renderer == "soft") return renderSoftraster(scene, command.options.softraster);
  const auto vulkan = openVulkan(command.options.device);
  if (!vulkan) return vulkan.status();
  return renderVulkan(scene, **vulkan);
}

int fail(const softraster::Status& status) {
  std::fprintf(stderr, "crosscheck: %s\n", status.message().c_str());
  return 1;
}

}  // namespace

int renderCommand(const RenderCommand& command) {
  const auto scene = loadScene(command.options.scene, command.options.overrides);
  if (!scene) return fail(scene.status());
  const auto frame = renderWith(command, *scene);
  if (!frame) return fail(frame.status());
  if (const auto written = writePng(command.output, frame->width, frame->height, frame->rgba); !written) {
    return fail(written);
  }
  if (!command.depthOutput.empty()) {
    const bool ranged = command.depthRange.size() == 2;
    const float lo = ranged ? command.depthRange[0] : 0.0f, hi = ranged ? command.depthRange[1] : 0.0f;
    if (const auto written = writeDepthView(command.depthOutput, *frame, scene->clearDepth, lo, hi); !written) {
      return fail(written);
    }
  }
  return 0;
}

}  // namespace crosscheck::cli
