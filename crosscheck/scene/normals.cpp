// Vertex normals (see normals.hpp).
#include "scene/normals.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstddef>

namespace crosscheck {
namespace {

glm::dvec3 at(const shaders::Mesh& mesh, std::uint32_t i) {
  const softraster::Vec3& p = mesh.positions[i];
  return {p.x, p.y, p.z};
}

// The face normal scaled by twice the triangle's area.
glm::dvec3 faceNormal(const shaders::Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const glm::dvec3 pa = at(mesh, a);
  return glm::cross(at(mesh, b) - pa, at(mesh, c) - pa);
}

// Unit length, rounded to float once; a zero vector (a degenerate triangle) stays zero.
softraster::Vec3 unit(glm::dvec3 n) {
  const double length = glm::length(n);
  if (!(length > 0)) return {0, 0, 0};
  return {static_cast<float>(n.x / length), static_cast<float>(n.y / length), static_cast<float>(n.z / length)};
}

}  // namespace

void computeNormals(shaders::Mesh& mesh, std::vector<std::uint32_t>& indices, bool indexed, NormalMode mode) {
  std::vector<std::uint32_t> corners = indices;
  if (!indexed) {
    corners.resize(mesh.vertexCount());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<std::uint32_t>(i);
  }
  corners.resize(corners.size() / 3 * 3);  // a trailing partial triangle draws nothing

  if (mode == NormalMode::Smooth) {
    std::vector<glm::dvec3> sums(mesh.vertexCount(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < corners.size(); t += 3) {
      const glm::dvec3 n = faceNormal(mesh, corners[t], corners[t + 1], corners[t + 2]);
      for (int k = 0; k < 3; ++k) sums[corners[t + k]] += n;
    }
    mesh.normals.clear();
    for (const glm::dvec3& n : sums) mesh.normals.push_back(unit(n));
    return;
  }

  shaders::Mesh flat;
  flat.positions.reserve(corners.size());
  flat.colours.reserve(corners.size());
  flat.normals.reserve(corners.size());
  for (std::size_t t = 0; t < corners.size(); t += 3) {
    const softraster::Vec3 n = unit(faceNormal(mesh, corners[t], corners[t + 1], corners[t + 2]));
    for (int k = 0; k < 3; ++k) {
      flat.positions.push_back(mesh.positions[corners[t + k]]);
      flat.colours.push_back(mesh.colours[corners[t + k]]);
      flat.normals.push_back(n);
    }
  }
  mesh = std::move(flat);
  if (indexed) {
    indices.resize(mesh.vertexCount());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
}

}  // namespace crosscheck
