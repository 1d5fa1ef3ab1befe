// builtins_sample_mask: the fragment built-ins gl_SampleMask and gl_SampleMaskIn
// (softraster/fragment_builtins.hpp). The C++ twin of builtins_sample_mask.vert / .frag; keep the
// three files reading alike. The vertex stage is vertex_color's. kWritesSampleMask says what
// writing gl_SampleMask says in GLSL.
// Deliberately nothing else: it shows which samples each fragment covered and which it kept.
#pragma once

#include "draw_inputs.hpp"
#include "vertex_color.hpp"

#include <softraster/fragment_builtins.hpp>
#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct BuiltinsSampleMask {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 4;  // vColour
  static constexpr bool kWritesSampleMask = true;  // gl_SampleMask
  static constexpr std::array<softraster::VertexAttribute, 2> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i], mesh.colours[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return {draw.modelViewProjection}; }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* vColour) {
    return vertexColorStage(u.modelViewProjection, in, vColour);  // vertex_color's vertex stage
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F* vColour, softraster::FragmentBuiltins<F>& b) {
    using softraster::toFloat;
    using softraster::toInt;
    const softraster::IntOf<F> column = toInt(b.fragCoord.x);
    const softraster::IntOf<F> row = toInt(b.fragCoord.y);
    b.sampleMask = (column + 3 * row) & 15;
    return {toFloat(b.sampleMaskIn) * 0.0625f, vColour[1], vColour[2], vColour[3]};
  }
};

}  // namespace shaders
