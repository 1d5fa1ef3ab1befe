// The compare command's JSON (see compare_json.hpp).
#include "output/compare_json.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace crosscheck {
namespace {

nlohmann::json sceneJson(const SceneResult& r) {
  auto finite = [](double v) -> nlohmann::json { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  const Comparison none;
  const Comparison& c = r.comparison ? *r.comparison : none;
  const Tolerance& t = r.tolerance;
  nlohmann::json j = {{"scene", r.entry.path.string()},
                      {"passed", r.comparison && c.passed()},
                      {"pixels", c.pixels},
                      {"samples_compared", c.samples},
                      {"coverage_mismatches", c.coverageMismatches},
                      {"colour_max_delta", c.colourMaxDelta},
                      {"colour_unit", c.colourUnit},
                      {"resolved_colour_max_delta", c.resolvedColourMaxDelta},
                      {"colour_mean_delta", c.colourMeanDelta},
                      {"colour_pixels_over", c.colourPixelsOver},
                      {"psnr", finite(c.psnr)},
                      {"depth_max_delta", c.depthMaxDelta},
                      {"depth_pixels_over", c.depthPixelsOver},
                      {"stencil_mismatches", c.stencilMismatches},
                      {"failures", c.failures},
                      {"tolerance",
                       {{"colour", t.colourThreshold},
                        {"depth", t.depthThreshold},
                        {"coverage_mismatches", t.maxCoverageMismatches},
                        {"colour_pixels_over", t.maxColourPixelsOver},
                        {"depth_pixels_over", t.maxDepthPixelsOver}}},
                      {"milliseconds", {{"soft", r.softMilliseconds}, {"vulkan", r.vulkanMilliseconds}}}};
  if (!c.moreColour.empty()) {  // colour attachments 1..
    nlohmann::json more = nlohmann::json::array();
    for (const AttachmentComparison& m : c.moreColour) {
      more.push_back({{"colour_max_delta", m.colourMaxDelta},
                      {"colour_unit", m.colourUnit},
                      {"colour_pixels_over", m.colourPixelsOver}});
    }
    j["more_colour_attachments"] = more;
  }
  if (!r.comparison) j["error"] = r.error;  // not compared (the compare command stops before this)
  return j;
}

}  // namespace

std::string compareJson(const RunResults& run) {
  std::string out;
  for (const SceneResult& r : run.scenes) out += sceneJson(r).dump() + "\n";
  return out;
}

}  // namespace crosscheck
