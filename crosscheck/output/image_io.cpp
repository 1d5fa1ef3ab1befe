// PNG writing and depth visualisation (see image_io.hpp).
#include "output/image_io.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace {

// stb_image_write's own deflate is quick but weak (a black 320x240 diff image: 3254 bytes); zlib
// at level 9 makes the report's many PNGs several times smaller (the same one: a few hundred).
// stb frees the buffer with free().
unsigned char* zlibCompress(unsigned char* data, int length, int* outLength, int /*quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out || compress2(out, &size, data, static_cast<uLong>(length), Z_BEST_COMPRESSION) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *outLength = static_cast<int>(size);
  return out;
}

}  // namespace

// stb_image_write compiled here, private to this file (static), so it can use zlib; Debian's
// libstb keeps its own copy for whoever else links it. Its unused writers (BMP, TGA, JPEG, HDR)
// would warn as unused static functions.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ZLIB_COMPRESS zlibCompress
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace crosscheck {

softraster::Status writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                            const std::vector<std::uint8_t>& rgba) {
  if (path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
  }
  // Opaque images as RGB: a quarter less to compress, the same pixels to a reader.
  bool opaque = true;
  for (std::size_t i = 3; i < rgba.size() && opaque; i += 4) opaque = rgba[i] == 255;
  std::vector<std::uint8_t> rgb;
  if (opaque) {
    rgb.resize(rgba.size() / 4 * 3);
    for (std::size_t i = 0, o = 0; i < rgba.size(); i += 4, o += 3) std::copy_n(&rgba[i], 3, &rgb[o]);
  }
  const int channels = opaque ? 3 : 4;
  if (!stbi_write_png(path.string().c_str(), static_cast<int>(width), static_cast<int>(height), channels,
                      opaque ? rgb.data() : rgba.data(), static_cast<int>(width) * channels)) {
    return softraster::Status::error(path.string() + ": cannot write PNG");
  }
  return {};
}

std::vector<std::uint8_t> depthToGrey(const std::vector<float>& depth, float clearDepth, float lo, float hi) {
  if (!(lo < hi)) {
    lo = 1, hi = 0;
    for (float z : depth) {
      if (z != clearDepth && std::isfinite(z)) lo = std::min(lo, z), hi = std::max(hi, z);
    }
    if (!(lo < hi)) lo = 0, hi = 1;
  }
  std::vector<std::uint8_t> out(depth.size() * 4);
  for (std::size_t i = 0; i < depth.size(); ++i) {
    const float t = std::clamp((depth[i] - lo) / (hi - lo), 0.0f, 1.0f);
    const auto g = static_cast<std::uint8_t>(std::lround(std::isfinite(t) ? t * 255.0f : 255.0f));
    out[4 * i] = out[4 * i + 1] = out[4 * i + 2] = g;
    out[4 * i + 3] = 255;
  }
  return out;
}

}  // namespace crosscheck
