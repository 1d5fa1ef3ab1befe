// The textured models: rows of the table of shading models (shading_models.cpp), from the twin textured.hpp.
#include "shading_model_row.hpp"
#include "textured.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> texturedModels() {
  static constexpr ShadingModel kRows[] = {
    model<TexturedShader>("textured", textured_vert_spirv, textured_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
