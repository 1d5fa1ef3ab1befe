// depth_only: positions to clip space and nothing else, the model of a depth pass (a shadow map).
// The C++ twin of depth_only.vert / depth_only.frag; keep them reading alike.
// Its GLSL fragment stage writes no colour, so it is drawn only where there is no colour to
// write: vkref renders a depth pass with no colour attachment, softraster with colour writes
// masked off (the colour the twin's fragment returns is never stored). The scene loader refuses
// it as a draw's "shading" for the same reason.
#pragma once

#include "draw_inputs.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct DepthOnlyShader {
  struct Vertex {
    softraster::Vec3 position;  // location 0
  };
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
    float pointSize = 1.0f;
  };
  static constexpr int kVaryings = 0;
  static constexpr bool kDepthPassOnly = true;  // no colour: drawn in depth passes only
  static constexpr std::array<softraster::VertexAttribute, 1> kAttributes{{{0, 3, offsetof(Vertex, position)}}};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) { return {draw.modelViewProjection, draw.pointSize}; }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float*) {
    const softraster::Mat4& m = u.modelViewProjection;
    return m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
  }

  static float pointSize(const Uniforms& u, const Vertex&) { return u.pointSize; }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F*) {
    return {F(0.0f), F(0.0f), F(0.0f), F(1.0f)};  // never stored (see the top of this file)
  }
};

}  // namespace shaders
