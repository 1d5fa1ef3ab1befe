// varyings_64: 64 varying components (16 vec4, Vulkan's minimum maxVertexOutputComponents),
// smooth, flat and noperspective in turn (by vec4), summed with weights (i + 1) / 256 in a fixed order. The C++
// twin of varyings_64.vert / .frag; keep the three files reading alike.
// Deliberately nothing but the varyings: it exists to carry softraster::kMaxVaryings components.
#pragma once

#include "draw_inputs.hpp"
#include "vertex_color.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct Varyings64 {
  using Vertex = VertexColorVertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 64;  // v0..v15, one vec4 each
  static constexpr softraster::InterpolationSet<kVaryings> kInterpolation = [] {
    softraster::InterpolationSet<kVaryings> set{};
    constexpr softraster::Interpolation kInTurn[3] = {softraster::Interpolation::Perspective,
                                                      softraster::Interpolation::Flat,
                                                      softraster::Interpolation::NoPerspective};
    for (int i = 0; i < kVaryings; ++i) set[static_cast<std::size_t>(i)] = kInTurn[(i / 4) % 3];
    return set;
  }();
  static constexpr std::array<softraster::VertexAttribute, 2> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i], mesh.colours[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return {draw.modelViewProjection}; }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* v) {
    const softraster::Mat4& m = u.modelViewProjection;
    const softraster::Vec4 clip =
        m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
    const float colour[4] = {in.colour.x, in.colour.y, in.colour.z, in.colour.w};
    for (int i = 0; i < 16; ++i) {  // v_i = inColour rotated by i (xyzw, yzwx, zwxy, wxyz)
      for (int c = 0; c < 4; ++c) v[4 * i + c] = colour[(i + c) % 4];
    }
    return clip;
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F* v) {
    softraster::Vec4T<F> sum{v[0] * (1.0f / 256.0f), v[1] * (1.0f / 256.0f), v[2] * (1.0f / 256.0f),
                             v[3] * (1.0f / 256.0f)};
    for (int i = 1; i < 16; ++i) {
      const float weight = static_cast<float>(i + 1) / 256.0f;  // GLSL's (i + 1).0 / 256.0: exact
      sum.x = sum.x + v[4 * i] * weight;
      sum.y = sum.y + v[4 * i + 1] * weight;
      sum.z = sum.z + v[4 * i + 2] * weight;
      sum.w = sum.w + v[4 * i + 3] * weight;
    }
    return sum;
  }
};

}  // namespace shaders
