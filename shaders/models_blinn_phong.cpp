// Blinn-Phong: rows of the table of shading models (shading_models.cpp), from the twin lit.hpp.
#include "shading_model_row.hpp"
#include "lit.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> blinnPhongModels() {
  static constexpr ShadingModel kRows[] = {
    model<BlinnPhongVertex>("blinn_phong_vertex", blinn_phong_vertex_vert_spirv, blinn_phong_vertex_frag_spirv),
    model<BlinnPhongPixel>("blinn_phong_pixel", blinn_phong_pixel_vert_spirv, blinn_phong_pixel_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
