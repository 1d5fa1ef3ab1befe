// colour_outputs: the vertex colour written to four colour attachments at once.
// The C++ twin of colour_outputs.frag (its vertex stage is vertex_color's: vertex_color.vert and
// vertexColorStage); keep the two reading alike. The fragment function returns one colour per
// output location (softraster/shader.hpp's ColourOutputs), so it is shaded on the scalar path.
// Deliberately only arithmetic the GLSL marks precise: each operation rounded on its own.
#pragma once

#include "draw_inputs.hpp"
#include "vertex_color.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct ColourOutputs {
  using Vertex = VertexColorVertex;
  using Uniforms = VertexColor::Uniforms;
  static constexpr int kVaryings = 4;  // vColour
  static constexpr std::array<softraster::VertexAttribute, 2> kAttributes = VertexColor::kAttributes;

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return VertexColor::vertexFrom(mesh, i); }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return VertexColor::uniformsFrom(draw); }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* vColour) {
    return vertexColorStage(u.modelViewProjection, in, vColour);
  }
  static float pointSize(const Uniforms& u, const Vertex&) { return u.pointSize; }

  template <class F>
  static softraster::ColourOutputs<F, 4> fragment(const Uniforms&, const F* vColour) {
    const F r = vColour[0], g = vColour[1], b = vColour[2], a = vColour[3];
    const F one = F(1.0f), four = F(4.0f), two = F(2.0f), half = F(0.5f), quarter = F(0.25f), threeQuarters = F(0.75f);
    return {{
        {r, g, b, a},                                            // outColour
        {one - b, one - g, one - r, a},                          // outComplement
        {r * four - two, g * b, -a, a * half + quarter},         // outWide
        {g * threeQuarters, b * threeQuarters, r * threeQuarters, a * threeQuarters},  // outRotated: c.gbra * 0.75
    }};
  }
};

}  // namespace shaders
