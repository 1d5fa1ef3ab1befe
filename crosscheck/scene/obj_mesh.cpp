// OBJ loading (see obj_mesh.hpp).
#include "scene/obj_mesh.hpp"

#include "scene/input_file.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

namespace crosscheck {
namespace {

// tinyobjloader's messages end in newlines and may hold several; errors here are one line.
std::string oneLine(std::string message) {
  while (!message.empty() && (message.back() == '\n' || message.back() == '\r')) message.pop_back();
  std::replace(message.begin(), message.end(), '\n', ';');
  return message;
}

// One statement's numbers: each a whole token that is a finite float; `values` gets the first few.
bool readFloats(std::istringstream& tokens, std::size_t& count, std::string& bad, double (&values)[8]) {
  std::string token;
  count = 0;
  while (tokens >> token) {
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(token.c_str(), &end);
    if (end != token.c_str() + token.size() || errno == ERANGE || !std::isfinite(v) ||
        std::fabs(v) > std::numeric_limits<float>::max()) {
      bad = token;
      return false;
    }
    if (count < 8) values[count] = v;
    ++count;
  }
  return true;
}

// A face corner's index: a non-zero integer referring to one of the `defined` elements so far
// (negative counts back from the last), as OBJ says; tinyobjloader would read "1e20" as 1.
std::optional<std::string> checkIndex(const std::string& text, std::int64_t defined, const char* what) {
  std::int64_t index = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), index);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    return "'" + text + "' is not an integer " + what + " index";
  }
  if (index == 0 || index > defined || index < -defined) {
    return std::string(what) + " index " + text + " refers to no " + what + " (" + std::to_string(defined) +
           " defined so far)";
  }
  return std::nullopt;
}

// Checks the statements tinyobjloader would accept silently in a way we must not: positions
// with other than 3 (x y z) or 6 (x y z r g b) numbers, numbers that are not finite floats,
// face indices that are not integers or refer to nothing, lines and points (not drawn), and
// statements OBJ meshes here do not use. "FILE:LINE: what", or OK.
softraster::Status checkObjStatements(const std::filesystem::path& path, std::istream& in) {
  using softraster::Status;
  std::int64_t positions = 0, uvs = 0, normals = 0;
  std::string line;
  for (std::size_t number = 1; std::getline(in, line); ++number) {
    const auto error = [&](const std::string& message) {
      return Status::error(path.string() + ":" + std::to_string(number) + ": " + message);
    };
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream tokens(line);
    std::string keyword;
    if (!(tokens >> keyword)) continue;
    std::size_t count = 0;
    std::string bad;
    double values[8] = {};
    if (keyword == "v" || keyword == "vn" || keyword == "vt") {
      if (!readFloats(tokens, count, bad, values)) return error("'" + bad + "' is not a finite number");
      if (keyword == "v" && count != 3 && count != 6) {
        return error("a position (v) has " + std::to_string(count) + " numbers; expected x y z or x y z r g b");
      }
      if (keyword == "v" && count == 6) {
        for (int c = 3; c < 6; ++c) {
          if (!(values[c] >= 0 && values[c] <= 1)) return error("a vertex colour (r g b) must be in [0, 1]");
        }
      }
      if (keyword == "vn" && count != 3) return error("a normal (vn) has " + std::to_string(count) + " numbers; expected 3");
      if (keyword == "vt" && (count < 1 || count > 3)) {
        return error("a texture coordinate (vt) has " + std::to_string(count) + " numbers; expected 1 to 3");
      }
      ++(keyword == "v" ? positions : keyword == "vn" ? normals : uvs);
    } else if (keyword == "f") {
      std::string corner;
      while (tokens >> corner) {
        ++count;
        std::string parts[3];
        std::size_t part = 0;
        for (char c : corner) {
          if (c == '/') {
            if (++part > 2) return error("face corner '" + corner + "' has more than three parts");
          } else {
            parts[part] += c;
          }
        }
        if (auto wrong = checkIndex(parts[0], positions, "position")) return error("face corner '" + corner + "': " + *wrong);
        if (part >= 1 && !parts[1].empty()) {
          if (auto wrong = checkIndex(parts[1], uvs, "texture coordinate")) return error("face corner '" + corner + "': " + *wrong);
        }
        if (part == 2) {
          if (auto wrong = checkIndex(parts[2], normals, "normal")) return error("face corner '" + corner + "': " + *wrong);
        }
      }
      if (count < 3) return error("a face has " + std::to_string(count) + " corners; expected at least 3");
    } else if (keyword == "l" || keyword == "p") {
      return error("lines and points ('" + keyword + "') are not drawn; a mesh here has faces only");
    } else if (keyword != "o" && keyword != "g" && keyword != "s" && keyword != "usemtl" && keyword != "mtllib") {
      return error("'" + keyword + "' is not an OBJ statement this loader reads (v, vt, vn, f, o, g, s, usemtl, mtllib)");
    }
  }
  if (in.bad()) return Status::error(path.string() + ": read error");
  return {};
}

}  // namespace

softraster::Result<ObjMesh> loadObjMesh(const std::filesystem::path& path, softraster::Vec4 fallbackColour) {
  using softraster::Status;
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we split polygons ourselves, as a fan, so the split is known
  config.mtl_search_path = path.parent_path().string();
  tinyobj::ObjReader reader;
  if (const Status readable = checkInputFile(path); !readable) return Status::error(path.string() + ": " + readable.message());
  {
    std::ifstream text(path);
    if (!text) return Status::error(path.string() + ": cannot be read");
    if (const Status statements = checkObjStatements(path, text); !statements) return statements;
  }
  if (!reader.ParseFromFile(path.string(), config)) {
    const std::string message = oneLine(reader.Error());
    return Status::error(path.string() + ": " + (message.empty() ? "cannot be parsed as OBJ" : message));
  }
  // Warnings (e.g. a missing .mtl) are errors here: a scene must render what its author meant.
  if (!reader.Warning().empty()) return Status::error(path.string() + ": " + oneLine(reader.Warning()));

  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  const auto& materials = reader.GetMaterials();
  for (const tinyobj::material_t& material : materials) {
    for (float kd : material.diffuse) {
      if (!(kd >= 0 && kd <= 1)) {
        return Status::error(path.string() + ": material '" + material.name + "': Kd must be in [0, 1]");
      }
    }
  }
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
  // Texture coordinates (vt) likewise: kept only when every face corner names one (u, v; a third
  // component is ignored: tinyobjloader keeps two).
  const std::size_t texcoordCount = attrib.texcoords.size() / 2;
  bool everyCornerHasTexcoord = texcoordCount > 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    for (const tinyobj::index_t& index : shape.mesh.indices) {
      if (index.texcoord_index < 0 || static_cast<std::size_t>(index.texcoord_index) >= texcoordCount) {
        everyCornerHasTexcoord = false;
      }
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
        if (everyCornerHasTexcoord) {
          const auto t = static_cast<std::size_t>(shape.mesh.indices[offset + c].texcoord_index);
          const softraster::Vec2 uv{attrib.texcoords[2 * t], attrib.texcoords[2 * t + 1]};
          if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
            return Status::error(path.string() + ": a texture coordinate (vt) is not finite in float");
          }
          mesh.vertices.texcoords.push_back(uv);
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
