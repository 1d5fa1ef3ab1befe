// The fragment built-in models discard and gl_FragDepth: rows of the table of shading models
// (shading_models.cpp), from the twins builtins_discard.hpp and builtins_frag_depth.hpp.
// (A family of its own file so that the fragment built-ins' draw loops compile as three
// translation units, not one that the build waited on alone.)
#include "builtins_discard.hpp"
#include "builtins_frag_depth.hpp"
#include "shading_model_row.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> builtinsModels() {
  static constexpr ShadingModel kRows[] = {
      model<BuiltinsDiscard>("builtins_discard", builtins_discard_vert_spirv, builtins_discard_frag_spirv),
      model<BuiltinsFragDepth>("builtins_frag_depth", builtins_frag_depth_vert_spirv, builtins_frag_depth_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
