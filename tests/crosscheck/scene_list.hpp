// The stems of the scene files directly in scenes/ and in scenes/stability/ (the stability cases),
// sorted: the parameters of the test suites that run every conformance scene
// (crosscheck_scenes_test.cpp, fast_path_test.cpp). Read when the test binary starts, so a new
// scene file is a new test case without a rebuild. Stems are unique across both folders (the
// conformance suite requires it), so a stem names its file: conformanceScenePath.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

inline std::vector<std::string> conformanceSceneNames() {
  std::vector<std::string> names;
  for (const std::filesystem::path& dir : {std::filesystem::path(SCENES_DIR), std::filesystem::path(SCENES_DIR) / "stability"}) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The file of a name conformanceSceneNames returned.
inline std::filesystem::path conformanceScenePath(const std::string& name) {
  const std::filesystem::path top = std::filesystem::path(SCENES_DIR) / (name + ".json");
  if (std::filesystem::exists(top)) return top;
  return std::filesystem::path(SCENES_DIR) / "stability" / (name + ".json");
}
