// The fragment built-in models: rows of the table of shading models (shading_models.cpp), from
// the twins builtins_discard.hpp, builtins_frag_depth.hpp, builtins_sample.hpp (gl_SampleID,
// gl_SamplePosition), builtins_sample_mask.hpp (gl_SampleMask, gl_SampleMaskIn) and
// varyings_64.hpp (64 varying components).
#include "builtins_discard.hpp"
#include "builtins_frag_depth.hpp"
#include "builtins_sample.hpp"
#include "builtins_sample_mask.hpp"
#include "shading_model_row.hpp"
#include "varyings_64.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> builtinsModels() {
  static constexpr ShadingModel kRows[] = {
      model<BuiltinsDiscard>("builtins_discard", builtins_discard_vert_spirv, builtins_discard_frag_spirv),
      model<BuiltinsFragDepth>("builtins_frag_depth", builtins_frag_depth_vert_spirv, builtins_frag_depth_frag_spirv),
      model<BuiltinsSample>("builtins_sample", builtins_sample_vert_spirv, builtins_sample_frag_spirv),
      model<BuiltinsSampleMask>("builtins_sample_mask", builtins_sample_mask_vert_spirv,
                                builtins_sample_mask_frag_spirv),
      model<Varyings64>("varyings_64", varyings_64_vert_spirv, varyings_64_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
