// Fuzz target: the scene loader with --set overrides (crosscheck/scene/scene.hpp, loadScene).
// The input is a scene file's text, optionally followed by a line "--set" and one override
// KEY.PATH=VALUE per line (at most 8), as `crosscheck render --set` passes them. The scene is
// written to a scratch folder that also holds mesh.obj (a quad), so "obj": "mesh.obj" loads.
// Properties: no crash, no undefined behaviour, no uncaught exception; an error is one line that
// starts with the scene file's path; a loaded scene has every draw's matrices computable.
// Deliberately no rendering (that is draw_fuzzer.cpp) and no path outside the scratch folder
// beyond what the input names itself.
#include "fuzz_support.hpp"

#include "scene/scene.hpp"

#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::filesystem::path scenePath = [] {
    fuzz::writeFile(fuzz::scratchDir() / "mesh.obj",
                    "v -1 -1 2\nv 1 -1 2\nv 1 1 2\nv -1 1 2\nvn 0 0 -1\nf 1//1 2//1 3//1 4//1\n");
    return fuzz::scratchDir() / "scene.json";
  }();
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto [sceneText, setLines] = fuzz::splitAt(input, "\n--set\n");
  fuzz::writeFile(scenePath, sceneText);
  std::vector<std::string> overrides;
  std::string_view rest = setLines;
  while (!rest.empty() && overrides.size() < 8) {
    const auto [line, after] = fuzz::splitAt(rest, "\n");
    overrides.emplace_back(line);
    rest = after;
  }

  const auto scene = crosscheck::loadScene(scenePath, overrides);
  if (!scene) {
    const std::string& error = scene.error();
    fuzz::require(error.rfind(scenePath.string() + ": ", 0) == 0, "the error names the scene file", error);
    return 0;
  }
  fuzz::require(!scene->draws.empty(), "a loaded scene has draws");
  for (const crosscheck::Draw& draw : scene->draws) {
    fuzz::require(draw.shading != nullptr, "every draw has a shading model");
    (void)crosscheck::drawParameters(*scene, draw);
  }
  return 0;
}
