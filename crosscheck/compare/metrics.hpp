// Comparison: what comparing two frames of a scene measured (coverage, colour and depth
// differences, PSNR, stencil mismatches) and which of the scene's limits it broke. A plain record, so a run's results
// can keep it after the frames are gone; compare.hpp measures it.
// Deliberately no verdict beyond the limits: expectations turn it into an Outcome (run/).
#pragma once

#include "scene/tolerance.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace crosscheck {

// Colour attachment 1.. of a scene with several (Scene::moreColour): its colour compared as
// attachment 0's is (every sample and the resolve), within the same colour threshold in its own
// format's steps.
struct AttachmentComparison {
  std::array<int, 4> colourMaxDelta{};     // per channel R, G, B, A, over every sample and the resolve
  std::string colourUnit = "8-bit steps";  // colourDeltaUnit of its format
  std::uint64_t colourPixelsOver = 0;      // any channel of any sample over the colour threshold
};

// With MSAA every count is over pixels, a pixel counting when any of its samples differs, and
// every maximum is over every sample (colour: also over the resolved colour); the colour mean and
// PSNR are of the resolved colour. `samples` says how many samples per pixel were compared.
struct Comparison {
  std::uint64_t pixels = 0;
  std::uint32_t samples = 1;                 // samples per pixel compared (1, or 4 with MSAA: every one)
  std::uint64_t coverageMismatches = 0;
  // Colour differences are in the format's own steps: 8-bit; of A2B10G10R10 10-bit (alpha 2-bit);
  // of the float formats units in the last place (at most INT_MAX). PSNR is of the byte view.
  std::array<int, 4> colourMaxDelta{};       // per channel R, G, B, A
  std::string colourUnit = "8-bit steps";    // what one step of colourMaxDelta is (colourDeltaUnit, compare.hpp)
  std::array<int, 4> resolvedColourMaxDelta{};  // per channel, of the resolved colour alone (= colourMaxDelta with 1 sample)
  std::array<double, 4> colourMeanDelta{};   // per channel, over all pixels (resolved colour)
  std::uint64_t colourPixelsOver = 0;        // any channel over the colour threshold
  double psnr = 0;                           // over RGB; +inf when identical
  double depthMaxDelta = 0;
  std::uint64_t depthPixelsOver = 0;
  std::uint64_t stencilMismatches = 0;       // pixels whose stored stencil differs in any sample (no tolerance: exact)
  std::vector<AttachmentComparison> moreColour;  // colour attachments 1.. (empty with one attachment)
  std::vector<std::string> failures;         // each "metric value > limit"; empty when passed
  bool passed() const { return failures.empty(); }
};

// The limits of `tolerance` the measured counts exceed, each "metric value > limit", in the order
// coverage_mismatches, colour_pixels_over, depth_pixels_over, then stencil_mismatches (allowed: 0,
// always; stencil values are integers both renderers must agree on exactly), then each later colour
// attachment's colour_pixels_over ("colour_pixels_over (attachment N)", colour_pixels_over's limit).
std::vector<std::string> limitFailures(const Comparison& measured, const Tolerance& tolerance);

}  // namespace crosscheck
