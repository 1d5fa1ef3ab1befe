// Framebuffer storage and clears.
#include <softraster/detail/output_merger.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>

namespace softraster {

Framebuffer::Framebuffer(std::uint32_t width, std::uint32_t height)
    : width_(width),
      height_(height),
      colour_(static_cast<std::size_t>(width) * height * 4, 0),
      depth_(static_cast<std::size_t>(width) * height, 1.0f) {}

void Framebuffer::clear(Vec4 colour, float depth) {
  std::uint8_t rgba[4];
  detail::storeColour(rgba, colour);
  for (std::size_t i = 0; i < colour_.size(); i += 4) {
    std::copy(rgba, rgba + 4, colour_.begin() + static_cast<std::ptrdiff_t>(i));
  }
  std::fill(depth_.begin(), depth_.end(), depth);
}

}  // namespace softraster
