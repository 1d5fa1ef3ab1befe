// builtins_frag_depth: gl_FragDepth written from gl_FragCoord (softraster/fragment_builtins.hpp,
// kWritesFragDepth). The C++ twin of builtins_frag_depth.vert / .frag; keep the three files
// reading alike. The vertex stage is vertex_color's.
// Deliberately no discard and no lighting: the depth buffer is what it is about.
#pragma once

#include "draw_inputs.hpp"
#include "vertex_color.hpp"

#include <softraster/fragment_builtins.hpp>
#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cmath>
#include <cstddef>

namespace shaders {

struct BuiltinsFragDepth {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 4;  // vColour
  static constexpr bool kWritesFragDepth = true;
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
    using softraster::floor;
    using softraster::lessThan;
    using softraster::select;
    using std::floor;
    const F cx = b.fragCoord.x * 0.0625f;
    const F stripe = select(lessThan(cx - floor(cx), F(0.5f)), F(0.25f), F(0.0f));
    b.fragDepth = (b.fragCoord.z - 0.8f) * 8.0f + stripe;
    return {vColour[0], vColour[1], vColour[2], vColour[3]};
  }
};

}  // namespace shaders
