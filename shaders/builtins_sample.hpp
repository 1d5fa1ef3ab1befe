// builtins_sample: the per-sample built-ins gl_SampleID and gl_SamplePosition
// (softraster/fragment_builtins.hpp). The C++ twin of builtins_sample.vert / .frag; keep the
// three files reading alike. The vertex stage is vertex_color's. kShadesPerSample says what
// reading gl_SampleID says in GLSL: the shader runs once per covered sample.
// Deliberately nothing else: it shows which sample each invocation was and where it lies.
#pragma once

#include "draw_inputs.hpp"
#include "vertex_color.hpp"

#include <softraster/fragment_builtins.hpp>
#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct BuiltinsSample {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 4;  // vColour
  static constexpr bool kShadesPerSample = true;  // reads gl_SampleID
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
    if (b.sampleId == 3) softraster::discardIf(b, softraster::lessThan(b.fragCoord.y, F(96.0f)));
    return {F(b.samplePosition.x), F(b.samplePosition.y), F(static_cast<float>(b.sampleId) * 0.25f), vColour[3]};
  }
};

}  // namespace shaders
