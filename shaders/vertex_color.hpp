// vertex_color: unlit, the vertex colour interpolated across the primitive.
// The C++ twin of vertex_color.vert / vertex_color.frag; keep the three files reading alike.
// The template parameter is the varying's qualifier, as INTERPOLATION is in the GLSL.
// vertexFrom and uniformsFrom say what it reads of a scene's draw (draw_inputs.hpp), for the
// table of shading models (shading_models.hpp); softraster itself needs only the rest.
// Deliberately no lighting and no texture: it is the flat-colour model the first scenes need.
#pragma once

#include "draw_inputs.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct VertexColorVertex {
  softraster::Vec3 position;  // location 0
  softraster::Vec4 colour;    // location 1
};

// The vertex stage: the position through the matrix (the same sum, in the same order, as the
// GLSL; the w column taken as is, inPosition.w == 1) and the colour passed on. Also the vertex
// stage of the built-ins twins (builtins_discard.hpp, builtins_frag_depth.hpp).
inline softraster::Vec4 vertexColorStage(const softraster::Mat4& m, const VertexColorVertex& in, float* vColour) {
  const softraster::Vec4 clip =
      m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
  vColour[0] = in.colour.x;
  vColour[1] = in.colour.y;
  vColour[2] = in.colour.z;
  vColour[3] = in.colour.w;
  return clip;
}

template <softraster::Interpolation Qualifier>
struct VertexColorShader {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
    float pointSize = 1.0f;
  };
  static constexpr int kVaryings = 4;  // vColour
  static constexpr softraster::InterpolationSet<kVaryings> kInterpolation{Qualifier, Qualifier, Qualifier, Qualifier};
  static constexpr std::array<softraster::VertexAttribute, 2> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i], mesh.colours[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return {draw.modelViewProjection, draw.pointSize}; }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* vColour) {
    return vertexColorStage(u.modelViewProjection, in, vColour);
  }

  static float pointSize(const Uniforms& u, const Vertex&) { return u.pointSize; }

  // F: float (one pixel) or softraster::FloatBatch (a block of pixels), as shader.hpp describes.
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F* vColour) {
    return {vColour[0], vColour[1], vColour[2], vColour[3]};
  }
};

using VertexColor = VertexColorShader<softraster::Interpolation::Perspective>;
using VertexColorFlat = VertexColorShader<softraster::Interpolation::Flat>;
using VertexColorNoPerspective = VertexColorShader<softraster::Interpolation::NoPerspective>;

}  // namespace shaders
