// The model with several fragment outputs (colour_outputs): a row of the table of shading models
// (shading_models.cpp), from the twin colour_outputs.hpp.
#include "colour_outputs.hpp"
#include "shading_model_row.hpp"

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders::rows {

std::span<const ShadingModel> colourOutputsModels() {
  static constexpr ShadingModel kRows[] = {
      model<ColourOutputs>("colour_outputs", colour_outputs_vert_spirv, colour_outputs_frag_spirv),
  };
  return kRows;
}

}  // namespace shaders::rows
