// The stability runner (see stability.hpp).
#include "run/stability.hpp"

#include "render/render.hpp"
#include "run/variants.hpp"
#include "scene/scene.hpp"

#include <exception>

namespace crosscheck {

bool variantPasses(const VariantRun& run) {
  return run.ok() && run.differingPixels && *run.differingPixels == 0 && run.coverageMismatches &&
         *run.coverageMismatches == 0 && (!run.hits || (run.hits->cracks == 0 && run.hits->doubleHits == 0));
}

bool StabilityResults::referencePasses() const {
  for (const StabilityCase& c : cases) {
    if (!c.error.empty()) return false;
    bool found = false;
    for (const VariantRun& run : c.variants.runs) {
      if (run.label != kStabilityReference) continue;
      found = true;
      if (!variantPasses(run)) return false;
    }
    if (!found) return false;
  }
  return true;
}

softraster::Result<StabilityResults> runStability(const std::vector<SceneEntry>& cases, const StabilityOptions& options) {
  auto opened = openVulkan(options.device);
  if (!opened) return opened.status().prefixed("vulkan");
  vkref::Renderer& renderer = **opened;
  const std::vector<Variant> variants = chartVariants(options.softraster);
  VariantOptions variantOptions;
  variantOptions.frames = options.frames;
  variantOptions.countHits = true;
  StabilityResults results;
  results.frames = std::max(1u, options.frames);
  for (std::size_t i = 0; i < cases.size(); ++i) {
    StabilityCase c;
    c.entry = cases[i];
    try {
      const auto scene = loadScene(c.entry.path);
      if (!scene) {
        c.error = scene.error();
      } else {
        c.description = scene->description;
        c.variants = runVariants(*scene, variants, renderer, variantOptions);
        if (!c.variants.lavapipeError.empty()) c.error = c.variants.lavapipeError;
      }
    } catch (const std::exception& e) {
      c.error = std::string("exception: ") + e.what();
    }
    results.cases.push_back(std::move(c));
    if (options.onCase) options.onCase(i, cases.size(), results.cases.back());
  }
  return results;
}

}  // namespace crosscheck
