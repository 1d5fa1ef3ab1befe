// lit_shadowed: per-pixel Blinn-Phong of the vertex colour in the light of a shadow map: the
// diffuse and specular terms times the light's visibility, from the shadow pass's depth
// (Compare::Sampler: a comparison sampler, GLSL's sampler2DShadow, filtered 0/1 results;
// Compare::Manual: one texel's depth read through a plain sampler2D and compared by hand).
// The C++ twin of lit.vert / lit.frag with SURFACE 3 and 4 (lit.hpp is SURFACE 0); keep them
// reading alike. The position in the shadow pass's clip space is a varying; the fragment divides
// it, maps x and y to texture coordinates (y down, as the pass's rows are) and subtracts the bias
// from its depth before comparing (reference <= the map's depth is lit).
// It samples, so it shades in quads (kQuads) and its fragment function takes FloatBatch only.
// Deliberately one shadow map, Blinn-Phong only, perspective-correct only.
#pragma once

#include "draw_inputs.hpp"
#include "lighting.hpp"
#include "lit.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>
#include <softraster/texture.hpp>

#include <array>
#include <cstddef>

namespace shaders {

enum class Compare { Sampler, Manual };

template <Compare How>
struct LitShadowedShader {
  using Vertex = LitVertex;
  struct Uniforms {
    LightingUniforms gpu;               // the uniform block (set 0, binding 0)
    softraster::Sampler2D shadowMap;    // uShadowMap (set 1, binding 0)
  };
  static constexpr bool kUniformBuffer = true;
  static constexpr bool kQuads = true;
  static constexpr unsigned kMeshInputs = kReadsNormals;
  static constexpr int kTextures = 1;
  // Its texture is a depth pass's depth (draw_inputs.hpp), sampled with or without compare.
  static constexpr ShadowMapSampler kShadowMap =
      How == Compare::Sampler ? ShadowMapSampler::Comparison : ShadowMapSampler::Plain;
  // vPosition (3), vNormal (3), vColour (4), vShadow (4).
  static constexpr int kVaryings = 14;
  static constexpr std::array<softraster::VertexAttribute, 3> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 3, offsetof(Vertex, normal)},
      {2, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i], mesh.normals[i], mesh.colours[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) {
    return {lightingUniformsFrom(draw, LightingSpace::Camera), draw.textures[0]};
  }

  static softraster::Vec4 vertex(const Uniforms& uniforms, const Vertex& in, float* out) {
    const LightingUniforms& u = uniforms.gpu;
    const glsl::Vec3T<float> position = lighting::toLighting(u, in.position);
    const glsl::Vec3T<float> normal = lighting::normalToLighting(u, in.normal);
    const softraster::Vec4 shadow = lighting::toShadow(u, in.position);
    const float values[kVaryings] = {position.x,  position.y,  position.z,  normal.x,    normal.y,
                                     normal.z,    in.colour.x, in.colour.y, in.colour.z, in.colour.w,
                                     shadow.x,    shadow.y,    shadow.z,    shadow.w};
    for (int i = 0; i < kVaryings; ++i) out[i] = values[i];
    return lighting::toClip(u, in.position);
  }

  static float pointSize(const Uniforms& uniforms, const Vertex&) { return uniforms.gpu.pointSize; }

  template <class F>
  static F visibility(const Uniforms& uniforms, const F* v) {
    const glsl::Vec3T<F> p = glsl::Vec3T<F>{v[10], v[11], v[12]} / v[13];
    const F s = p.x * F(0.5f) + F(0.5f);
    const F t = p.y * F(0.5f) + F(0.5f);
    const F reference = p.z - F(uniforms.gpu.shadow.x);
    if constexpr (How == Compare::Sampler) {
      return softraster::textureShadow(uniforms.shadowMap, s, t, reference);
    } else {
      const F depth = softraster::texture(uniforms.shadowMap, s, t).x;
      return glsl::selectLessEqual(reference, depth, F(1.0f), F(0.0f));
    }
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& uniforms, const F* v) {
    const glsl::Vec3T<F> c = lighting::phongLightVisible<true, F>(uniforms.gpu, {v[0], v[1], v[2]}, {v[3], v[4], v[5]},
                                                                 {v[6], v[7], v[8]}, visibility(uniforms, v));
    return {c.x, c.y, c.z, v[9]};
  }
};

using BlinnPhongShadowed = LitShadowedShader<Compare::Sampler>;
using BlinnPhongShadowedManual = LitShadowedShader<Compare::Manual>;

}  // namespace shaders
