// crosscheck view's pictures: what each view (controls.hpp, ViewKind) shows of one frame of both
// renderers, as one RGBA8 image with its panes labelled. Side and Depth put two panes side by
// side (2W x H); the others are one pane (W x H). The heatmaps are the report's own
// (compare.hpp: diffHeatmap, depthDiffHeatmap), the depth views the report's grey over the range
// both frames share (artifacts.hpp, image_io.hpp).
// Deliberately no SDL and no text: the window scales the image and draws the labels.
#pragma once

#include "render/render.hpp"
#include "scene/scene.hpp"
#include "view/controls.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace crosscheck::view {

struct Pane {
  std::uint32_t x = 0;  // left edge in the image
  std::string label;    // "softraster exact", "Vulkan (lavapipe)", ...
};

struct Picture {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  std::vector<Pane> panes;
};

// `frame` counts the frames shown so far (the flicker view's clock); `method` names softraster's
// method in the labels.
Picture composeView(ViewKind view, const Frame& soft, const Frame& vulkan, const Scene& scene, std::uint64_t frame,
                    const std::string& method);

// Whether the flicker view shows Vulkan (else softraster) at `frame`.
bool flickerShowsVulkan(std::uint64_t frame);

}  // namespace crosscheck::view
