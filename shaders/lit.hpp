// lit: the lit shading models, one template over the light model, where it is evaluated and the
// varyings' qualifier. The C++ twin of lit.vert / lit.frag (MODEL, PER_PIXEL, INTERPOLATION);
// keep the three files, and lighting.hpp with lighting.glsl, reading alike.
//   LightModel::Course   the course's omni light (world space): R = rho * (D + N)
//   LightModel::Phong, LightModel::BlinnPhong   ambient + diffuse + specular (camera space)
// PerPixel false: lit per vertex (Gouraud), the colour interpolated; true: the position, normal
// and colour are interpolated and each pixel is lit (with NoPerspective, the course's skew).
// The vertex colour is the surface's colour (the course's rho, Phong's kd); its alpha passes on.
// Deliberately no texture and no second light.
#pragma once

#include "draw_inputs.hpp"
#include "lighting.hpp"

#include <softraster/math.hpp>
#include <softraster/shader.hpp>

#include <array>
#include <cstddef>

namespace shaders {

struct LitVertex {
  softraster::Vec3 position;  // location 0
  softraster::Vec3 normal;    // location 1
  softraster::Vec4 colour;    // location 2
};

enum class LightModel { Course, Phong, BlinnPhong };

template <LightModel Model, bool PerPixel, softraster::Interpolation Qualifier>
struct LitShader {
  using Vertex = LitVertex;
  using Uniforms = LightingUniforms;
  static constexpr bool kUniformBuffer = true;  // too big for push constants
  // Phong and Blinn-Phong per pixel: a long chain of divisions, roots and pow per block, shaded
  // two blocks at a time on the fast path (shader.hpp): the Blinn-Phong quad 12-17% faster. The
  // course's light, without pow, measured 3-8% slower in its room, so it does not.
  static constexpr bool kBlockPairs = PerPixel && Model != LightModel::Course;
  static constexpr unsigned kMeshInputs = kReadsNormals;
  // Per vertex: vColour; per pixel: vPosition (3), vNormal (3), vColour (4).
  static constexpr int kVaryings = PerPixel ? 10 : 4;
  static constexpr softraster::InterpolationSet<kVaryings> kInterpolation = [] {
    softraster::InterpolationSet<kVaryings> all{};
    all.fill(Qualifier);
    return all;
  }();
  static constexpr std::array<softraster::VertexAttribute, 3> kAttributes{{
      {0, 3, offsetof(Vertex, position)},
      {1, 3, offsetof(Vertex, normal)},
      {2, 4, offsetof(Vertex, colour)},
  }};

  static Vertex vertexFrom(const Mesh& mesh, std::size_t i) {
    return {mesh.positions[i], mesh.normals[i], mesh.colours[i]};
  }
  static Uniforms uniformsFrom(const DrawParameters& draw) {
    return lightingUniformsFrom(draw, Model == LightModel::Course ? LightingSpace::World : LightingSpace::Camera);
  }

  template <class F>
  static glsl::Vec3T<F> light(const Uniforms& u, const glsl::Vec3T<F>& position, const glsl::Vec3T<F>& normal,
                              const glsl::Vec3T<F>& colour) {
    if constexpr (Model == LightModel::Course) {
      return lighting::courseLight(u, position, normal, colour);
    } else {
      return lighting::phongLight<Model == LightModel::BlinnPhong>(u, position, normal, colour);
    }
  }

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* out) {
    const glsl::Vec3T<float> position = lighting::toLighting(u, in.position);
    const glsl::Vec3T<float> normal = lighting::normalToLighting(u, in.normal);
    if constexpr (PerPixel) {
      const float values[kVaryings] = {position.x, position.y, position.z, normal.x,        normal.y,
                                       normal.z,   in.colour.x, in.colour.y, in.colour.z, in.colour.w};
      for (int i = 0; i < kVaryings; ++i) out[i] = values[i];
    } else {
      const glsl::Vec3T<float> c = light<float>(u, position, normal, {in.colour.x, in.colour.y, in.colour.z});
      out[0] = c.x;
      out[1] = c.y;
      out[2] = c.z;
      out[3] = in.colour.w;
    }
    return lighting::toClip(u, in.position);
  }

  static float pointSize(const Uniforms& u, const Vertex&) { return u.pointSize; }

  // F: float (one pixel) or softraster::FloatBatch (a block of pixels), as shader.hpp describes.
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* v) {
    if constexpr (PerPixel) {
      const glsl::Vec3T<F> c = light<F>(u, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]});
      return {c.x, c.y, c.z, v[9]};
    } else {
      return {v[0], v[1], v[2], v[3]};
    }
  }
};

using CourseLightVertex = LitShader<LightModel::Course, false, softraster::Interpolation::Perspective>;
using CourseLightPixel = LitShader<LightModel::Course, true, softraster::Interpolation::Perspective>;
using CourseLightPixelNoPerspective = LitShader<LightModel::Course, true, softraster::Interpolation::NoPerspective>;
using PhongVertex = LitShader<LightModel::Phong, false, softraster::Interpolation::Perspective>;
using PhongPixel = LitShader<LightModel::Phong, true, softraster::Interpolation::Perspective>;
using BlinnPhongVertex = LitShader<LightModel::BlinnPhong, false, softraster::Interpolation::Perspective>;
using BlinnPhongPixel = LitShader<LightModel::BlinnPhong, true, softraster::Interpolation::Perspective>;

}  // namespace shaders
