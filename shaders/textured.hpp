// textured: unlit, the draw's texture sampled at the vertex's texture coordinate (the OBJ's vt or
// the scene's "texcoords"), times the vertex colour. The C++ twin of textured.vert /
// textured.frag; keep the three files reading alike.
// It samples, so it shades in quads (kQuads, softraster/texture.hpp) and its fragment function
// takes FloatBatch only. Uniforms: `gpu` is the push-constant block vkref uploads; the sampler
// travels beside it (vkref binds the same texture at set 1, binding 0).
// Deliberately no lighting: the lit, textured model is lit_textured.
#pragma once

#include "draw_inputs.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>
#include <softraster/texture.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct TexturedVertex {
  softraster::Vec3 position;  // location 0
  softraster::Vec2 texcoord;  // location 1
  softraster::Vec4 colour;    // location 2
};

struct TexturedShader {
  using Vertex = TexturedVertex;
  struct Block {
    softraster::Mat4 modelViewProjection;
  };
  struct Uniforms {
    Block gpu;
    softraster::Sampler2D texture;  // uTexture
  };
  static constexpr bool kQuads = true;
  static constexpr unsigned kMeshInputs = kReadsTexcoords;
  static constexpr int kTextures = 1;
  static constexpr int kVaryings = 6;  // vTexcoord (2), vColour (4)
  static constexpr std::array<softraster::VertexAttribute, 3> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 2, offsetof(Vertex, texcoord)},
      {2, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) {
    return {mesh.positions[i], mesh.texcoords[i], mesh.colours[i]};
  }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return {{draw.modelViewProjection}, draw.textures[0]}; }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* out) {
    const softraster::Mat4& m = u.gpu.modelViewProjection;
    const softraster::Vec4 clip =
        m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
    const float values[kVaryings] = {in.texcoord.x, in.texcoord.y, in.colour.x, in.colour.y, in.colour.z, in.colour.w};
    for (int i = 0; i < kVaryings; ++i) out[i] = values[i];
    return clip;
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* v) {
    const softraster::Vec4T<F> t = softraster::texture(u.texture, v[0], v[1]);
    return {t.x * v[2], t.y * v[3], t.z * v[4], t.w * v[5]};
  }
};

}  // namespace shaders
