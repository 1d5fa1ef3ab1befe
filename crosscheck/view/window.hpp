// crosscheck view's window (SDL2): shows what canvas.hpp draws (the picture, its labels, the
// status band, the help) by copying it onto the window's surface, reads the keyboard as SDL's key
// names, and hands back what it showed as the screenshot. Takes X (or Wayland where
// WAYLAND_DISPLAY is set); with no display named, or only SDL's offscreen driver, it is an error
// rather than a window no one sees.
// Deliberately the only file that includes SDL (the rest of view/ is tested without a display);
// without SDL2 the build takes window_none.cpp instead.
#pragma once

#include "view/display.hpp"

#include <softraster/status.hpp>

#include <cstdint>
#include <memory>
#include <string>

namespace crosscheck::view {

// The error is "view: cannot open a window: SDL's reason" plus a hint about the display, or, in
// a crosscheck built without SDL2 (window_none.cpp), that it was.
softraster::Result<std::unique_ptr<Display>> openWindow(std::uint32_t sceneWidth, std::uint32_t sceneHeight,
                                                        const std::string& title);

}  // namespace crosscheck::view
