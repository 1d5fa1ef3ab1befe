// The fuzz build's shaders::shadingModels() and findShadingModel(): rows with a name and mesh
// inputs only (shading_model_names.hpp says why). Linked into the fuzz targets instead of the
// shaders library; never into the default build.
#include "shading_model_names.hpp"

#include <shading_models.hpp>

#include <vector>

namespace shaders {

std::span<const ShadingModel> shadingModels() {
  static const std::vector<ShadingModel> kModels = [] {
    std::vector<ShadingModel> rows;
    for (const fuzz::ShadingModelName& m : fuzz::kShadingModelNames) {
      ShadingModel row;
      row.name = m.name;
      row.meshInputs = m.meshInputs;
      row.textures = m.textures;
      row.shadowMap = m.shadowMap;
      row.depthPassOnly = m.depthPassOnly;
      row.colourOutputs = m.colourOutputs;
      rows.push_back(row);
    }
    return rows;
  }();
  return kModels;
}

const ShadingModel* findShadingModel(std::string_view name) {
  for (const ShadingModel& m : shadingModels()) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

}  // namespace shaders
