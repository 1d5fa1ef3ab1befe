// crosscheck view's window contents (see canvas.hpp).
#include "view/canvas.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

namespace crosscheck::view {
namespace {

using Colour = std::array<std::uint8_t, 3>;

struct Canvas {
  const CanvasLayout& layout;
  Picture& out;

  // Fills [x0, x1) x [y0, y1), clipped; alpha in 0..255 blends over what is there.
  void fill(int x0, int y0, int x1, int y1, Colour c, int alpha = 255) {
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, static_cast<int>(out.width));
    y1 = std::min(y1, static_cast<int>(out.height));
    for (int y = y0; y < y1; ++y) {
      std::uint8_t* p = out.rgba.data() + (static_cast<std::size_t>(y) * out.width + x0) * 4;
      if (alpha == 255) {
        for (int x = x0; x < x1; ++x, p += 4) p[0] = c[0], p[1] = c[1], p[2] = c[2];
        continue;
      }
      for (int x = x0; x < x1; ++x, p += 4) {
        for (int k = 0; k < 3; ++k) p[k] = static_cast<std::uint8_t>((c[k] * alpha + p[k] * (255 - alpha) + 127) / 255);
      }
    }
  }

  static int width(const std::string& line) {
    std::vector<char> chars(line.begin(), line.end());
    chars.push_back('\0');
    return stb_easy_font_width(chars.data());
  }

  // Text with its top left at (x, y), on a dark box when `box`.
  void text(int x, int y, const std::string& line, Colour c, bool box) {
    if (line.empty()) return;
    std::vector<char> chars(line.begin(), line.end());
    chars.push_back('\0');
    std::vector<char> buffer(chars.size() * 300 + 1024);  // stb: ~270 bytes a character
    const int quads = stb_easy_font_print(0, 0, chars.data(), nullptr, buffer.data(), static_cast<int>(buffer.size()));
    const int s = layout.textScale;
    if (box) fill(x - 3, y - 2, x + stb_easy_font_width(chars.data()) * s + 3, y + layout.lineHeight - 2, {0, 0, 0}, 170);
    for (int q = 0; q < quads; ++q) {
      const float* v0 = reinterpret_cast<const float*>(buffer.data() + q * 64);       // vertex 0: x, y, z, colour
      const float* v2 = reinterpret_cast<const float*>(buffer.data() + q * 64 + 32);  // vertex 2: the opposite corner
      fill(x + static_cast<int>(v0[0]) * s, y + static_cast<int>(v0[1]) * s, x + static_cast<int>(v2[0]) * s,
           y + static_cast<int>(v2[1]) * s, c);
    }
  }
};

}  // namespace

CanvasLayout canvasLayout(std::uint32_t sceneWidth, std::uint32_t sceneHeight) {
  CanvasLayout l;
  const double width = 2.0 * sceneWidth, height = sceneHeight;
  int whole = 0;
  for (int k = 4; k >= 1 && whole == 0; --k) {
    if (k * width <= 1400 && k * height <= 900) whole = k;
  }
  l.scale = whole != 0 ? whole : std::min(1400 / width, 900 / height);
  l.width = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(width * l.scale)));
  l.imageHeight = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(height * l.scale)));
  l.textScale = l.width >= 1000 ? 2 : 1;
  l.lineHeight = 12 * l.textScale;
  l.height = l.imageHeight + kStatusLines * l.lineHeight + 10;
  return l;
}

Picture drawCanvas(const CanvasLayout& layout, const Picture& picture, const Overlay& overlay) {
  Picture out;
  out.width = layout.width;
  out.height = layout.height;
  out.rgba.resize(std::size_t{out.width} * out.height * 4);
  const std::uint32_t background = 0xff181818;  // RGBA 24, 24, 24, 255 in either byte order
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) std::memcpy(out.rgba.data() + i, &background, 4);
  Canvas canvas{layout, out};
  if (!picture.rgba.empty() && picture.width != 0 && picture.height != 0) {
    // Nearest neighbour: window pixel (x, y) shows picture pixel (x / scale, y / scale); a window
    // row that shows the same picture row as the one above is a copy of it.
    const std::uint32_t w = std::min<std::uint32_t>(out.width, static_cast<std::uint32_t>(std::lround(picture.width * layout.scale)));
    const std::uint32_t h = std::min<std::uint32_t>(layout.imageHeight, static_cast<std::uint32_t>(std::lround(picture.height * layout.scale)));
    const std::uint32_t left = (out.width - w) / 2;
    std::vector<std::uint32_t> column(w);
    for (std::uint32_t x = 0; x < w; ++x) column[x] = std::min(picture.width - 1, static_cast<std::uint32_t>(x / layout.scale));
    std::uint32_t previous = picture.height;
    for (std::uint32_t y = 0; y < h; ++y) {
      const std::uint32_t row = std::min(picture.height - 1, static_cast<std::uint32_t>(y / layout.scale));
      std::uint8_t* to = out.rgba.data() + (std::size_t{y} * out.width + left) * 4;
      if (row == previous) {
        std::memcpy(to, to - std::size_t{out.width} * 4, std::size_t{w} * 4);
        continue;
      }
      previous = row;
      const std::uint8_t* from = picture.rgba.data() + std::size_t{row} * picture.width * 4;
      for (std::uint32_t x = 0; x < w; ++x, to += 4) {
        std::memcpy(to, from + std::size_t{column[x]} * 4, 4);
        to[3] = 255;
      }
    }
    for (const Pane& pane : picture.panes) {
      canvas.text(static_cast<int>(left + std::lround(pane.x * layout.scale)) + 6, 4, pane.label, {255, 255, 255}, true);
    }
  }
  int y = static_cast<int>(layout.imageHeight) + 6;
  for (const std::string& line : overlay.status) {
    canvas.text(6, y, line, {230, 230, 230}, false);
    y += layout.lineHeight;
  }
  if (!overlay.help.empty()) {  // the title, then the keys in two columns: key, then what it does
    const int rows = static_cast<int>(overlay.help.size()) / 2;  // (size - 1 + 1) / 2
    const int top = layout.lineHeight * 2, lh = layout.lineHeight, w = static_cast<int>(out.width);
    canvas.fill(8, top - 6, w - 8, top + lh * (rows + 1) + 4, {0, 0, 0}, 215);
    canvas.text(16, top, overlay.help[0], {255, 255, 255}, false);
    const int keyWidth = Canvas::width("PageDown  ") * layout.textScale;
    for (std::size_t i = 1; i < overlay.help.size(); ++i) {
      const int row = static_cast<int>(i - 1) % std::max(rows, 1), column = static_cast<int>(i - 1) / std::max(rows, 1);
      const int x = 16 + column * (w - 32) / 2, ly = top + lh * (row + 1);
      const std::string& line = overlay.help[i];
      const auto tab = line.find('\t');
      canvas.text(x, ly, line.substr(0, tab), {255, 255, 160}, false);
      if (tab != std::string::npos) canvas.text(x + keyWidth, ly, line.substr(tab + 1), {230, 230, 230}, false);
    }
  }
  return out;
}

}  // namespace crosscheck::view
