// The images of one compared scene, written as PNG files into one folder while its frames exist:
// soft.png, vulkan.png, diff.png (diffHeatmap), soft.depth.png and vulkan.depth.png (both depth
// buffers mapped to grey over one shared range, so equal depths look equal) and depth.diff.png
// (depthDiffHeatmap); with a depth/stencil format also soft.stencil.png, vulkan.stencil.png (grey =
// the stored value) and stencil.diff.png (stencilDiffHeatmap); with several colour attachments,
// for each attachment N after the first, soft.attachmentN.png, vulkan.attachmentN.png and
// attachmentN.diff.png (its resolved colour, and its diffHeatmap); with MSAA, for each sample s as
// stored before the resolve, soft.sampleS.png, vulkan.sampleS.png and sampleS.diff.png (its
// diffHeatmap, coverage of that sample included); the runner's scenes record what was written. Also the compare command's five images (eight with stencil) and the render command's
// depth view.
// Also copying a scene's files to another folder (merge).
// Deliberately PNG only and nothing about how a page shows them (that is report/report.hpp).
#pragma once

#include "render/render.hpp"
#include "results/results.hpp"
#include "scene/scene.hpp"

#include <softraster/status.hpp>

#include <cstdint>
#include <filesystem>
#include <utility>

namespace crosscheck {

// The depth range both depth views use: the smallest and largest depth that differs from the
// clear depth in either frame. When all drawn depths are one value, the range runs from it to the
// clear depth (so the drawing stands out); (0, 1) when nothing was drawn.
std::pair<float, float> sharedDepthRange(const Frame& soft, const Frame& vulkan, float clearDepth);

// Which images a scene gets: all six, or (Compact, for the report) when both frames are
// bit-identical in colour (every attachment), depth and stencil (every sample with MSAA) only
// "preview": preview.png, the colour box-filtered down to
// at most kPreviewSize pixels on its longer side (nothing differs, so there is nothing to look at
// closely, and a suite that passes makes a small report); all six otherwise.
enum class SceneImageSet { All, Compact };
inline constexpr std::uint32_t kPreviewSize = 160;

// Writes the images into root / folder and records them (and the depth range) in *result.
// The error is "FILE: cannot write PNG".
softraster::Status writeSceneImages(const std::filesystem::path& root, const std::filesystem::path& folder,
                                    SceneResult* result, const Scene& scene, const Frame& soft, const Frame& vulkan,
                                    SceneImageSet set = SceneImageSet::All);

// Copies a scene's recorded files (its images and pixel data, from result->imageRoot) to the same
// relative paths under `root` and makes `root` its image root (merge: one report folder over the
// shards' folders). A file already there is replaced; a scene without files is left as it is.
// The error is "FILE: cannot copy to DEST: reason".
softraster::Status copySceneFiles(SceneResult* result, const std::filesystem::path& root);

// The compare command's --out DIR: soft.png, vulkan.png, diff.png, and soft.depth.png and
// vulkan.depth.png each over its own range (depthToGrey's default); no depth difference; with
// stencil also soft.stencil.png, vulkan.stencil.png and stencil.diff.png; with several colour
// attachments soft.attachmentN.png, vulkan.attachmentN.png and attachmentN.diff.png for each after the first.
softraster::Status writeCompareImages(const std::filesystem::path& dir, const Scene& scene, const Frame& soft,
                                      const Frame& vulkan);

// One frame's depth view as grey PNG over [lo, hi] (lo >= hi: the frame's own range).
softraster::Status writeDepthView(const std::filesystem::path& path, const Frame& frame, float clearDepth, float lo,
                                  float hi);

}  // namespace crosscheck
