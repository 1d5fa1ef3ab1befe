// Expectations file: the known results of scenes, so a run fails only on something new.
// One scene per line, `NAME,STATUS # reason`: NAME is the scene's name (its file stem, e.g.
// `room`), STATUS one of the Outcomes Pass, Fail, Crash, Timeout, Skip. Blank lines and lines that start
// with '#' are comments; the reason is optional but recommended. Format: scenes/README.md.
// Deliberately no wildcards and no per-metric expectations: a known failure is a whole scene.
#pragma once

#include "run/outcome.hpp"

#include <softraster/status.hpp>

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

namespace crosscheck {

struct Expectation {
  Outcome outcome = Outcome::Pass;  // Pass, Fail, Crash, Timeout or Skip
  std::string reason;
  int line = 0;
};

struct Expectations {
  std::filesystem::path file;
  std::map<std::string, Expectation> byScene;

  const Expectation* find(const std::string& sceneName) const {
    const auto it = byScene.find(sceneName);
    return it == byScene.end() ? nullptr : &it->second;
  }
};

// Parses the text of an expectations file; `file` names it in errors. The error is one line:
// "FILE:LINE: what is wrong".
softraster::Result<Expectations> parseExpectations(std::string_view text, const std::filesystem::path& file);

// Reads and parses a file; an unreadable file is "FILE: cannot read expectations file: reason".
softraster::Result<Expectations> loadExpectations(const std::filesystem::path& file);

// The result a scene gets once its expectation is applied to what actually happened
// (actual is Pass, Fail, Crash or Timeout): an expected Fail that fails is ExpectedFail, one that
// passes is UnexpectedPass, one that crashes stays Crash; likewise for an expected Crash or
// Timeout (an expected Timeout that crashes stays Crash, and the other way round).
Outcome applyExpectation(Outcome actual, const Expectation* expected);

}  // namespace crosscheck
