// The record of a scene's variant runs (run/variants.hpp makes it): each method and option's
// frame times and its agreement with lavapipe, and lavapipe's own frame time. Data only, so a
// SceneResult can carry it through results.json, the worker processes and merge.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crosscheck {

// How often each pixel is drawn, counted by drawing the scene again with every draw's shading
// replaced by a constant colour of 1/255 added into a cleared image (blend ONE + ONE, depth test
// and writes off, culling, topology, polygon mode, viewport and scissor as the scene has them):
// the red channel is then the number of fragments that landed on the pixel (up to 255). Counted
// for the variant and for lavapipe, pixel by pixel:
//   cracks:      pixels lavapipe hits and the variant hits not at all (for a closed mesh drawn
//                with back faces culled, lavapipe hits its silhouette once everywhere: the holes
//                along shared edges);
//   doubleHits:  pixels the variant hits more often than lavapipe (along a shared edge, both
//                triangles drawing the pixel; where lavapipe itself draws a pixel twice, e.g.
//                two coplanar quads, only a third hit counts).
// Single-sample scenes only (an MSAA scene's resolved colour is no count).
struct HitCounts {
  std::uint64_t cracks = 0, doubleHits = 0;
  std::uint64_t referenceCovered = 0;  // pixels lavapipe hits at least once
};

struct VariantRun {
  std::string label;
  std::string method;                 // methodName()
  std::string depth;                  // "z" or "1/z"
  std::vector<double> frameMilliseconds;
  double medianMilliseconds = 0;
  // Against lavapipe's frame; absent when either failed.
  std::optional<std::uint64_t> coverageMismatches;
  std::optional<int> colourMaxDelta;  // the largest |Δ| of any channel, 8-bit steps
  std::optional<std::uint64_t> differingPixels;  // pixels whose colour differs at all (colourDifferingPixels)
  std::optional<bool> withinTolerance;  // the scene's limits (compareFrames) held
  std::optional<HitCounts> hits;      // when counted
  std::string error;                  // one line when the variant failed
  bool ok() const { return error.empty(); }
};

struct VariantResults {
  unsigned frames = 0;                // timed frames per variant
  double lavapipeMilliseconds = 0;    // lavapipe's median submit over `frames` frames (0: unknown)
  std::string lavapipeError;          // one line when lavapipe failed
  std::vector<VariantRun> runs;       // one per variant, in chartVariants order
};

}  // namespace crosscheck
