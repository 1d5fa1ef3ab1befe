// Outcome: the seven results one scene can have in a conformance run, and their names as written in
// output, JUnit files and expectations files (README and the CLI call them statuses). Timeout is
// a scene that gave no result within the run's --timeout (its worker process was killed).
// Not an error type: errors are softraster::Status / Result (softraster/status.hpp); a scene that
// cannot be run has the outcome Crash and its error line beside it.
// Deliberately no "Flake" outcome: both renderers are deterministic, so a scene that changes its
// result between runs is a bug to fix, not a state to record.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace crosscheck {

enum class Outcome { Pass, Fail, ExpectedFail, UnexpectedPass, Skip, Crash, Timeout };

inline constexpr std::array<Outcome, 7> kAllOutcomes{Outcome::Pass,           Outcome::Fail, Outcome::ExpectedFail,
                                                     Outcome::UnexpectedPass, Outcome::Skip, Outcome::Crash,
                                                     Outcome::Timeout};

constexpr std::string_view outcomeName(Outcome outcome) {
  switch (outcome) {
    case Outcome::Pass: return "Pass";
    case Outcome::Fail: return "Fail";
    case Outcome::ExpectedFail: return "ExpectedFail";
    case Outcome::UnexpectedPass: return "UnexpectedPass";
    case Outcome::Skip: return "Skip";
    case Outcome::Crash: return "Crash";
    case Outcome::Timeout: return "Timeout";
  }
  return "?";
}

// The outcome with this name, or nullopt (a lookup, not an error: the caller names the file).
inline std::optional<Outcome> parseOutcome(std::string_view name) {
  for (Outcome o : kAllOutcomes) {
    if (outcomeName(o) == name) return o;
  }
  return std::nullopt;
}

// Fail, Crash, Timeout and UnexpectedPass fail a run; everything else is as expected.
constexpr bool isUnexpected(Outcome outcome) {
  return outcome == Outcome::Fail || outcome == Outcome::Crash || outcome == Outcome::Timeout ||
         outcome == Outcome::UnexpectedPass;
}

}  // namespace crosscheck
