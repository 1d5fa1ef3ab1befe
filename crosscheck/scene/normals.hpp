// Vertex normals (and tangents) for the shading models that read them (the lit models): flat, one per triangle
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

// Fills mesh.tangents for a triangle list with normals and texture coordinates: per vertex, the
// sum of its triangles' directions of +u (and +v) in object space, weighted by their texture-space
// area, made perpendicular to the normal and unit; w = +1 where (normal, tangent) x gives +v's
// side, else -1 (a mirrored mapping). A vertex whose triangles give no frame gets any direction
// perpendicular to its normal.
void computeTangents(shaders::Mesh& mesh, const std::vector<std::uint32_t>& indices, bool indexed);

}  // namespace crosscheck
