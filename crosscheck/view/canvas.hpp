// crosscheck view's window contents, drawn on the CPU into one RGBA8 image the size of the
// window: the picture (views.hpp) scaled by nearest neighbour, each pane's label, the status lines
// in a band under it and the help over it. Text is stb_easy_font's (libstb-dev, already a
// dependency): a tiny vector font of rectangles, so no font file is needed; it is ASCII only
// (the title bar carries the UTF-8 "|Δ|", the canvas "|d|").
// The layout is fixed once per scene: room for two panes (2W x H) scaled by a whole number up to 4
// while it fits 1400 x 900, else scaled down, so no view changes the window's size; one-pane
// views are centred. Drawing it here rather than through SDL's renderer keeps the window code to
// a blit (SDL's software renderer took ~25 ms a frame for the text's rectangles under Xvfb) and
// makes a screenshot exactly what was shown.
// Deliberately no SDL here.
#pragma once

#include "view/display.hpp"
#include "view/views.hpp"

#include <cstdint>

namespace crosscheck::view {

inline constexpr int kStatusLines = 6;  // the band under the picture

struct CanvasLayout {
  std::uint32_t width = 0, height = 0;  // the window
  double scale = 1;                     // window pixels per picture pixel
  std::uint32_t imageHeight = 0;        // the picture's part of the window, from the top
  int textScale = 1;                    // one font pixel is textScale x textScale window pixels
  int lineHeight = 12;
};
CanvasLayout canvasLayout(std::uint32_t sceneWidth, std::uint32_t sceneHeight);

// The window's pixels (alpha 255) for `picture` and `overlay` in `layout`.
Picture drawCanvas(const CanvasLayout& layout, const Picture& picture, const Overlay& overlay);

}  // namespace crosscheck::view
