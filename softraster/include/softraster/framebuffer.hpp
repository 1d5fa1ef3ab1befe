// Framebuffer: an R8G8B8A8_UNORM colour image and a depth image (formats.hpp), row 0 at the top,
// with 1 or 4 samples per pixel (samples of a pixel are adjacent). Depth is kept as the format
// stores it: UNORM depth as its integer, D32_SFLOAT as its float's bits. resolve() averages
// colour samples as lavapipe's resolve blit does and keeps depth sample 0.
// Deliberately without stencil until a scene needs it.
#pragma once

#include <softraster/formats.hpp>
#include <softraster/math.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace softraster {

class Framebuffer {
 public:
  Framebuffer() = default;
  // samples: 1 or 4 (the Vulkan standard 4x pattern).
  Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat = DepthFormat::D32Sfloat,
              std::uint32_t samples = 1);

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t samples() const { return samples_; }
  DepthFormat depthFormat() const { return depthFormat_; }

  // A single-sample framebuffer: colour = average of the samples (float sum in sample order,
  // times 0.25, stored as UNORM8), depth = sample 0. A single-sample framebuffer resolves to a copy.
  Framebuffer resolve() const;
  // The same resolve into `out`, reusing its storage when it already has this framebuffer's size
  // and depth format with one sample (no allocation per frame).
  void resolveInto(Framebuffer& out) const;

  // Clears colour (converted as a UNORM8 store converts) and depth (as a depth clear converts:
  // lrint(depth * (2^n - 1)) for UNORM formats).
  void clear(Vec4 colour, float depth);

  // 4 bytes per sample, RGBA; samples() samples per pixel.
  std::vector<std::uint8_t>& colour() { return colour_; }
  const std::vector<std::uint8_t>& colour() const { return colour_; }

  // Depth as stored, one value per sample (see the top of this file).
  std::vector<std::uint32_t>& depthStorage() { return depth_; }
  const std::vector<std::uint32_t>& depthStorage() const { return depth_; }
  // Depth of one sample (index into depthStorage()) as a float in [0, 1].
  float depth(std::size_t sample) const;

 private:
  std::uint32_t width_ = 0, height_ = 0, samples_ = 1;
  DepthFormat depthFormat_ = DepthFormat::D32Sfloat;
  std::vector<std::uint8_t> colour_;
  std::vector<std::uint32_t> depth_;
};

}  // namespace softraster
