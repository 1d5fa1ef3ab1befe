// The unlit vertex_color models: rows of the table of shading models (shading_models.cpp), from the twin vertex_color.hpp.
#include "shading_model_row.hpp"
#include "vertex_color.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> vertexColorModels() {
  static constexpr ShadingModel kRows[] = {
    model<VertexColor>("vertex_color", vertex_color_vert_spirv, vertex_color_frag_spirv),
    model<VertexColorFlat>("vertex_color_flat", vertex_color_flat_vert_spirv, vertex_color_flat_frag_spirv),
    model<VertexColorNoPerspective>("vertex_color_noperspective", vertex_color_noperspective_vert_spirv,
                                    vertex_color_noperspective_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
