// The model with the most varyings: a row of the table of shading models (shading_models.cpp),
// from the twin varyings_64.hpp (64 varying components).
// (A family of its own file so that the fragment built-ins' draw loops compile as three
// translation units, not one that the build waited on alone.)
#include "shading_model_row.hpp"
#include "varyings_64.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> varyingsModels() {
  static constexpr ShadingModel kRows[] = {
      model<Varyings64>("varyings_64", varyings_64_vert_spirv, varyings_64_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
