// What a scene gives every shading model, in a form no model owns: the mesh's vertex attributes
// (each one entry per vertex) and the per-draw values. Each C++ twin (NAME.hpp) says which of
// them it reads (vertexFrom, uniformsFrom, kMeshInputs); the table (shading_models.hpp) turns
// them into the twin's vertices and uniforms for both renderers.
// Matrices and positions arrive rounded to float once from the scene's double-precision values.
// Deliberately only what a model reads today.
#pragma once

#include <softraster/math.hpp>
#include <softraster/texture.hpp>

#include <array>

#include <cstddef>
#include <vector>

namespace shaders {

// Mesh attributes a model reads beyond positions and colours (a twin's kMeshInputs); the scene
// parser computes them only for a model that reads them.
inline constexpr unsigned kReadsNormals = 1u;
inline constexpr unsigned kReadsTexcoords = 2u;
inline constexpr unsigned kReadsTangents = 4u;  // computed from positions, normals and texture coordinates

// How a model samples a shadow map (a depth pass's depth, the scene's "passes"): not at all, with
// a comparison sampler (GLSL sampler2DShadow), or with a plain sampler2D and its own compare.
enum class ShadowMapSampler : unsigned char { None, Comparison, Plain };

// Textures a draw may give its model (the first is the surface's colour, the second a normal map).
inline constexpr std::size_t kMaxDrawTextures = 2;

struct Mesh {
  std::vector<softraster::Vec3> positions;  // object space
  std::vector<softraster::Vec4> colours;    // RGBA in [0, 1], one per position
  std::vector<softraster::Vec3> normals;    // object space, one per position; empty unless read
  std::vector<softraster::Vec2> texcoords;  // (u, v), one per position; empty unless read
  std::vector<softraster::Vec4> tangents;   // object space along +u, w = +-1 the bitangent's side; empty unless read
  std::size_t vertexCount() const { return positions.size(); }
};

// The scene's one light, in world and in camera space.
struct Light {
  softraster::Vec4 positionInWorld{0, 0, 0, 1};
  softraster::Vec4 positionInCamera{0, 0, 0, 1};
  softraster::Vec4 power{14, 14, 14, 0};  // the course's P, RGB
  softraster::Vec4 colour{1, 1, 1, 0};    // Phong's light colour
};

// A draw's material beyond its vertex colours (the course's rho, Phong's diffuse colour).
struct Material {
  softraster::Vec4 indirect{0.5f, 0.5f, 0.5f, 0};  // the course's constant indirect light N
  softraster::Vec4 ambient{0.1f, 0.1f, 0.1f, 0};   // Phong's ambient light
  softraster::Vec4 specular{0.5f, 0.5f, 0.5f, 0};  // Phong's specular reflectance
  float shininess = 32;                            // Phong's exponent
};

struct DrawParameters {
  softraster::Mat4 modelViewProjection = softraster::Mat4::identity();  // object to clip space
  softraster::Mat4 modelToWorld = softraster::Mat4::identity();
  softraster::Mat4 normalToWorld = softraster::Mat4::identity();   // inverse transpose of modelToWorld's 3x3
  softraster::Mat4 modelToCamera = softraster::Mat4::identity();
  softraster::Mat4 normalToCamera = softraster::Mat4::identity();  // inverse transpose of modelToCamera's 3x3
  Light light;
  Material material;
  float pointSize = 1.0f;  // gl_PointSize of point primitives
  float nearPlane = 1.0f;  // the camera's near plane distance (depth_view)
  // A model that samples a shadow map (kSamplesShadowPass): object -> the clip space of the pass
  // whose depth it samples, and the bias subtracted from the reference depth.
  softraster::Mat4 modelToShadow = softraster::Mat4::identity();
  float shadowBias = 0.0f;
  // The draw's textures and samplers, in the order its model binds them (set 1, binding i);
  // textures the model does not sample are null.
  std::array<softraster::Sampler2D, kMaxDrawTextures> textures{};
};

}  // namespace shaders
