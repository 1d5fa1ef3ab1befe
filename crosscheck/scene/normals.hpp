// Vertex normals for the shading models that read them (the lit models): flat, one per triangle
// (its corners get their own vertices, so no two triangles share one), or smooth, one per shared
// vertex (the normalised sum of its triangles' area-weighted face normals). A face normal is
// (b - a) x (c - a): outwards for a front face wound counter-clockwise on screen, as every mesh
// here is. Computed in double and rounded to float once.
// Deliberately triangle lists only: a strip or a fan would have to be split the same way, and no
// scene draws one lit.
#pragma once

#include <draw_inputs.hpp>

#include <cstdint>
#include <vector>

namespace crosscheck {

enum class NormalMode { Flat, Smooth };

// Fills mesh.normals for a triangle list (`indices` when `indexed`, else the vertices in order).
// Flat rewrites the mesh, and the indices of an indexed draw, to one vertex per triangle corner.
void computeNormals(shaders::Mesh& mesh, std::vector<std::uint32_t>& indices, bool indexed, NormalMode mode);

}  // namespace crosscheck
