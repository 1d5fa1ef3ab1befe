// The bench's JSON: {"machine": {cpu, cores, memset_gb_per_s (from memory: memory_limit_ms's),
// memset_warm_gb_per_s (the buffer in cache), allocator}, "frames", "warmup",
// "threads", "softraster_allow_avx512", "scenes": [{scene, description, width, height, samples,
// pixels, triangles, bytes_written, memory_limit_ms, results: [{renderer, method (softraster
// only), threads, median_ms, min_ms, setup_ms, frames_ms, coverage_mismatches, colour_max_delta,
// depth_max_delta, agrees, ratio_vs_lavapipe, error}]}]}. Agreement fields are null where nothing
// was compared (lavapipe itself, a failed renderer); ratio_vs_lavapipe is lavapipe_median / median
// (> 1: softraster is faster), 1 for lavapipe, null when unknown.
// Reads a BenchResults value (run/bench.hpp) only.
// Deliberately not results.json (the conformance run's record): a bench run is its own document.
#pragma once

#include "run/bench.hpp"

#include <string>

namespace crosscheck {

std::string benchJson(const BenchResults& results);

}  // namespace crosscheck
