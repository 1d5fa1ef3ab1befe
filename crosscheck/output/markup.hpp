// Escaping text for XML and HTML (JUnit files, the report), URLs of files next to a page, a time
// as UTC text, and writing such a document to disk.
// Deliberately no document model: the writers build their markup as text and escape every value
// they put into it.
#pragma once

#include <softraster/status.hpp>

#include <ctime>
#include <filesystem>
#include <string>
#include <string_view>

namespace crosscheck {

// Escapes & < > " ' as entities. Characters XML 1.0 cannot carry at all (control characters other
// than tab, newline and carriage return) and bytes that are not UTF-8 become U+FFFD, so the result
// is always well-formed character data or attribute text.
std::string escapeMarkup(std::string_view text);

// Percent-encodes a relative file path for an href or src: '/' stays, unreserved characters stay,
// every other byte becomes %XX.
std::string encodeUrlPath(std::string_view path);

// `time` in UTC, formatted by strftime `format` (e.g. "%Y-%m-%dT%H:%M:%S").
std::string utcTime(std::time_t time, const char* format);

// Writes `text` to `file`, creating its folder. The error is "FILE: cannot write WHAT: REASON".
softraster::Status writeDocument(const std::filesystem::path& file, std::string_view text, std::string_view what);

}  // namespace crosscheck
