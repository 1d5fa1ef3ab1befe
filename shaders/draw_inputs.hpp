// What a scene gives every shading model, in a form no model owns: the mesh's vertex attributes
// (each one entry per vertex) and the per-draw values. Each C++ twin (NAME.hpp) says which of
// them it reads (vertexFrom, uniformsFrom); the table (shading_models.hpp) turns them into the
// twin's vertices and uniforms for both renderers.
// Deliberately only what a model reads today (positions and colours): normals and texture
// coordinates join the mesh here, and the scene parser fills them, when a model reads them.
#pragma once

#include <softraster/math.hpp>

#include <cstddef>
#include <vector>

namespace shaders {

struct Mesh {
  std::vector<softraster::Vec3> positions;  // object space
  std::vector<softraster::Vec4> colours;    // RGBA in [0, 1], one per position
  std::size_t vertexCount() const { return positions.size(); }
};

struct DrawParameters {
  softraster::Mat4 viewProjection = softraster::Mat4::identity();  // object to clip space
  float pointSize = 1.0f;                                          // gl_PointSize of point primitives
};

}  // namespace shaders
