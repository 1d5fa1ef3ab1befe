// OBJ meshes through tinyobjloader: positions, faces (polygons split as a fan: (a,b,c),(a,c,d)...)
// a colour per vertex from the face's material (Kd), the OBJ vertex colour, or a fallback, and
// the normals (vn) when every face corner has one, as a model-neutral shaders::Mesh.
// Deliberately ignores texture coordinates until a shading model reads them.
#pragma once

#include <softraster/status.hpp>

#include <draw_inputs.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace crosscheck {

struct ObjMesh {
  shaders::Mesh vertices;               // one per face corner
  std::vector<std::uint32_t> indices;
};

// The mesh, or the error "FILE: what is wrong".
softraster::Result<ObjMesh> loadObjMesh(const std::filesystem::path& path, softraster::Vec4 fallbackColour);

}  // namespace crosscheck
