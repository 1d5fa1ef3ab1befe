// The bench's terminal table: a header line about the machine and the run, then one row per
// scene and renderer (each softraster method run, then lavapipe): frame median and minimum,
// setup, the memory limit of the scene, the ratio to lavapipe, the pixels whose colour differs
// from Vulkan's, the colour mean |Δ| and the agreement with Vulkan (coverage mismatches / colour
// max |Δ| / depth max |Δ|).
// Reads a BenchResults value (run/bench.hpp) only.
// Deliberately plain fixed-width text, no colours and no per-frame numbers (the JSON has them).
#pragma once

#include "run/bench.hpp"

#include <string>

namespace crosscheck {

std::string benchTable(const BenchResults& results);

}  // namespace crosscheck
