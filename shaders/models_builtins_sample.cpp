// The per-sample fragment built-in models: rows of the table of shading models
// (shading_models.cpp), from the twins builtins_sample.hpp (gl_SampleID, gl_SamplePosition) and
// builtins_sample_mask.hpp (gl_SampleMask, gl_SampleMaskIn).
// (A family of its own file so that the fragment built-ins' draw loops compile as three
// translation units, not one that the build waited on alone.)
#include "builtins_sample.hpp"
#include "builtins_sample_mask.hpp"
#include "shading_model_row.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> builtinsSampleModels() {
  static constexpr ShadingModel kRows[] = {
      model<BuiltinsSample>("builtins_sample", builtins_sample_vert_spirv, builtins_sample_frag_spirv),
      model<BuiltinsSampleMask>("builtins_sample_mask", builtins_sample_mask_vert_spirv,
                                builtins_sample_mask_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
