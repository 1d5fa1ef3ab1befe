// OBJ meshes through tinyobjloader: positions, faces (polygons split as a fan: (a,b,c),(a,c,d)...)
// a colour per vertex from the face's material (Kd), the OBJ vertex colour, or a fallback, and
// the normals (vn) and the texture coordinates (vt) each when every face corner has one, as a
// model-neutral shaders::Mesh.
// Before tinyobjloader reads the file, every statement is checked (obj_mesh.cpp,
// checkObjStatements): what tinyobjloader would accept silently (a face index "1e20" read as 1, a
// position with two numbers) is an error naming the file and line.
// Deliberately no materials beyond Kd (no map_Kd: a scene names its textures).
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
