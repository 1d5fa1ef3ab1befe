// lit_surface: per-pixel Phong or Blinn-Phong whose surface colour is the vertex colour times a
// texture (Surface::Textured), and whose normal may also come from a tangent-space normal map
// (Surface::NormalMapped: the map's xyz * 2 - 1 in the frame of the interpolated normal, tangent
// and bitangent = cross(normal, tangent) * tangent.w). The C++ twin of lit.vert / lit.frag with
// SURFACE 1 and 2 (lit.hpp is the twin of SURFACE 0); keep them reading alike.
// It samples, so it shades in quads (kQuads) and its fragment function takes FloatBatch only.
// Tangents come from the mesh (the scene computes them from the texture coordinates, with the
// handedness in w). Deliberately per pixel only, perspective-correct only, and not the course's
// light model (the scenes that need textures light with Phong).
#pragma once

#include "draw_inputs.hpp"
#include "lighting.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>
#include <softraster/texture.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct LitSurfaceVertex {
  softraster::Vec3 position;  // location 0
  softraster::Vec3 normal;    // location 1
  softraster::Vec4 colour;    // location 2
  softraster::Vec2 texcoord;  // location 3
  softraster::Vec4 tangent;   // location 4 (read with a normal map only)
};

enum class Surface { Textured, NormalMapped };

template <bool Blinn, Surface Kind>
struct LitSurfaceShader {
  using Vertex = LitSurfaceVertex;
  struct Uniforms {
    LightingUniforms gpu;  // the uniform block (set 0, binding 0)
    std::array<softraster::Sampler2D, 2> textures;  // uTexture, uNormalMap (set 1, bindings 0 and 1)
  };
  static constexpr bool kNormalMap = Kind == Surface::NormalMapped;
  static constexpr bool kUniformBuffer = true;
  static constexpr bool kQuads = true;
  static constexpr unsigned kMeshInputs = kReadsNormals | kReadsTexcoords | (kNormalMap ? kReadsTangents : 0u);
  static constexpr int kTextures = kNormalMap ? 2 : 1;
  // vPosition (3), vNormal (3), vColour (4), vTexcoord (2), and vTangent (4) with a normal map.
  static constexpr int kVaryings = kNormalMap ? 16 : 12;
  static constexpr std::array<softraster::VertexAttribute, kNormalMap ? 5 : 4> kAttributes = [] {
    std::array<softraster::VertexAttribute, kNormalMap ? 5 : 4> a{{
        {0, 3, offsetof(Vertex, position)},
        {1, 3, offsetof(Vertex, normal)},
        {2, 4, offsetof(Vertex, colour)},
        {3, 2, offsetof(Vertex, texcoord)},
    }};
    if constexpr (kNormalMap) a[4] = {4, 4, offsetof(Vertex, tangent)};
    return a;
  }();

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) {
    return {mesh.positions[i], mesh.normals[i], mesh.colours[i], mesh.texcoords[i],
            kNormalMap ? mesh.tangents[i] : softraster::Vec4{}};
  }
  static Uniforms uniformsFrom(const DrawParameters& draw) {
    return {lightingUniformsFrom(draw, LightingSpace::Camera), draw.textures};
  }

  static softraster::Vec4 vertex(const Uniforms& uniforms, const Vertex& in, float* out) {
    const LightingUniforms& u = uniforms.gpu;
    const glsl::Vec3T<float> position = lighting::toLighting(u, in.position);
    const glsl::Vec3T<float> normal = lighting::normalToLighting(u, in.normal);
    const float values[12] = {position.x, position.y,  position.z,  normal.x,      normal.y,      normal.z,
                              in.colour.x, in.colour.y, in.colour.z, in.colour.w, in.texcoord.x, in.texcoord.y};
    for (int i = 0; i < 12; ++i) out[i] = values[i];
    if constexpr (kNormalMap) {
      const glsl::Vec3T<float> t = lighting::directionToLighting(u, {in.tangent.x, in.tangent.y, in.tangent.z});
      out[12] = t.x;
      out[13] = t.y;
      out[14] = t.z;
      out[15] = in.tangent.w;
    }
    return lighting::toClip(u, in.position);
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& uniforms, const F* v) {
    using glsl::Vec3T;
    const softraster::Vec4T<F> albedo = softraster::texture(uniforms.textures[0], v[10], v[11]);
    const softraster::Vec4T<F> surface{v[6] * albedo.x, v[7] * albedo.y, v[8] * albedo.z, v[9] * albedo.w};
    Vec3T<F> normal{v[3], v[4], v[5]};
    if constexpr (kNormalMap) {
      const Vec3T<F> n = glsl::normalize(normal);
      const Vec3T<F> t = glsl::normalize(Vec3T<F>{v[12], v[13], v[14]});
      const Vec3T<F> b = glsl::cross(n, t) * v[15];
      const softraster::Vec4T<F> map = softraster::texture(uniforms.textures[1], v[10], v[11]);
      const Vec3T<F> m{map.x * F(2.0f) - F(1.0f), map.y * F(2.0f) - F(1.0f), map.z * F(2.0f) - F(1.0f)};
      normal = t * m.x + b * m.y + n * m.z;
    }
    const Vec3T<F> c = lighting::phongLight<Blinn, F>(uniforms.gpu, {v[0], v[1], v[2]}, normal,
                                                      {surface.x, surface.y, surface.z});
    return {c.x, c.y, c.z, surface.w};
  }
};

using BlinnPhongTextured = LitSurfaceShader<true, Surface::Textured>;
using BlinnPhongNormalMapped = LitSurfaceShader<true, Surface::NormalMapped>;

}  // namespace shaders
