// The shading models' names, mesh inputs, texture counts, depth-pass roles and colour outputs as
// the fuzz build's stand-in for the real table (shaders/shading_models.cpp), whose rows instantiate every twin's draw code and take minutes
// to compile: the scene loader only looks a model up by name and asks what its mesh must hold.
// shading_model_names_test.cpp checks in the default build that this list is the real table's.
// Deliberately no SPIR-V and no draw functions: nothing in the fuzz build renders a scene.
#pragma once

#include <draw_inputs.hpp>

#include <string_view>

namespace fuzz {

struct ShadingModelName {
  std::string_view name;
  unsigned meshInputs;
  unsigned textures = 0;  // the textures the model samples ("texture", then "normal_map")
  shaders::ShadowMapSampler shadowMap = shaders::ShadowMapSampler::None;  // samples a depth pass ("shadow_map")
  bool depthPassOnly = false;                                              // depth_only: no colour
  unsigned colourOutputs = 1;                                              // colour_outputs: 4
};

inline constexpr ShadingModelName kShadingModelNames[] = {
    {"vertex_color", 0},
    {"vertex_color_flat", 0},
    {"vertex_color_noperspective", 0},
    {"light_vertex", shaders::kReadsNormals},
    {"light_pixel", shaders::kReadsNormals},
    {"light_pixel_noperspective", shaders::kReadsNormals},
    {"phong_vertex", shaders::kReadsNormals},
    {"phong_pixel", shaders::kReadsNormals},
    {"blinn_phong_vertex", shaders::kReadsNormals},
    {"blinn_phong_pixel", shaders::kReadsNormals},
    {"textured", shaders::kReadsTexcoords, 1},
    {"blinn_phong_textured", shaders::kReadsNormals | shaders::kReadsTexcoords, 1},
    {"blinn_phong_normal_mapped", shaders::kReadsNormals | shaders::kReadsTexcoords | shaders::kReadsTangents, 2},
    {"blinn_phong_shadowed", shaders::kReadsNormals, 1, shaders::ShadowMapSampler::Comparison},
    {"blinn_phong_shadowed_manual", shaders::kReadsNormals, 1, shaders::ShadowMapSampler::Plain},
    {"depth_only", 0, 0, shaders::ShadowMapSampler::None, true},
    {"depth_view", 0},
    {"builtins_discard", 0},
    {"builtins_frag_depth", 0},
    {"builtins_sample", 0},
    {"builtins_sample_mask", 0},
    {"varyings_64", 0},
    {"colour_outputs", 0, 0, shaders::ShadowMapSampler::None, false, 4},
};

}  // namespace fuzz
