// The table of shading models and the template that makes a row from a C++ twin (see
// shading_models.hpp, whose top comment lists what adding a model touches).
#include "shading_models.hpp"

#include "vertex_color.hpp"

#include <cstdint>
#include <cstring>

#include <shaders/all_spirv.h>  // every NAME_vert_spirv / NAME_frag_spirv array (shaders/CMakeLists.txt)

namespace shaders {
namespace {

template <class Shader>
std::vector<typename Shader::Vertex> verticesOf(const Mesh& mesh) {
  std::vector<typename Shader::Vertex> vertices;
  vertices.reserve(mesh.vertexCount());
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) vertices.push_back(Shader::vertexFrom(mesh, i));
  return vertices;
}

template <class T>
std::vector<std::byte> bytesOf(const T* data, std::size_t count) {
  std::vector<std::byte> bytes(sizeof(T) * count);
  if (!bytes.empty()) std::memcpy(bytes.data(), data, bytes.size());
  return bytes;
}

template <class Shader>
std::vector<std::byte> vertexBytes(const Mesh& mesh) {
  const auto vertices = verticesOf<Shader>(mesh);
  return bytesOf(vertices.data(), vertices.size());
}

template <class Shader>
std::vector<std::byte> uniformBytes(const DrawParameters& draw) {
  const typename Shader::Uniforms uniforms = Shader::uniformsFrom(draw);
  return bytesOf(&uniforms, 1);
}

template <class Shader>
struct Prepared {
  std::vector<typename Shader::Vertex> vertices;
  typename Shader::Uniforms uniforms;
};

template <class Shader>
softraster::Status drawPrepared(const std::any& prepared, const softraster::Context& context,
                                const softraster::PipelineState& state, bool indexed,
                                std::span<const std::uint32_t> indices, softraster::Framebuffer& framebuffer) {
  const auto& p = std::any_cast<const Prepared<Shader>&>(prepared);
  const std::span<const typename Shader::Vertex> vertices(p.vertices);
  return indexed ? context.drawIndexed<Shader>(state, p.uniforms, vertices, indices, framebuffer)
                 : context.draw<Shader>(state, p.uniforms, vertices, framebuffer);
}

template <class Shader>
SoftrasterDraw prepareSoftraster(const Mesh& mesh, const DrawParameters& draw) {
  return {Prepared<Shader>{verticesOf<Shader>(mesh), Shader::uniformsFrom(draw)}, &drawPrepared<Shader>};
}

// One row of the table, everything but the name and the SPIR-V taken from the twin `Shader`.
template <class Shader, std::size_t VertexWords, std::size_t FragmentWords>
constexpr ShadingModel model(std::string_view name, const std::uint32_t (&vertexSpirv)[VertexWords],
                   const std::uint32_t (&fragmentSpirv)[FragmentWords]) {
  return {name,
          vertexSpirv,
          fragmentSpirv,
          Shader::kAttributes,
          sizeof(typename Shader::Vertex),
          sizeof(typename Shader::Uniforms),
          &vertexBytes<Shader>,
          &uniformBytes<Shader>,
          &prepareSoftraster<Shader>};
}

// The table: name in scene files, C++ twin, SPIR-V pair (compile_shader_pair's NAME).
constexpr ShadingModel kModels[] = {
    model<VertexColor>("vertex_color", vertex_color_vert_spirv, vertex_color_frag_spirv),
    model<VertexColorFlat>("vertex_color_flat", vertex_color_flat_vert_spirv, vertex_color_flat_frag_spirv),
    model<VertexColorNoPerspective>("vertex_color_noperspective", vertex_color_noperspective_vert_spirv,
                                    vertex_color_noperspective_frag_spirv),
};

}  // namespace

std::span<const ShadingModel> shadingModels() { return kModels; }

const ShadingModel* findShadingModel(std::string_view name) {
  for (const ShadingModel& m : kModels) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

}  // namespace shaders
