// Framebuffer: an R8G8B8A8_UNORM colour image and a D32_SFLOAT depth image, row 0 at the top.
// Deliberately single-sample and without stencil until a scene needs more.
#pragma once

#include <softraster/math.hpp>
#include <softraster/status.hpp>

#include <cstdint>
#include <vector>

namespace softraster {

class Framebuffer {
 public:
  Framebuffer() = default;
  Framebuffer(std::uint32_t width, std::uint32_t height);

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }

  // Clears colour (converted as a UNORM8 store converts) and depth.
  void clear(Vec4 colour, float depth);

  // 4 bytes per pixel, RGBA.
  std::vector<std::uint8_t>& colour() { return colour_; }
  const std::vector<std::uint8_t>& colour() const { return colour_; }
  std::vector<float>& depth() { return depth_; }
  const std::vector<float>& depth() const { return depth_; }

 private:
  std::uint32_t width_ = 0, height_ = 0;
  std::vector<std::uint8_t> colour_;
  std::vector<float> depth_;
};

}  // namespace softraster
