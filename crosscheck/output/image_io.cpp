// PNG writing and depth visualisation (see image_io.hpp).
#include "output/image_io.hpp"

#include <stb_image_write.h>

#include <algorithm>
#include <cmath>

namespace crosscheck {

softraster::Status writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height,
                            const std::vector<std::uint8_t>& rgba) {
  if (path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
  }
  if (!stbi_write_png(path.string().c_str(), static_cast<int>(width), static_cast<int>(height), 4, rgba.data(),
                      static_cast<int>(width * 4))) {
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
