// How a row of the table of shading models (shading_models.hpp) is made from a C++ twin: the
// template each model family's file (models_*.cpp) instantiates for its twins. Private to
// shaders/: the rows are read through shading_models.hpp.
// Each family has its own file so the heavy instantiations (softraster's draw loop per twin,
// depth format and fragment path) compile in parallel and a change to one family rebuilds only it.
#pragma once

#include "shading_models.hpp"

#include <cstdint>
#include <cstring>
#include <span>

namespace shaders::rows {

template <class Shader>
constexpr bool uniformBufferOf() {
  if constexpr (requires { Shader::kUniformBuffer; }) return Shader::kUniformBuffer;
  return false;
}

template <class Shader>
constexpr unsigned meshInputsOf() {
  if constexpr (requires { Shader::kMeshInputs; }) return Shader::kMeshInputs;
  return 0;
}

template <class Shader>
constexpr unsigned texturesOf() {
  if constexpr (requires { Shader::kTextures; }) return Shader::kTextures;
  return 0;
}

template <class Shader>
constexpr ShadowMapSampler shadowMapOf() {
  if constexpr (requires { Shader::kShadowMap; }) return Shader::kShadowMap;
  return ShadowMapSampler::None;
}

template <class Shader>
constexpr bool depthPassOnlyOf() {
  if constexpr (requires { Shader::kDepthPassOnly; }) return Shader::kDepthPassOnly;
  return false;
}

// What vkref uploads of a twin's uniforms: all of them, or the `gpu` block of a twin whose
// uniforms also carry samplers (those are bound as textures, not copied).
template <class Shader>
struct GpuUniforms {
  using Type = typename Shader::Uniforms;
  static const Type& of(const typename Shader::Uniforms& u) { return u; }
};
template <class Shader>
  requires requires(const typename Shader::Uniforms& u) { u.gpu; }
struct GpuUniforms<Shader> {
  using Type = decltype(Shader::Uniforms::gpu);
  static const Type& of(const typename Shader::Uniforms& u) { return u.gpu; }
};

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
  return bytesOf(&GpuUniforms<Shader>::of(uniforms), 1);
}

template <class Shader>
struct Prepared {
  std::vector<typename Shader::Vertex> vertices;
  typename Shader::Uniforms uniforms;
};

template <class Shader>
softraster::Status drawPrepared(const std::any& prepared, softraster::Pass& pass, const softraster::PipelineState& state,
                                bool indexed, std::span<const std::uint32_t> indices) {
  const auto& p = std::any_cast<const Prepared<Shader>&>(prepared);
  const std::span<const typename Shader::Vertex> vertices(p.vertices);
  return indexed ? pass.drawIndexed<Shader>(state, p.uniforms, vertices, indices)
                 : pass.draw<Shader>(state, p.uniforms, vertices);
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
          sizeof(typename GpuUniforms<Shader>::Type),
          uniformBufferOf<Shader>(),
          meshInputsOf<Shader>(),
          texturesOf<Shader>(),
          shadowMapOf<Shader>(),
          depthPassOnlyOf<Shader>(),
          static_cast<std::uint32_t>(softraster::colourOutputsOf<Shader>()),
          &vertexBytes<Shader>,
          &uniformBytes<Shader>,
          &prepareSoftraster<Shader>};
}

}  // namespace shaders::rows
