// The table of shading models: one row per model, the one place crosscheck learns which models
// exist (its scene parser looks names up here; both render adapters draw through a row).
// A row holds the name scene files use, the SPIR-V pair compiled from NAME.vert / NAME.frag, the
// vertex layout, uniform size and placement (push constants or a uniform block) of the C++ twin, and functions instantiated from the twin
// by one template (shading_models.cpp) that turn a model-neutral draw (draw_inputs.hpp) into the
// twin's vertices and uniforms: as bytes for Vulkan, as the twin's own types for softraster's
// Context::draw<Shader> / drawIndexed<Shader>.
//
// Adding a shading model touches only:
//   1. shaders/NAME.vert and NAME.frag (GLSL) and NAME.hpp (the C++ twin: softraster's shader
//      contract, softraster/shader.hpp, plus vertexFrom and uniformsFrom, and optionally
//      kUniformBuffer (uniforms in a uniform block) and kMeshInputs (normals));
//   2. shaders/CMakeLists.txt: one compile_shader_pair line;
//   3. a row in its family's shaders/models_FAMILY.cpp (a new family: a new models_FAMILY.cpp,
//      listed in shaders/CMakeLists.txt and in shading_models.cpp);
//   4. scenes/README.md: the name in the `shading` row.
// (A model that reads a mesh attribute or a per-draw value no model read before also adds it to
// draw_inputs.hpp and to what fills it in crosscheck: scene/scene.cpp, render/render.cpp.)
// Deliberately no virtual classes and no registry: the table is a fixed list, a row is data and
// function pointers, and the per-pixel work stays inside softraster's template over the twin.
#pragma once

#include "draw_inputs.hpp"

#include <softraster/framebuffer.hpp>
#include <softraster/pass.hpp>
#include <softraster/pipeline.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>
#include <softraster/status.hpp>

#include <any>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace shaders {

// One draw made ready for softraster by a row: the twin's vertices and uniforms, built before
// the draw is timed, and the twin's Pass::draw / drawIndexed (softraster/pass.hpp).
class SoftrasterDraw {
 public:
  using DrawFunction = softraster::Status (*)(const std::any& prepared, softraster::Pass& pass,
                                              const softraster::PipelineState& state, bool indexed,
                                              std::span<const std::uint32_t> indices);
  SoftrasterDraw(std::any prepared, DrawFunction draw) : prepared_(std::move(prepared)), draw_(draw) {}

  // vkCmdDrawIndexed with `indices` when `indexed`, else vkCmdDraw of every vertex, in `pass`.
  softraster::Status draw(softraster::Pass& pass, const softraster::PipelineState& state, bool indexed,
                          std::span<const std::uint32_t> indices) const {
    return draw_(prepared_, pass, state, indexed, indices);
  }

 private:
  std::any prepared_;
  DrawFunction draw_;
};

struct ShadingModel {
  std::string_view name;                              // as written in scene files ("shading")
  std::span<const std::uint32_t> vertexSpirv;         // NAME.vert, compiled at build
  std::span<const std::uint32_t> fragmentSpirv;       // NAME.frag
  std::span<const softraster::VertexAttribute> attributes;  // the twin's kAttributes
  std::uint32_t vertexStride = 0;                     // sizeof(twin::Vertex), bytes
  std::uint32_t uniformSize = 0;                      // sizeof(twin::Uniforms) (or its `gpu` block), bytes
  bool uniformBuffer = false;  // the uniforms are a uniform block (set 0, binding 0), not push constants
  unsigned meshInputs = 0;     // kReadsNormals...: what the mesh must hold beyond positions and colours
  unsigned textures = 0;       // textures it samples: DrawParameters::textures[0..n-1], set 1 bindings 0..n-1
  ShadowMapSampler shadowMap = ShadowMapSampler::None;  // its one texture is a depth pass's depth, not an image file
  bool depthPassOnly = false;      // writes no colour: drawn only in depth passes (depth_only)
  std::uint32_t colourOutputs = 1;  // fragment output locations 0..n-1: colour attachments it can fill
  // Vulkan: the mesh as twin::Vertex, vertexStride bytes per vertex; the uniforms as twin::Uniforms.
  std::vector<std::byte> (*vertexBytes)(const Mesh& mesh) = nullptr;
  std::vector<std::byte> (*uniformBytes)(const DrawParameters& draw) = nullptr;
  // softraster: the same vertices and uniforms in the twin's types, ready to draw.
  SoftrasterDraw (*prepareSoftraster)(const Mesh& mesh, const DrawParameters& draw) = nullptr;
};

// Every model, in the order error messages list them.
std::span<const ShadingModel> shadingModels();

// The model scene files call `name`, or nullptr.
const ShadingModel* findShadingModel(std::string_view name);

// What a draw without "shading" uses.
inline constexpr std::string_view kDefaultShadingModel = "vertex_color";

}  // namespace shaders
