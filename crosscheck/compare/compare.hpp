// Image comparison of two Frames of one scene, within the scene's Tolerance: the metrics
// (metrics.hpp) and the two difference heatmaps.
// Colour is compared in the format's own steps (bytes; A2B10G10R10's stored 10- and 2-bit values;
// the float formats' units in the last place; not their byte view), so the colour threshold is in
// those steps too.
// Coverage: a sample is covered in a frame when its colour (in any colour attachment), depth or
// stencil differs from the clear values (as each format stores them); a coverage mismatch is a
// pixel whose samples are not covered alike in both frames.
// Stencil (with a depth/stencil format) is compared exactly: a stencil mismatch is a pixel whose
// stored stencil differs in any sample. With MSAA every sample is compared (colour, depth,
// stencil, coverage) and the resolved colour too (metrics.hpp says which metric is which); the
// colour attachments after the first are compared as the first (Comparison::moreColour);
// without, a pixel is its one sample. (A fragment that writes
// exactly the clear colour with depth writes off is invisible to this test.)
// Deliberately no perceptual metric and no position-deviation tolerance: the exact method is
// held to the bit, and edge differences are counted, not forgiven.
#pragma once

#include "compare/metrics.hpp"
#include "render/render.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace crosscheck {

// Measures the differences and checks them against scene.tolerance (limitFailures).
Comparison compareFrames(const Frame& result, const Frame& reference, const Scene& scene);

// What one step of a colour delta is for a target format, as the outputs print it: "8-bit
// steps", "10-bit steps (alpha 2-bit)", "half ULPs" or "float ULPs".
std::string colourDeltaUnit(softraster::ColourFormat format);

// Pixels covered in a frame (in any sample, colour, depth or stencil differs from the scene's clear values).
std::uint64_t coveredPixels(const Frame& frame, const Scene& scene);

// Pixels whose (resolved) colour differs between two frames at all: any byte, or for a wider format
// any stored bit. Frames of different sizes differ in every pixel of the larger.
std::uint64_t colourDifferingPixels(const Frame& a, const Frame& b);

// RGBA8 heatmap of the difference: black where equal, blue up to the colour threshold, red to
// yellow above it by magnitude, magenta where coverage differs.
std::vector<std::uint8_t> diffHeatmap(const Frame& result, const Frame& reference, const Scene& scene);

// RGBA8 heatmap of the depth difference: black where equal, blue up to the depth threshold, red
// to yellow above it (yellow at 2^16 times the threshold and beyond, on a log scale; a threshold
// of 0 counts from 2^-24), magenta
// where one depth is NaN and the other is not.
std::vector<std::uint8_t> depthDiffHeatmap(const Frame& result, const Frame& reference, const Scene& scene);

// RGBA8 view of a frame's stencil (grey = the stored value), and the heatmap of the stencil
// difference: black where equal, magenta where the stored values differ (stencil has no
// tolerance). Both empty for frames without stencil.
std::vector<std::uint8_t> stencilToGrey(const Frame& frame);
std::vector<std::uint8_t> stencilDiffHeatmap(const Frame& result, const Frame& reference);

}  // namespace crosscheck
