// The text a conformance run prints: one line per scene (as each finishes), the progress line
// for a terminal, the closing summary (failures with their metrics next to the limits, the
// slowest scenes) and the counts line last. The writers read results (results.hpp) and nothing
// else: a run's RunResults, or one SceneResult as it finishes.
// Deliberately returns strings and prints nothing: the command decides where each goes.
#pragma once

#include "results/results.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace crosscheck {

// "Pass            room  (soft 4.77 ms, vulkan 28.68 ms)", "Fail  name: metric value > limit ...".
std::string resultLine(const SceneResult& result);

// What went wrong in a scene, one line: the failed limits with the metric behind each
// ("depth_pixels_over 333 > 0 (depth max |Δ| 1.7881393e-07, threshold 5.9604645e-08)"), the crash error, or why
// an UnexpectedPass is one.
std::string resultDetail(const SceneResult& result);

// "[3/10] failures: 1 elapsed: 12.3s" (no carriage return, no newline).
std::string progressLine(std::size_t done, std::size_t total, std::size_t failures, double elapsedSeconds);

// Failures, expected failures and the `slowest` slowest scenes, each section a heading plus one
// indented line per scene; empty sections are left out. Ends with a newline when not empty.
// A slow scene's line says where its time went: "room  123.45 ms: load 1.20, softraster 10.30
// (draw 4.77), vulkan 80.10 (submit 28.68), compare 2.00, images 30.00" (milliseconds; draw and
// submit are the renderers' timed spans inside their whole calls).
std::string summaryText(const RunResults& run, std::size_t slowest = 5);

// "N passed, N failed", plus ", N skipped" when some were.
std::string countsLine(const Counts& counts);

}  // namespace crosscheck
