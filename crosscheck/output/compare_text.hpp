// The compare command's text: per scene its path and Pass or Fail, then each metric next to its
// limit, both renderers' times and one line per limit that was exceeded.
// Reads a run's results (results.hpp) only; the compare command's run has one scene.
// Deliberately returns a string and prints nothing.
#pragma once

#include "results/results.hpp"

#include <string>

namespace crosscheck {

std::string compareText(const RunResults& run);

}  // namespace crosscheck
