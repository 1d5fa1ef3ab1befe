// The course's light model: rows of the table of shading models (shading_models.cpp), from the twin lit.hpp.
#include "shading_model_row.hpp"
#include "lit.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> courseLightModels() {
  static constexpr ShadingModel kRows[] = {
    model<CourseLightVertex>("light_vertex", light_vertex_vert_spirv, light_vertex_frag_spirv),
    model<CourseLightPixel>("light_pixel", light_pixel_vert_spirv, light_pixel_frag_spirv),
    model<CourseLightPixelNoPerspective>("light_pixel_noperspective", light_pixel_noperspective_vert_spirv,
                                         light_pixel_noperspective_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
