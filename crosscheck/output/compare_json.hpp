// The compare command's JSON: one object per scene, one a line, with the metrics, the failed
// limits, the tolerance and both renderers' times ("psnr" is null when the images are identical).
// Reads a run's results (results.hpp) only; the compare command's run has one scene.
// Deliberately not results.json: this is the compare command's established output format.
#pragma once

#include "results/results.hpp"

#include <string>

namespace crosscheck {

std::string compareJson(const RunResults& run);

}  // namespace crosscheck
