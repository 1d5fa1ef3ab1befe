// The table of shading models (see shading_models.hpp, whose top comment lists what adding a
// model touches): the rows of every model family (models_*.cpp, made by shading_model_row.hpp),
// in one list.
#include "shading_models.hpp"

#include <vector>

namespace shaders {
namespace rows {
std::span<const ShadingModel> vertexColorModels();
std::span<const ShadingModel> courseLightModels();
std::span<const ShadingModel> phongModels();
std::span<const ShadingModel> blinnPhongModels();
std::span<const ShadingModel> texturedModels();
std::span<const ShadingModel> shadowedModels();
std::span<const ShadingModel> depthModels();
std::span<const ShadingModel> builtinsModels();
std::span<const ShadingModel> builtinsSampleModels();
std::span<const ShadingModel> varyingsModels();
std::span<const ShadingModel> colourOutputsModels();
}  // namespace rows

std::span<const ShadingModel> shadingModels() {
  static const std::vector<ShadingModel> kModels = [] {
    std::vector<ShadingModel> all;
    for (auto family : {rows::vertexColorModels(), rows::courseLightModels(), rows::phongModels(),
                        rows::blinnPhongModels(), rows::texturedModels(), rows::shadowedModels(),
                        rows::depthModels(), rows::builtinsModels(), rows::builtinsSampleModels(),
                        rows::varyingsModels(), rows::colourOutputsModels()}) {
      all.insert(all.end(), family.begin(), family.end());
    }
    return all;
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
