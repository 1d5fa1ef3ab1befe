// The textured models: rows of the table of shading models (shading_models.cpp), from the twins
// textured.hpp and lit_surface.hpp.
#include "lit_surface.hpp"
#include "shading_model_row.hpp"
#include "textured.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> texturedModels() {
  static constexpr ShadingModel kRows[] = {
    model<TexturedShader>("textured", textured_vert_spirv, textured_frag_spirv),
    model<BlinnPhongTextured>("blinn_phong_textured", blinn_phong_textured_vert_spirv, blinn_phong_textured_frag_spirv),
    model<BlinnPhongNormalMapped>("blinn_phong_normal_mapped", blinn_phong_normal_mapped_vert_spirv,
                                  blinn_phong_normal_mapped_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
