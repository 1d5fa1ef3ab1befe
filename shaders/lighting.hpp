// What the lit shading models share: the uniform block (std140, as lighting.glsl declares it),
// the object-space transforms and the two light models, written over the float type F so the
// vertex stage (float) and the fragment stage (float or FloatBatch) run the same source.
// The C++ twin of lighting.glsl; keep the two reading alike. Built-ins are lavapipe's
// (lavapipe_builtins.hpp).
// Deliberately one light and no attenuation terms beyond the course's 1/(4 pi r^2).
#pragma once

#include "draw_inputs.hpp"
#include "lavapipe_builtins.hpp"

#include <softraster/math.hpp>

namespace shaders {

struct LightingUniforms {
  softraster::Mat4 modelViewProjection;  // object -> clip
  softraster::Mat4 modelToLighting;      // object -> the space light is computed in
  softraster::Mat4 normalToLighting;     // object normals -> that space (columns' xyz used)
  softraster::Vec4 lightPosition;        // in that space; w unused
  softraster::Vec4 lightPower;           // the course's P (RGB), or Phong's light colour
  softraster::Vec4 indirect;             // the course's N, or Phong's ambient light
  softraster::Vec4 specular;             // Phong: specular reflectance (xyz) and shininess (w)
  float pointSize = 1.0f;
  float padding[3] = {};                 // std140: the next matrix starts on 16 bytes
  softraster::Mat4 modelToShadow = softraster::Mat4::identity();  // object -> the shadow pass's clip space
  softraster::Vec4 shadow{};             // x: the depth bias subtracted from the shadow map's reference
};
static_assert(sizeof(LightingUniforms) == 3 * 64 + 4 * 16 + 16 + 64 + 16, "LightingUniforms must match lighting.glsl (std140)");

// Where a model lights: the course's light in world space, Phong's in camera space.
enum class LightingSpace { World, Camera };

inline LightingUniforms lightingUniformsFrom(const DrawParameters& d, LightingSpace space) {
  const bool world = space == LightingSpace::World;
  LightingUniforms u;
  u.modelViewProjection = d.modelViewProjection;
  u.modelToLighting = world ? d.modelToWorld : d.modelToCamera;
  u.normalToLighting = world ? d.normalToWorld : d.normalToCamera;
  u.lightPosition = world ? d.light.positionInWorld : d.light.positionInCamera;
  u.lightPower = world ? d.light.power : d.light.colour;
  u.indirect = world ? d.material.indirect : d.material.ambient;
  u.specular = d.material.specular;
  u.specular.w = d.material.shininess;
  u.pointSize = d.pointSize;
  u.modelToShadow = d.modelToShadow;
  u.shadow.x = d.shadowBias;
  return u;
}

namespace lighting {

using glsl::Vec3T;

inline softraster::Vec4 toClip(const LightingUniforms& u, softraster::Vec3 p) {
  const softraster::Mat4& m = u.modelViewProjection;
  return m.columns[0] * p.x + m.columns[1] * p.y + m.columns[2] * p.z + m.columns[3];
}

inline Vec3T<float> xyz(const softraster::Vec4& v) { return {v.x, v.y, v.z}; }

inline Vec3T<float> toLighting(const LightingUniforms& u, softraster::Vec3 p) {
  const auto& m = u.modelToLighting.columns;
  return xyz(m[0]) * p.x + xyz(m[1]) * p.y + xyz(m[2]) * p.z + xyz(m[3]);
}

inline Vec3T<float> directionToLighting(const LightingUniforms& u, softraster::Vec3 d) {
  const auto& m = u.modelToLighting.columns;
  return xyz(m[0]) * d.x + xyz(m[1]) * d.y + xyz(m[2]) * d.z;
}

inline Vec3T<float> normalToLighting(const LightingUniforms& u, softraster::Vec3 n) {
  const auto& m = u.normalToLighting.columns;
  return xyz(m[0]) * n.x + xyz(m[1]) * n.y + xyz(m[2]) * n.z;
}

template <class F>
Vec3T<F> broadcast(const softraster::Vec4& v) {
  return {F(v.x), F(v.y), F(v.z)};
}

// The course's omni light: R = rho * (D + N), D = P * max(r^.n^, 0) / (4 pi |r|^2).
template <class F>
Vec3T<F> courseLight(const LightingUniforms& u, const Vec3T<F>& position, const Vec3T<F>& normal,
                     const Vec3T<F>& rho) {
  const Vec3T<F> n = glsl::normalize(normal);
  const Vec3T<F> r = broadcast<F>(u.lightPosition) - position;
  const F r2 = glsl::dot(r, r);
  const F cosine = glsl::maxConstant(glsl::dot(glsl::normalize(r), n), 0.0f);
  const Vec3T<F> direct = broadcast<F>(u.lightPower) * cosine / (F(12.566370614359172f) * r2);
  return rho * (direct + broadcast<F>(u.indirect));
}

inline softraster::Vec4 toShadow(const LightingUniforms& u, softraster::Vec3 p) {
  const softraster::Mat4& m = u.modelToShadow;
  return m.columns[0] * p.x + m.columns[1] * p.y + m.columns[2] * p.z + m.columns[3];
}

// Phong (Blinn false) or Blinn-Phong (Blinn true) in camera space, the eye at the origin:
// ambient + (diffuse + specular) * visibility (1 without shadows, where x * 1 is x).
template <bool Blinn, class F>
Vec3T<F> phongLightVisible(const LightingUniforms& u, const Vec3T<F>& position, const Vec3T<F>& normal,
                           const Vec3T<F>& kd, const F& visibility) {
  const Vec3T<F> n = glsl::normalize(normal);
  const Vec3T<F> l = glsl::normalize(broadcast<F>(u.lightPosition) - position);
  const Vec3T<F> v = glsl::normalize(-position);
  const F diffuse = glsl::maxConstant(glsl::dot(n, l), 0.0f);
  F facing;
  if constexpr (Blinn) {
    facing = glsl::maxConstant(glsl::dot(n, glsl::normalize(l + v)), 0.0f);
  } else {
    facing = glsl::maxConstant(glsl::dot(glsl::reflect(-l, n), v), 0.0f);
  }
  const F highlight = glsl::pow(facing, F(u.specular.w));
  const Vec3T<F> light = broadcast<F>(u.lightPower);
  return (broadcast<F>(u.indirect) * kd + ((kd * diffuse) * light) * visibility) +
         ((broadcast<F>(u.specular) * highlight) * light) * visibility;
}

template <bool Blinn, class F>
Vec3T<F> phongLight(const LightingUniforms& u, const Vec3T<F>& position, const Vec3T<F>& normal, const Vec3T<F>& kd) {
  return phongLightVisible<Blinn, F>(u, position, normal, kd, F(1.0f));
}

}  // namespace lighting
}  // namespace shaders
