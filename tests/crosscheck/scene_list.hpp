// The stems of the scene files directly in scenes/, sorted: the parameters of the test suites that
// run every conformance scene (crosscheck_scenes_test.cpp, fast_path_test.cpp). Read when the test
// binary starts, so a new scene file is a new test case without a rebuild.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

inline std::vector<std::string> conformanceSceneNames() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(SCENES_DIR)) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}
