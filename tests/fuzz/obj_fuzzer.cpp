// Fuzz target: the OBJ loader (crosscheck/scene/obj_mesh.hpp, loadObjMesh through tinyobjloader).
// The input is an OBJ file's text, optionally followed by a line "#--mtl" and the text of the
// material library mesh.mtl beside it (so "mtllib mesh.mtl" and "usemtl" reach real materials).
// Properties: no crash, no undefined behaviour, no uncaught exception; an error starts with the
// OBJ's path; a loaded mesh has as many colours (and normals, if any) as positions, and every
// index is below the vertex count.
// Deliberately no scene around it (scene_fuzzer.cpp covers "obj" in scenes).
#include "fuzz_support.hpp"

#include "scene/obj_mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path objPath = fuzz::scratchDir() / "mesh.obj";
  static const std::filesystem::path mtlPath = fuzz::scratchDir() / "mesh.mtl";
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto [objText, mtlText] = fuzz::splitAt(input, "\n#--mtl\n");
  fuzz::writeFile(objPath, objText);
  fuzz::writeFile(mtlPath, mtlText);

  const auto mesh = crosscheck::loadObjMesh(objPath, softraster::Vec4{0.5f, 0.5f, 0.5f, 1.0f});
  if (!mesh) {
    fuzz::require(mesh.error().rfind(objPath.string() + ":", 0) == 0, "the error names the OBJ file", mesh.error());
    return 0;
  }
  const std::size_t vertices = mesh->vertices.positions.size();
  fuzz::require(mesh->vertices.colours.size() == vertices, "a colour per vertex");
  fuzz::require(mesh->vertices.normals.empty() || mesh->vertices.normals.size() == vertices, "a normal per vertex or none");
  for (std::uint32_t index : mesh->indices) fuzz::require(index < vertices, "every index is below the vertex count");
  return 0;
}
