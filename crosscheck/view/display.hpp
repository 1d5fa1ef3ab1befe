// What crosscheck view's loop (viewer.hpp) needs of a window: the keys, showing a picture with
// its text, and a screenshot of what was shown. window.hpp is the SDL2 one; a test can stand in
// its own. Deliberately no drawing and no key mapping here.
#pragma once

#include "view/views.hpp"

#include <softraster/status.hpp>

#include <string>
#include <vector>

namespace crosscheck::view {

struct KeyInput {
  std::vector<std::string> held;     // keys down now (SDL's key names)
  std::vector<std::string> pressed;  // keys that went down since the last poll
  bool closed = false;               // the window was closed
};

// The text around a picture: the status lines under it, and the help drawn over it when shown.
struct Overlay {
  std::vector<std::string> status;
  std::vector<std::string> help;     // a title, then "KEY\tWHAT" lines; empty: hidden
  std::string title;                 // the window's title bar (UTF-8)
};

class Display {
 public:
  virtual ~Display() = default;
  // Events since the last poll; `keyboard` false: only whether the window was closed (a script runs).
  virtual KeyInput poll(bool keyboard) = 0;
  virtual softraster::Status show(const Picture& picture, const Overlay& overlay) = 0;
  // The window as last shown, every pixel (RGBA8, alpha 255).
  virtual softraster::Result<Picture> screenshot() = 0;
};

}  // namespace crosscheck::view
