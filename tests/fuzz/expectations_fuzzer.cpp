// Fuzz target: the expectations file parser (crosscheck/run/expectations.hpp, parseExpectations).
// The input is the file's text.
// Properties: no crash, no undefined behaviour, no uncaught exception; an error is
// "fuzz.txt:LINE: ..." with a line that exists; every parsed entry has a non-empty name without
// ',' or '#', one of the statuses an expectations file may give, and a line number in the file.
// Deliberately no file I/O (loadExpectations only reads the file and calls this parser).
#include "fuzz_support.hpp"

#include "run/expectations.hpp"

#include <algorithm>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using crosscheck::Outcome;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n')) + 1;
  const auto parsed = crosscheck::parseExpectations(text, "fuzz.txt");
  if (!parsed) {
    const std::string& error = parsed.error();
    fuzz::require(error.rfind("fuzz.txt:", 0) == 0, "the error names the file", error);
    const long line = std::strtol(error.c_str() + 9, nullptr, 10);
    fuzz::require(line >= 1 && line <= lines, "the error names a line of the file", error);
    return 0;
  }
  for (const auto& [name, expectation] : parsed->byScene) {
    fuzz::require(!name.empty() && name.find_first_of(",#") == std::string::npos, "a scene name without ',' or '#'", name);
    const Outcome o = expectation.outcome;
    fuzz::require(o == Outcome::Pass || o == Outcome::Fail || o == Outcome::Crash || o == Outcome::Timeout ||
                      o == Outcome::Skip,
                  "a status an expectations file may give");
    fuzz::require(expectation.line >= 1 && expectation.line <= lines, "the entry's line is in the file");
    fuzz::require(expectation.reason.find('\n') == std::string::npos, "a reason is one line");
  }
  return 0;
}
