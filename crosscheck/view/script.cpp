// crosscheck view's key scripts (see script.hpp).
#include "view/script.hpp"

#include "scene/input_file.hpp"

#include <charconv>
#include <fstream>
#include <sstream>

namespace crosscheck::view {
namespace {

std::string methodList() {
  std::string list;
  for (softraster::Method m : softraster::kMethods) list += (list.empty() ? "" : ", ") + std::string(softraster::methodName(m));
  return list;
}

std::string viewList() {
  std::string list;
  for (ViewKind v : kViews) list += (list.empty() ? "" : ", ") + std::string(viewName(v));
  return list;
}

std::string keyList() {
  std::string list;
  for (const Control& c : controls()) list += (list.empty() ? "" : " ") + std::string(c.key);
  return list;
}

bool isFileName(const std::string& name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
                    c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

softraster::Result<std::vector<ScriptCommand>> parseScript(const std::string& text, const std::string& file) {
  using softraster::Status;
  std::vector<ScriptCommand> commands;
  std::istringstream lines(text);
  std::string raw;
  unsigned number = 0;
  while (std::getline(lines, raw)) {
    ++number;
    const auto fail = [&](const std::string& what) { return Status::error(file + ":" + std::to_string(number) + ": " + what); };
    if (const auto hash = raw.find('#'); hash != std::string::npos) raw.erase(hash);
    std::istringstream in(raw);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    if (words.empty()) continue;
    ScriptCommand c;
    c.line = number;
    const std::string& verb = words[0];
    const auto count = [&](std::size_t index, unsigned& out) -> Status {
      if (words.size() <= index) return {};
      const std::string& w = words[index];
      unsigned value = 0;
      const auto [ptr, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
      if (ec != std::errc() || ptr != w.data() + w.size() || value < 1 || value > kMaxScriptFrames) {
        return fail("'" + w + "': expected a whole number of frames from 1 to " + std::to_string(kMaxScriptFrames));
      }
      out = value;
      return {};
    };
    const auto arity = [&](std::size_t least, std::size_t most, const char* form) -> Status {
      if (words.size() < least || words.size() > most) return fail("expected '" + std::string(form) + "'");
      return {};
    };
    if (verb == "key") {
      c.kind = ScriptCommand::Kind::Key;
      if (Status s = arity(2, 3, "key NAME [FRAMES]"); !s) return s;
      if (!controlForKey(words[1])) return fail("unknown key '" + words[1] + "' (keys: " + keyList() + ")");
      c.key = words[1];
      if (Status s = count(2, c.frames); !s) return s;
    } else if (verb == "frame") {
      c.kind = ScriptCommand::Kind::Frame;
      if (Status s = arity(1, 2, "frame [N]"); !s) return s;
      if (Status s = count(1, c.frames); !s) return s;
    } else if (verb == "view") {
      c.kind = ScriptCommand::Kind::View;
      if (Status s = arity(2, 2, "view NAME"); !s) return s;
      const auto view = viewFromName(words[1]);
      if (!view) return fail("unknown view '" + words[1] + "' (expected one of " + viewList() + ")");
      c.view = *view;
    } else if (verb == "method") {
      c.kind = ScriptCommand::Kind::Method;
      if (Status s = arity(2, 2, "method NAME"); !s) return s;
      const auto method = softraster::methodFromName(words[1]);
      if (!method) return fail("unknown method '" + words[1] + "' (expected one of " + methodList() + ")");
      c.method = *method;
    } else if (verb == "screenshot" || verb == "save") {
      const bool save = verb == "save";
      c.kind = save ? ScriptCommand::Kind::Save : ScriptCommand::Kind::Screenshot;
      if (Status s = arity(2, 2, save ? "save NAME" : "screenshot NAME"); !s) return s;
      if (!isFileName(words[1])) {
        return fail("'" + words[1] + "': expected a file name (letters, digits, '-', '_', '.'; no folders)");
      }
      c.name = words[1];
      const std::string extension = save ? ".json" : ".png";
      if (c.name.size() < extension.size() || c.name.compare(c.name.size() - extension.size(), extension.size(), extension) != 0) {
        c.name += extension;
      }
    } else if (verb == "quit") {
      c.kind = ScriptCommand::Kind::Quit;
      if (Status s = arity(1, 1, "quit"); !s) return s;
    } else {
      return fail("unknown command '" + verb + "' (expected key, frame, view, method, screenshot, save or quit)");
    }
    commands.push_back(std::move(c));
  }
  return commands;
}

softraster::Result<std::vector<ScriptCommand>> loadScript(const std::filesystem::path& path) {
  using softraster::Status;
  if (const Status readable = checkInputFile(path); !readable) {
    return Status::error(path.string() + ": cannot read script: " + readable.message());
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) return Status::error(path.string() + ": cannot read script");
  std::ostringstream text;
  text << file.rdbuf();
  return parseScript(text.str(), path.string());
}

std::string scriptHelp() {
  return "Script (--script FILE), one command a line, '#' comments:\n"
         "  key NAME [FRAMES]   hold key NAME down for FRAMES frames (default 1): a held control steps\n"
         "                      once a frame, a pressed one acts once\n"
         "  frame [N]           show N frames (default 1) with no key down\n"
         "  view NAME           switch the view (" + viewList() + ") and show a frame\n"
         "  method NAME         switch softraster's method (" + methodList() + ") and show a frame\n"
         "  screenshot NAME     write the window as last shown to OUT/NAME.png\n"
         "  save NAME           save as scene: OUT/NAME.json, OUT/NAME.soft.png, OUT/NAME.vulkan.png\n"
         "  quit                stop (so does the end of the file)\n";
}

}  // namespace crosscheck::view
