// crosscheck view --script FILE: keys and frames, so a walk through a scene is reproducible. One
// command a line; '#' starts a comment; blank lines are skipped:
//   key NAME [FRAMES]   hold the key NAME (controls.hpp: SDL's key names, "Up", "PageUp", "W", "F2")
//                       down for FRAMES frames (default 1): a held control steps once per frame, a
//                       pressed one acts once, on the first
//   frame [N]           show N frames (default 1) with no key down (time advances if playing)
//   view NAME           switch the view (side, soft, vulkan, diff, flicker, depth, depth-diff)
//                       and show one frame
//   method NAME         switch softraster's method (exact, exact-scalar, ...) and show one frame
//   screenshot NAME     write the window as it was last shown to OUT/NAME.png
//   save NAME           save as scene: OUT/NAME.json plus OUT/NAME.soft.png and NAME.vulkan.png
//   quit                stop (the end of the file does too)
// FRAMES and N are whole numbers from 1 to kMaxScriptFrames; NAME for screenshot and save is a
// file name (letters, digits, '-', '_', '.'), without folders. An error is one line naming the
// file and the line: "FILE:LINE: what is wrong".
// Deliberately no timing, no mouse and no loops: a script says frame by frame what happens.
#pragma once

#include "view/controls.hpp"

#include <softraster/options.hpp>
#include <softraster/status.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace crosscheck::view {

inline constexpr unsigned kMaxScriptFrames = 100000;

struct ScriptCommand {
  enum class Kind { Key, Frame, View, Method, Screenshot, Save, Quit };
  Kind kind = Kind::Frame;
  std::string key;            // Key: SDL's key name, one of controls()
  unsigned frames = 1;        // Key, Frame
  ViewKind view = ViewKind::Side;                          // View
  softraster::Method method = softraster::Method::Exact;   // Method
  std::string name;           // Screenshot, Save: the file name (".png" / ".json" added when missing)
  unsigned line = 0;          // where it is in the file
};

// Parses a script's text; `file` names it in errors ("FILE:LINE: what is wrong").
softraster::Result<std::vector<ScriptCommand>> parseScript(const std::string& text, const std::string& file);
// Reads and parses a script file; an unreadable file is "FILE: cannot read script: reason".
softraster::Result<std::vector<ScriptCommand>> loadScript(const std::filesystem::path& path);

// The script format, for --help.
std::string scriptHelp();

}  // namespace crosscheck::view
