// Framebuffer storage, clears and depth read-out.
#include <softraster/detail/output_merger.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace softraster {

std::uint32_t depthClearValue(DepthFormat format, float depth) {
  const int bits = unormDepthBits(format);
  if (bits == 0) return std::bit_cast<std::uint32_t>(depth);
  return static_cast<std::uint32_t>(std::lrint(static_cast<double>(depth) * ((1u << bits) - 1)));
}

Framebuffer::Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat)
    : width_(width),
      height_(height),
      depthFormat_(depthFormat),
      colour_(static_cast<std::size_t>(width) * height * 4, 0),
      depth_(static_cast<std::size_t>(width) * height, 0) {}

void Framebuffer::clear(Vec4 colour, float depth) {
  std::uint8_t rgba[4];
  detail::storeColour(rgba, colour);
  for (std::size_t i = 0; i < colour_.size(); i += 4) {
    std::copy(rgba, rgba + 4, colour_.begin() + static_cast<std::ptrdiff_t>(i));
  }
  std::fill(depth_.begin(), depth_.end(), depthClearValue(depthFormat_, depth));
}

float Framebuffer::depth(std::size_t pixel) const {
  const int bits = unormDepthBits(depthFormat_);
  if (bits == 0) return std::bit_cast<float>(depth_[pixel]);
  return static_cast<float>(static_cast<double>(depth_[pixel]) / ((1u << bits) - 1));
}

}  // namespace softraster
