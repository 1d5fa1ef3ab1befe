// Vertex normals (see normals.hpp).
#include "scene/normals.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
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
      if (!mesh.texcoords.empty()) flat.texcoords.push_back(mesh.texcoords[corners[t + k]]);
    }
  }
  mesh = std::move(flat);
  if (indexed) {
    indices.resize(mesh.vertexCount());
    for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<std::uint32_t>(i);
  }
}

void computeTangents(shaders::Mesh& mesh, const std::vector<std::uint32_t>& indices, bool indexed) {
  std::vector<std::uint32_t> corners = indices;
  if (!indexed) {
    corners.resize(mesh.vertexCount());
    for (std::size_t i = 0; i < corners.size(); ++i) corners[i] = static_cast<std::uint32_t>(i);
  }
  corners.resize(corners.size() / 3 * 3);
  std::vector<glm::dvec3> tangents(mesh.vertexCount(), glm::dvec3(0.0)), bitangents(mesh.vertexCount(), glm::dvec3(0.0));
  const auto position = [&](std::uint32_t i) {
    return glm::dvec3(mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  };
  for (std::size_t t = 0; t < corners.size(); t += 3) {
    const std::uint32_t a = corners[t], b = corners[t + 1], c = corners[t + 2];
    const glm::dvec3 e1 = position(b) - position(a), e2 = position(c) - position(a);
    const double du1 = double(mesh.texcoords[b].x) - mesh.texcoords[a].x, dv1 = double(mesh.texcoords[b].y) - mesh.texcoords[a].y;
    const double du2 = double(mesh.texcoords[c].x) - mesh.texcoords[a].x, dv2 = double(mesh.texcoords[c].y) - mesh.texcoords[a].y;
    const double det = du1 * dv2 - du2 * dv1;
    if (det == 0 || !std::isfinite(det)) continue;  // no texture-space frame: the triangle adds nothing
    // Weighted by the triangle's area in texture space, as the face normals are by area.
    const glm::dvec3 tu = (e1 * dv2 - e2 * dv1) * (det > 0 ? 1.0 : -1.0);
    const glm::dvec3 tv = (e2 * du1 - e1 * du2) * (det > 0 ? 1.0 : -1.0);
    for (std::uint32_t i : {a, b, c}) {
      tangents[i] += tu;
      bitangents[i] += tv;
    }
  }
  mesh.tangents.clear();
  for (std::size_t i = 0; i < mesh.vertexCount(); ++i) {
    const glm::dvec3 n(mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z);
    glm::dvec3 t = tangents[i] - n * glm::dot(n, tangents[i]);  // Gram-Schmidt against the normal
    if (!(glm::length(t) > 1e-12)) {
      // No usable texture frame here: any direction perpendicular to the normal.
      t = glm::cross(n, std::fabs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0));
    }
    const softraster::Vec3 u = unit(t);
    const double w = glm::dot(glm::cross(n, t), bitangents[i]) < 0 ? -1.0 : 1.0;
    mesh.tangents.push_back({u.x, u.y, u.z, static_cast<float>(w)});
  }
}

}  // namespace crosscheck
