// builtins_discard: the fragment built-ins gl_FragCoord, gl_FrontFacing and discard
// (softraster/fragment_builtins.hpp). The C++ twin of builtins_discard.vert / .frag; keep the
// three files reading alike. The vertex stage is vertex_color's.
// Deliberately no gl_FragDepth and no texture: it shows which fragments survive and what the
// built-ins read, nothing else.
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

struct BuiltinsDiscard {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 4;  // vColour
  static constexpr bool kReadsFrontFacing = true;  // gl_FrontFacing (also on unfilled polygons' lines and points)
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
    using std::floor;
    const F cx = b.fragCoord.x * 0.25f;
    const F cy = b.fragCoord.y * 0.25f;
    softraster::discardIf(b, lessThan(cx - floor(cx), F(0.5f)) & lessThan(cy - floor(cy), F(0.5f)));
    if (b.frontFacing) {
      return {b.fragCoord.x / 128.0f, b.fragCoord.y / 128.0f, b.fragCoord.z, b.fragCoord.w * 2.0f};
    }
    return {vColour[0], vColour[1], vColour[2], 1.0f - b.fragCoord.z};
  }
};

}  // namespace shaders
