// OBJ loading (see obj_mesh.hpp).
#include "scene/obj_mesh.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>

namespace crosscheck {
namespace {

// tinyobjloader's messages end in newlines and may hold several; errors here are one line.
std::string oneLine(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ';');
  return message;
}

}  // namespace

softraster::Result<ObjMesh> loadObjMesh(const std::filesystem::path& path, softraster::Vec4 fallbackColour) {
  using softraster::Status;
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we split polygons ourselves, as a fan, so the split is known
  config.mtl_search_path = path.parent_path().string();
  tinyobj::ObjReader reader;
  if (!std::filesystem::is_regular_file(path)) return Status::error(path.string() + ": file not found");
  if (!reader.ParseFromFile(path.string(), config)) {
    const std::string message = oneLine(reader.Error());
    return Status::error(path.string() + ": " + (message.empty() ? "cannot be parsed as OBJ" : message));
  }
  // Warnings (e.g. a missing .mtl) are errors here: a scene must render what its author meant.
  if (!reader.Warning().empty()) return Status::error(path.string() + ": " + oneLine(reader.Warning()));

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto& materials = reader.GetMaterials();
  const std::size_t positionCount = attrib.vertices.size() / 3;
  const bool hasVertexColours = attrib.colors.size() == attrib.vertices.size() && !attrib.colors.empty() &&
                                std::any_of(attrib.colors.begin(), attrib.colors.end(), [](float c) { return c != 1.0f; });
  // Normals (vn) are kept only when every face corner names one: a mesh half with normals would
  // light half of itself from computed ones without saying so.
  const std::size_t normalCount = attrib.normals.size() / 3;
  bool everyCornerHasNormal = normalCount > 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      if (index.normal_index < 0 || static_cast<std::size_t>(index.normal_index) >= normalCount) everyCornerHasNormal = false;
    }
  }
  ObjMesh mesh;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const std::size_t corners = shape.mesh.num_face_vertices[face];
      const int materialId = face < shape.mesh.material_ids.size() ? shape.mesh.material_ids[face] : -1;
      softraster::Vec4 faceColour = fallbackColour;
      if (materialId >= 0 && static_cast<std::size_t>(materialId) < materials.size()) {
        const auto& kd = materials[static_cast<std::size_t>(materialId)].diffuse;
        faceColour = {kd[0], kd[1], kd[2], 1.0f};
      }
      const auto first = static_cast<std::uint32_t>(mesh.vertices.vertexCount());
      for (std::size_t c = 0; c < corners; ++c) {
        const int p = shape.mesh.indices[offset + c].vertex_index;
        if (p < 0 || static_cast<std::size_t>(p) >= positionCount) {
          return Status::error(path.string() + ": shape '" + shape.name + "' face " + std::to_string(face + 1) +
                               " refers to a vertex that does not exist");
        }
        const auto i = static_cast<std::size_t>(p);
        mesh.vertices.positions.push_back({attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]});
        mesh.vertices.colours.push_back(hasVertexColours ? softraster::Vec4{attrib.colors[3 * i], attrib.colors[3 * i + 1],
                                                                            attrib.colors[3 * i + 2], 1.0f}
                                                         : faceColour);
        if (everyCornerHasNormal) {
          const auto n = static_cast<std::size_t>(shape.mesh.indices[offset + c].normal_index);
          mesh.vertices.normals.push_back({attrib.normals[3 * n], attrib.normals[3 * n + 1], attrib.normals[3 * n + 2]});
        }
      }
      for (std::size_t c = 2; c < corners; ++c) {
        mesh.indices.insert(mesh.indices.end(), {first, first + static_cast<std::uint32_t>(c - 1),
                                                 first + static_cast<std::uint32_t>(c)});
      }
      offset += corners;
    }
  }
  if (mesh.indices.empty()) return Status::error(path.string() + ": no faces");
  return mesh;
}

}  // namespace crosscheck
