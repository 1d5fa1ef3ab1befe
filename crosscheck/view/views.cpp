// crosscheck view's pictures of a frame (see views.hpp).
#include "view/views.hpp"

#include "compare/compare.hpp"
#include "output/artifacts.hpp"
#include "output/image_io.hpp"

#include <algorithm>

namespace crosscheck::view {
namespace {

Picture onePane(std::uint32_t w, std::uint32_t h, std::vector<std::uint8_t> rgba, std::string label) {
  Picture p;
  p.width = w;
  p.height = h;
  p.rgba = std::move(rgba);
  p.panes.push_back({0, std::move(label)});
  return p;
}

// Two W x H images next to each other.
Picture twoPanes(std::uint32_t w, std::uint32_t h, const std::vector<std::uint8_t>& left, std::string leftLabel,
                 const std::vector<std::uint8_t>& right, std::string rightLabel) {
  Picture p;
  p.width = 2 * w;
  p.height = h;
  p.rgba.resize(std::size_t{p.width} * h * 4);
  const std::size_t row = std::size_t{w} * 4;
  for (std::uint32_t y = 0; y < h; ++y) {
    std::copy_n(left.begin() + y * row, row, p.rgba.begin() + 2 * y * row);
    std::copy_n(right.begin() + y * row, row, p.rgba.begin() + 2 * y * row + row);
  }
  p.panes.push_back({0, std::move(leftLabel)});
  p.panes.push_back({w, std::move(rightLabel)});
  return p;
}

// Colour with alpha made opaque: the window shows what is stored, not blended over anything.
std::vector<std::uint8_t> opaque(std::vector<std::uint8_t> rgba) {
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
  return rgba;
}

}  // namespace

bool flickerShowsVulkan(std::uint64_t frame) { return (frame / kFlickerFrames) % 2 == 1; }

Picture composeView(ViewKind view, const Frame& soft, const Frame& vulkan, const Scene& scene, std::uint64_t frame,
                    const std::string& method) {
  const std::uint32_t w = soft.width, h = soft.height;
  const std::string softLabel = "softraster " + method, vulkanLabel = "Vulkan (lavapipe)";
  switch (view) {
    case ViewKind::Side: return twoPanes(w, h, opaque(soft.rgba), softLabel, opaque(vulkan.rgba), vulkanLabel);
    case ViewKind::Soft: return onePane(w, h, opaque(soft.rgba), softLabel);
    case ViewKind::Vulkan: return onePane(w, h, opaque(vulkan.rgba), vulkanLabel);
    case ViewKind::Diff:
      return onePane(w, h, diffHeatmap(soft, vulkan, scene), "colour difference (blue within tolerance, red-yellow over, magenta coverage)");
    case ViewKind::Flicker:
      return flickerShowsVulkan(frame) ? onePane(w, h, opaque(vulkan.rgba), "flicker: " + vulkanLabel)
                                       : onePane(w, h, opaque(soft.rgba), "flicker: " + softLabel);
    case ViewKind::Depth: {
      const auto [lo, hi] = sharedDepthRange(soft, vulkan, scene.clearDepth);
      return twoPanes(w, h, depthToGrey(soft.depth, scene.clearDepth, lo, hi), "depth: " + softLabel,  // RGBA grey
                      depthToGrey(vulkan.depth, scene.clearDepth, lo, hi), "depth: " + vulkanLabel);
    }
    case ViewKind::DepthDiff:
      return onePane(w, h, depthDiffHeatmap(soft, vulkan, scene), "depth difference (blue within tolerance, red-yellow over)");
  }
  return {};
}

}  // namespace crosscheck::view
