// The known deviations of lavapipe from the Vulkan specification: for each, the spec's words,
// what lavapipe does instead, and the scene of scenes/ that shows it. softraster follows the
// driver by default and the spec with ContextOptions::deviations = Spec (--softraster-deviations
// spec); the conformance runner measures, on each deviation's scene, how many pixels the spec's
// behaviour changes (SceneResult::specDeviationPixels), and results.json and the report list
// them (results/results_json.cpp, output/report/).
// Deliberately not here: the behaviour itself (softraster's geometry/viewport.hpp has it) and
// the measurement (run/conformance.cpp renders and compares).
#pragma once

#include <string_view>
#include <vector>

namespace crosscheck {

struct KnownDeviation {
  std::string_view name;      // short id, as results.json and the report name it
  std::string_view spec;      // the specification's words
  std::string_view lavapipe;  // what lavapipe does instead
  std::string_view scene;     // the scene (file stem in scenes/) that shows it
};

const std::vector<KnownDeviation>& knownDeviations();

// The deviation scene `sceneName` shows, or nullptr.
const KnownDeviation* deviationShownBy(std::string_view sceneName);

}  // namespace crosscheck
