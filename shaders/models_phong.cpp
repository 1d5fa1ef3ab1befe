// Phong: rows of the table of shading models (shading_models.cpp), from the twin lit.hpp.
#include "shading_model_row.hpp"
#include "lit.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> phongModels() {
  static constexpr ShadingModel kRows[] = {
    model<PhongVertex>("phong_vertex", phong_vertex_vert_spirv, phong_vertex_frag_spirv),
    model<PhongPixel>("phong_pixel", phong_pixel_vert_spirv, phong_pixel_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
