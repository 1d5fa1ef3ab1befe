// Expectations file parsing (see expectations.hpp).
#include "run/expectations.hpp"

#include "scene/input_file.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

namespace crosscheck {
namespace {

using softraster::Status;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

}  // namespace

softraster::Result<Expectations> parseExpectations(std::string_view text, const std::filesystem::path& file) {
  Expectations expectations;
  expectations.file = file;
  int lineNumber = 0;
  while (!text.empty()) {
    ++lineNumber;
    const auto newline = text.find('\n');
    const std::string_view line = text.substr(0, newline);
    text = newline == std::string_view::npos ? std::string_view{} : text.substr(newline + 1);

    const auto hash = line.find('#');
    const std::string_view content = trim(line.substr(0, hash));
    const std::string_view reason = hash == std::string_view::npos ? std::string_view{} : trim(line.substr(hash + 1));
    if (content.empty()) continue;  // blank or comment

    const auto fail = [&](const std::string& what) {
      return Status::error(file.string() + ":" + std::to_string(lineNumber) + ": " + what);
    };
    const auto comma = content.find(',');
    if (comma == std::string_view::npos || content.find(',', comma + 1) != std::string_view::npos) {
      return fail("expected 'SCENE,STATUS # reason', got '" + std::string(content) + "'");
    }
    const std::string name(trim(content.substr(0, comma)));
    const std::string_view outcomeText = trim(content.substr(comma + 1));
    if (name.empty()) return fail("missing scene name before ','");
    const auto outcome = parseOutcome(outcomeText);
    if (!outcome || !(*outcome == Outcome::Pass || *outcome == Outcome::Fail || *outcome == Outcome::Crash ||
                      *outcome == Outcome::Timeout || *outcome == Outcome::Skip)) {
      return fail("'" + std::string(outcomeText) + "' is not one of Pass, Fail, Crash, Timeout, Skip");
    }
    const auto [it, inserted] = expectations.byScene.emplace(name, Expectation{*outcome, std::string(reason), lineNumber});
    if (!inserted) return fail("scene '" + name + "' is already listed on line " + std::to_string(it->second.line));
  }
  return expectations;
}

softraster::Result<Expectations> loadExpectations(const std::filesystem::path& file) {
  const std::string context = file.string() + ": cannot read expectations file: ";
  if (const Status readable = checkInputFile(file); !readable) return Status::error(context + readable.message());
  errno = 0;
  std::ifstream in(file, std::ios::binary);
  if (!in) return Status::error(context + (errno ? std::strerror(errno) : "cannot open"));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return Status::error(context + "read error");
  return parseExpectations(text.str(), file);
}

Outcome applyExpectation(Outcome actual, const Expectation* expected) {
  if (!expected || expected->outcome == Outcome::Pass) return actual;
  if (expected->outcome == Outcome::Skip) return Outcome::Skip;  // not run at all
  if (actual == Outcome::Pass) return Outcome::UnexpectedPass;
  if (actual == expected->outcome) return Outcome::ExpectedFail;
  return actual;
}

}  // namespace crosscheck
