// The bench's JSON (see bench_json.hpp).
#include "output/bench_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace crosscheck {
namespace {

using nlohmann::json;

json finite(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json runJson(const BenchRun& run) {
  json j = {{"renderer", run.renderer}, {"threads", run.threads}};
  if (!run.method.empty()) {
    j["method"] = run.method;
    j["affine_varyings"] = run.affineVaryings;
  }
  j["median_ms"] = finite(run.medianMilliseconds);
  j["min_ms"] = finite(run.minMilliseconds);
  j["setup_ms"] = finite(run.setupMilliseconds);
  j["frames_ms"] = run.frameMilliseconds;
  if (run.agreement) {
    const Comparison& c = *run.agreement;
    j["coverage_mismatches"] = c.coverageMismatches;
    j["pixels_differing"] = run.pixelsDiffering;
    j["colour_max_delta"] = *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end());
    j["colour_unit"] = c.colourUnit;
    j["colour_mean_delta"] = finite((c.colourMeanDelta[0] + c.colourMeanDelta[1] + c.colourMeanDelta[2] + c.colourMeanDelta[3]) / 4);
    j["depth_max_delta"] = finite(c.depthMaxDelta);
    j["agrees"] = c.passed();
  } else {
    j["coverage_mismatches"] = nullptr;
    j["pixels_differing"] = nullptr;
    j["colour_max_delta"] = nullptr;
    j["colour_unit"] = nullptr;
    j["colour_mean_delta"] = nullptr;
    j["depth_max_delta"] = nullptr;
    j["agrees"] = nullptr;
  }
  j["ratio_vs_lavapipe"] = run.ratioVsLavapipe > 0 ? finite(run.ratioVsLavapipe) : json(nullptr);
  j["error"] = run.ok() ? json(nullptr) : json(run.error);
  return j;
}

}  // namespace

std::string benchJson(const BenchResults& results) {
  json scenes = json::array();
  for (const BenchScene& scene : results.scenes) {
    json runs = json::array();
    for (const BenchRun& run : scene.runs) runs.push_back(runJson(run));
    scenes.push_back({{"scene", scene.scene.string()},
                      {"description", scene.description},
                      {"width", scene.width},
                      {"height", scene.height},
                      {"samples", scene.samples},
                      {"pixels", scene.pixels},
                      {"triangles", scene.triangles},
                      {"bytes_written", scene.bytesWritten},
                      {"memory_limit_ms", finite(scene.memoryLimitMilliseconds)},
                      {"results", std::move(runs)}});
  }
  const json document = {{"machine",
                          {{"cpu", results.machine.cpu},
                           {"cores", results.machine.cores},
                           {"memset_gb_per_s", finite(results.machine.memsetGigabytesPerSecond)},
                           {"memset_warm_gb_per_s", finite(results.machine.memsetWarmGigabytesPerSecond)},
                           {"allocator", results.machine.allocator}}},
                         {"frames", results.frames},
                         {"warmup", results.warmup},
                         {"threads", results.threads},
                         {"softraster_allow_avx512", results.allowAvx512},
                         {"scenes", std::move(scenes)}};
  return document.dump(2) + "\n";
}

}  // namespace crosscheck
