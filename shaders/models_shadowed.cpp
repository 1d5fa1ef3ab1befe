// The shadowed models: rows of the table of shading models (shading_models.cpp), from the twin
// lit_shadowed.hpp (Blinn-Phong in the light of a shadow map, compared in the sampler or by hand).
#include "lit_shadowed.hpp"
#include "shading_model_row.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> shadowedModels() {
  static constexpr ShadingModel kRows[] = {
    model<BlinnPhongShadowed>("blinn_phong_shadowed", blinn_phong_shadowed_vert_spirv, blinn_phong_shadowed_frag_spirv),
    model<BlinnPhongShadowedManual>("blinn_phong_shadowed_manual", blinn_phong_shadowed_manual_vert_spirv,
                                    blinn_phong_shadowed_manual_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
