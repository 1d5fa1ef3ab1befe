// Tolerance: how closely softraster and Vulkan must agree on one scene, as its scene file says
// (scenes/README.md, "tolerance"). Its own header so the results of a run can hold the limits
// without the scene itself.
// Deliberately no per-region or per-draw limits: a tolerance belongs to the whole image.
#pragma once

#include <cstdint>

namespace crosscheck {

// A pixel is "over" when any colour channel differs by more than colourThreshold (in the format's
// steps: 8-bit, 10-bit for A2B10G10R10, units in the last place for the float formats) or depth
// by more than depthThreshold; the max* counts are how many such pixels pass.
struct Tolerance {
  int colourThreshold = 1;
  double depthThreshold = 0x1p-24;
  std::uint64_t maxCoverageMismatches = 0;
  std::uint64_t maxColourPixelsOver = 0;
  std::uint64_t maxDepthPixelsOver = 0;
};

}  // namespace crosscheck
