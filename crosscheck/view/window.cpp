// crosscheck view's SDL2 window (see window.hpp): canvas.hpp draws the window's pixels, this file
// opens the window, copies them onto its surface and reads the keyboard.
#include "view/window.hpp"

#include "view/canvas.hpp"

#define SDL_MAIN_HANDLED
#include <SDL.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace crosscheck::view {
namespace {

class Window : public Display {
 public:
  Window(SDL_Window* window, const CanvasLayout& layout) : window_(window), layout_(layout) {}
  ~Window() override {
    SDL_DestroyWindow(window_);
    SDL_Quit();  // all of SDL, its D-Bus connection too
  }

  KeyInput poll(bool keyboard) override {
    KeyInput input;
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
      if (event.type == SDL_QUIT) input.closed = true;
      if (event.type == SDL_WINDOWEVENT && event.window.event == SDL_WINDOWEVENT_CLOSE) input.closed = true;
      if (keyboard && event.type == SDL_KEYDOWN && !event.key.repeat) {
        input.pressed.emplace_back(SDL_GetKeyName(event.key.keysym.sym));
      }
    }
    if (keyboard) {
      int count = 0;
      const Uint8* state = SDL_GetKeyboardState(&count);
      for (int code = 0; code < count; ++code) {
        if (state[code]) input.held.emplace_back(SDL_GetKeyName(SDL_GetKeyFromScancode(static_cast<SDL_Scancode>(code))));
      }
    }
    return input;
  }

  softraster::Status show(const Picture& picture, const Overlay& overlay) override {
    shown_ = drawCanvas(layout_, picture, overlay);
    if (overlay.title != title_) {
      title_ = overlay.title;
      SDL_SetWindowTitle(window_, title_.c_str());
    }
    SDL_Surface* surface = SDL_GetWindowSurface(window_);
    if (!surface) return softraster::Status::error(std::string("view: the window has no surface: ") + SDL_GetError());
    if (SDL_MUSTLOCK(surface)) SDL_LockSurface(surface);
    const int w = std::min(surface->w, static_cast<int>(shown_.width)), h = std::min(surface->h, static_cast<int>(shown_.height));
    const int converted = SDL_ConvertPixels(w, h, SDL_PIXELFORMAT_RGBA32, shown_.rgba.data(), static_cast<int>(shown_.width * 4),
                                            surface->format->format, surface->pixels, surface->pitch);
    if (SDL_MUSTLOCK(surface)) SDL_UnlockSurface(surface);
    if (converted != 0 || SDL_UpdateWindowSurface(window_) != 0) {
      return softraster::Status::error(std::string("view: cannot draw the window: ") + SDL_GetError());
    }
    return {};
  }

  softraster::Result<Picture> screenshot() override { return shown_; }

 private:
  SDL_Window* window_;
  CanvasLayout layout_;
  Picture shown_;  // the window's pixels as last shown
  std::string title_;
};

}  // namespace

softraster::Result<std::unique_ptr<Display>> openWindow(std::uint32_t sceneWidth, std::uint32_t sceneHeight,
                                                        const std::string& title) {
  SDL_SetMainReady();
  const auto failed = [](const char* what) {
    std::string hint;
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) {
      hint = " (DISPLAY is not set: run it on a desktop, or under xvfb-run -a)";
    } else if (display && *display) {
      hint = std::string(" (DISPLAY=") + display + ": is an X server running there?)";
    }
    return softraster::Status::error(std::string("view: cannot open a window: ") + what + ": " + SDL_GetError() + hint);
  };
  // No display named at all: say so before SDL tries its drivers (and Wayland's library prints
  // its own complaint). With X alone, X is the driver to take.
  const char* asked = std::getenv("SDL_VIDEODRIVER");
  const auto set = [](const char* name) { return std::getenv(name) && *std::getenv(name); };
  if (!(asked && *asked)) {
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY")) {
      SDL_SetError("no display");
      return failed("SDL_Init");
    }
    if (!set("WAYLAND_DISPLAY")) SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
  }
  if (SDL_InitSubSystem(SDL_INIT_VIDEO) != 0) return failed("SDL_Init");
  // Without a display SDL falls back to its offscreen driver, a window no one sees that would
  // wait for keys forever; only asked for by name (SDL_VIDEODRIVER=offscreen) is it taken.
  const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
  if ((driver == "offscreen" || driver == "dummy" || driver == "evdev") && !(asked && driver == asked)) {
    SDL_SetError("no display (SDL found only its '%s' video driver)", driver.c_str());
    const softraster::Status status = failed("SDL_Init");
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    return status;
  }
  // The window's surface straight through X (shared memory), not through an OpenGL texture: under
  // Xvfb that GL is llvmpipe, and it cost ~40 ms a frame for a 1280 x 634 window.
  SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
  const CanvasLayout layout = canvasLayout(sceneWidth, sceneHeight);
  SDL_Window* window = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                                        static_cast<int>(layout.width), static_cast<int>(layout.height), 0);
  if (!window) {
    const softraster::Status status = failed("SDL_CreateWindow");
    SDL_QuitSubSystem(SDL_INIT_VIDEO);
    return status;
  }
  return std::unique_ptr<Display>(new Window(window, layout));
}

}  // namespace crosscheck::view
