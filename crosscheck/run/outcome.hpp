// The six outcomes of one scene in a conformance run, and their names as written in output,
// JUnit files and expectations files.
// Deliberately no "Flake" status: both renderers are deterministic, so a scene that changes its
// result between runs is a bug to fix, not a state to record.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace crosscheck {

enum class Status { Pass, Fail, ExpectedFail, UnexpectedPass, Skip, Crash };

inline constexpr std::array<Status, 6> kAllStatuses{Status::Pass,           Status::Fail, Status::ExpectedFail,
                                                    Status::UnexpectedPass, Status::Skip, Status::Crash};

constexpr std::string_view statusName(Status status) {
  switch (status) {
    case Status::Pass: return "Pass";
    case Status::Fail: return "Fail";
    case Status::ExpectedFail: return "ExpectedFail";
    case Status::UnexpectedPass: return "UnexpectedPass";
    case Status::Skip: return "Skip";
    case Status::Crash: return "Crash";
  }
  return "?";
}

inline std::optional<Status> parseStatus(std::string_view name) {
  for (Status s : kAllStatuses) {
    if (statusName(s) == name) return s;
  }
  return std::nullopt;
}

// Fail, Crash and UnexpectedPass fail a run; everything else is as expected.
constexpr bool isUnexpected(Status status) {
  return status == Status::Fail || status == Status::Crash || status == Status::UnexpectedPass;
}

}  // namespace crosscheck
