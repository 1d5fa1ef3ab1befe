// The depth models: rows of the table of shading models (shading_models.cpp), from the twins
// depth_only.hpp (a depth pass's model) and depth_view.hpp (the course's depth-buffer view).
#include "depth_only.hpp"
#include "depth_view.hpp"
#include "shading_model_row.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> depthModels() {
  static constexpr ShadingModel kRows[] = {
    model<DepthOnlyShader>("depth_only", depth_only_vert_spirv, depth_only_frag_spirv),
    model<DepthViewShader>("depth_view", depth_view_vert_spirv, depth_view_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
