// crosscheck compare: one scene with both renderers, compared within its tolerance; prints the
// metrics as text or one JSON object and optionally writes the images (see commands.hpp).
#include "cli/commands.hpp"

#include "compare/compare.hpp"
#include "output/artifacts.hpp"
#include "output/compare_json.hpp"
#include "output/compare_text.hpp"
#include "render/render.hpp"
#include "results/results.hpp"
#include "scene/scene.hpp"

#include <cstdio>

namespace crosscheck::cli {
namespace {

// The one-scene run the writers read.
RunResults resultsOf(const Scene& scene, const Comparison& comparison, const Frame& soft, const Frame& vulkan) {
  RunResults run;
  SceneResult& r = run.scenes.emplace_back();
  r.entry = {scene.path.stem().string(), scene.path};
  r.outcome = r.actual = comparison.passed() ? Outcome::Pass : Outcome::Fail;
  r.loaded = true;
  r.description = scene.description;
  r.width = scene.width;
  r.height = scene.height;
  r.tolerance = scene.tolerance;
  r.comparison = comparison;
  r.softMilliseconds = soft.milliseconds;
  r.vulkanMilliseconds = vulkan.milliseconds;
  return run;
}

}  // namespace

int compareCommand(const CompareCommand& command) {
  const SceneOptions& options = command.options;
  const auto scene = loadScene(options.scene, options.overrides);
  if (!scene) return failWith(scene.status());
  const auto soft = renderSoftraster(*scene, options.softraster);
  if (!soft) return failIn(scene->path, soft.status());
  const auto vulkan = openVulkan(options.device);
  if (!vulkan) return failWith(vulkan.status());
  const auto reference = renderVulkan(*scene, **vulkan);
  if (!reference) return failIn(scene->path, reference.status());
  const Comparison comparison = compareFrames(*soft, *reference, *scene);
  if (!command.outDir.empty()) {
    if (const auto written = writeCompareImages(command.outDir, *scene, *soft, *reference); !written) return failWith(written);
  }
  const RunResults run = resultsOf(*scene, comparison, *soft, *reference);
  std::fputs((command.json ? compareJson(run) : compareText(run)).c_str(), stdout);
  return comparison.passed() ? 0 : 1;
}

}  // namespace crosscheck::cli
