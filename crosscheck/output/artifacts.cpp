// Scene images (see artifacts.hpp).
#include "output/artifacts.hpp"

#include "compare/compare.hpp"
#include "output/image_io.hpp"

#include <algorithm>
#include <cmath>

namespace crosscheck {

std::pair<float, float> sharedDepthRange(const Frame& soft, const Frame& vulkan, float clearDepth) {
  float lo = 1, hi = 0;
  for (const Frame* frame : {&soft, &vulkan}) {
    for (const float z : frame->depth) {
      if (z != clearDepth && std::isfinite(z)) lo = std::min(lo, z), hi = std::max(hi, z);
    }
  }
  if (lo < hi) return {lo, hi};
  if (lo == hi && lo != clearDepth) return {std::min(lo, clearDepth), std::max(lo, clearDepth)};
  return {0.0f, 1.0f};
}

softraster::Status writeSceneImages(const std::filesystem::path& root, const std::filesystem::path& folder,
                                    SceneResult* result, const Scene& scene, const Frame& soft, const Frame& vulkan) {
  const auto [lo, hi] = sharedDepthRange(soft, vulkan, scene.clearDepth);
  result->depthViewRange = {lo, hi};
  result->imageRoot = root;
  result->images.clear();
  softraster::Status status;
  const auto write = [&](const char* kind, const char* file, const Frame& frame, const std::vector<std::uint8_t>& rgba) {
    const std::filesystem::path relative = folder / file;
    status = writePng(root / relative, frame.width, frame.height, rgba);
    if (status) result->images.push_back({kind, relative});
    return status.ok();
  };
  // Stops at the first image that cannot be written (the later ones are not even computed).
  static_cast<void>(write("soft", "soft.png", soft, soft.rgba) && write("vulkan", "vulkan.png", vulkan, vulkan.rgba) &&
                    write("diff", "diff.png", soft, diffHeatmap(soft, vulkan, scene)) &&
                    write("soft.depth", "soft.depth.png", soft, depthToGrey(soft.depth, scene.clearDepth, lo, hi)) &&
                    write("vulkan.depth", "vulkan.depth.png", vulkan, depthToGrey(vulkan.depth, scene.clearDepth, lo, hi)) &&
                    write("depth.diff", "depth.diff.png", soft, depthDiffHeatmap(soft, vulkan, scene)));
  return status;
}

softraster::Status writeCompareImages(const std::filesystem::path& dir, const Scene& scene, const Frame& soft,
                                      const Frame& vulkan) {
  softraster::Status written = writePng(dir / "soft.png", soft.width, soft.height, soft.rgba);
  if (written) written = writePng(dir / "vulkan.png", vulkan.width, vulkan.height, vulkan.rgba);
  if (written) written = writePng(dir / "diff.png", soft.width, soft.height, diffHeatmap(soft, vulkan, scene));
  if (written) written = writeDepthView(dir / "soft.depth.png", soft, scene.clearDepth, 0, 0);
  if (written) written = writeDepthView(dir / "vulkan.depth.png", vulkan, scene.clearDepth, 0, 0);
  return written;
}

softraster::Status writeDepthView(const std::filesystem::path& path, const Frame& frame, float clearDepth, float lo,
                                  float hi) {
  return writePng(path, frame.width, frame.height, depthToGrey(frame.depth, clearDepth, lo, hi));
}

}  // namespace crosscheck
