// The HTML comparison report: DIR/index.html, one self-contained page (inline CSS and script, no
// network) over the scenes' PNGs in DIR/<scene>/ (written by artifacts.hpp). A summary table of
// every scene, sortable, worst first, with a thumbnail, the error line of a Crash and the counts
// that decide a result, filtered by status, by name and to "only unexpected"; every unexpected
// result listed at the top with thumbnails, and its expectations lines to copy; per scene a
// collapsed section (anchor #scene=NAME) with its scene file, the command that reproduces it,
// softraster, Vulkan and the diff heatmap side by side with a legend, both depth views and their
// difference, flicker, onion skin and wipe, nearest-neighbour zoom and the values of both images
// under the pointer, the description and the tolerance. A section's images are in a <template> until it is first opened, and then
// load lazily, so 100 scenes stay fast; the page's script is needed to see them.
// The value readout reads DIR/<scene>/pixels.js (writePixelData): raw RGBA8 and float depth of
// both frames, zlib-compressed and base64-encoded, loaded with a <script> element because a canvas
// cannot read PNGs back on a page opened from file://.
// With a baseline (an earlier run's results.json, results/baseline.hpp), a line at the top counts
// new failures, fixed scenes and scenes whose metrics changed, each marked in the summary table
// (the changed values too, with the baseline's in their tooltip), in the list at the top and in its
// section, and a filter shows only the scenes that changed.
// When the run drew its scenes' variants (SceneResult::variants, report's default), each section
// has the speed-vs-accuracy panels of output/chart_svg.hpp, a section after the summary the
// overview over every scene with the legend (#chart), and the stability cases (scenes of a
// stability/ folder) a table of case x method with pass or fail and the numbers (#stability).
// The page reads a run's results (results.hpp) only; the pixel data is written from the frames
// while they exist, during the run.
// Deliberately no charting library (inline SVG, no script needed for it), no history beyond one
// baseline and no server.
#pragma once

#include "render/render.hpp"
#include "results/baseline.hpp"
#include "results/results.hpp"

#include <softraster/status.hpp>

#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace crosscheck {

// The text of DIR/<scene>/pixels.js: `crosscheckPixels("name", {w, h, soft, vulkan, softDepth,
// vulkanDepth})`, each buffer zlib-compressed and base64-encoded; depth as little-endian float32.
std::string pixelDataScript(const std::string& sceneName, const Frame& soft, const Frame& vulkan);

// Writes pixelDataScript to root / relative and records it in *result; the error is
// "FILE: cannot write pixel data: reason".
softraster::Status writePixelData(const std::filesystem::path& root, const std::filesystem::path& relative,
                                  SceneResult* result, const Frame& soft, const Frame& vulkan);

// Positions of the results, worst first: Crash, Timeout, Fail, UnexpectedPass, ExpectedFail, Pass,
// Skip; then by coverage mismatches, pixels over the colour and depth thresholds (most first), PSNR
// (lowest first) and name.
std::vector<std::size_t> worstFirst(const std::vector<SceneResult>& results);

// The run to compare with: where its results.json was read, the run, and this run against it.
struct ReportBaseline {
  std::filesystem::path file;
  std::time_t finished = 0;
  RunResults run;
  BaselineComparison versus;  // compareWithBaseline(this run, run)
};

// The arguments of a suite command line that change a render, as `crosscheck compare` takes them
// (--softraster-fma, --softraster-deviations, --device, --set, --validation;
// RunResults::renderArguments), in their order.
std::string renderArgumentsOf(const std::string& commandLine);

// The header shows the counts, the run's time and jobs, when it finished (UTC), its command line
// and the JUnit file; then every unexpected result with thumbnails and the expectations lines
// that would accept them, the filters, and the summary table. Links to scene files and the JUnit
// file are relative to `reportDir` (the folder index.html is written to; empty: absolute).
std::string reportHtml(const RunResults& run, const std::filesystem::path& reportDir = {},
                       const ReportBaseline* baseline = nullptr);

// Writes dir/index.html; the error is "FILE: cannot write report: reason".
softraster::Status writeReport(const std::filesystem::path& dir, const RunResults& run,
                               const ReportBaseline* baseline = nullptr);

}  // namespace crosscheck
