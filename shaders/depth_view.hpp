// depth_view: the course's depth-buffer view as a shading model: grey near / z, z the distance
// along the view axis (clip w, perspective-correct), white at the near plane, falling off as the
// 1/z depth buffer does. The C++ twin of depth_view.vert / depth_view.frag; keep them reading alike.
// What it shows beside `--depth-out`: that image is the depth buffer itself (z/w, or 1/w for the
// 1/z buffer), this one is a colour every renderer computes the same way and compares as colour.
// Deliberately no remapping range: near / z needs none, and the UNORM store clamps what lies
// in front of the near plane.
#pragma once

#include "draw_inputs.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct DepthViewShader {
  struct Vertex {
    softraster::Vec3 position;  // location 0
  };
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
    float pointSize = 1.0f;
    float nearPlane = 1.0f;
  };
  static constexpr int kVaryings = 1;  // vDepth
  static constexpr std::array<softraster::VertexAttribute, 1> kAttributes{{{0, 3, offsetof(Vertex, position)}}};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) { return {mesh.positions[i]}; }
  static Uniforms uniformsFrom(const DrawParameters& draw) {
    return {draw.modelViewProjection, draw.pointSize, draw.nearPlane};
  }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* vDepth) {
    const softraster::Mat4& m = u.modelViewProjection;
    const softraster::Vec4 clip =
        m.columns[0] * in.position.x + m.columns[1] * in.position.y + m.columns[2] * in.position.z + m.columns[3];
    vDepth[0] = clip.w;
    return clip;
  }

  static float pointSize(const Uniforms& u, const Vertex&) { return u.pointSize; }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* vDepth) {
    const F grey = F(u.nearPlane) / vDepth[0];
    return {grey, grey, grey, F(1.0f)};
  }
};

}  // namespace shaders
