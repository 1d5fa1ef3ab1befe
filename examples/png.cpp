// writePng through stb_image_write (the single-header library, compiled here once).
// Deliberately the only file that includes stb: its warnings stay out of the examples.
#include "png.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

bool writePng(const std::string& path, std::uint32_t width, std::uint32_t height, const std::vector<std::uint8_t>& rgba) {
  const int w = static_cast<int>(width), h = static_cast<int>(height);
  return stbi_write_png(path.c_str(), w, h, 4, rgba.data(), w * 4) != 0;
}
