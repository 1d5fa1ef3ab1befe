// Framebuffer: an R8G8B8A8_UNORM colour image and a depth image (formats.hpp), row 0 at the top,
// with 1 or 4 samples per pixel (samples of a pixel are adjacent). Depth is kept as the format
// stores it: UNORM depth as its integer, D32_SFLOAT as its float's bits. resolve() averages
// colour samples as lavapipe's resolve blit does and keeps depth sample 0.
// clear() is deferred: it remembers the values, and the next draw that runs in the Context's
// bands writes them band by band, on the band's own thread just before drawing there (so the
// rows are in that core's cache when drawn); any other access to the images writes the whole
// clear first, so a pending clear is never observable.
// Deliberately without stencil until a scene needs it.
#pragma once

#include <softraster/formats.hpp>
#include <softraster/math.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
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
  // lrint(depth * (2^n - 1)) for UNORM formats). Deferred, as the top of this file says.
  void clear(Vec4 colour, float depth);

  // 4 bytes per sample, RGBA; samples() samples per pixel.
  std::vector<std::uint8_t>& colour() { return settled().colour_; }
  const std::vector<std::uint8_t>& colour() const { return settled().colour_; }

  // Depth as stored, one value per sample (see the top of this file).
  std::vector<std::uint32_t>& depthStorage() { return settled().depth_; }
  const std::vector<std::uint32_t>& depthStorage() const { return settled().depth_; }
  // Depth of one sample (index into depthStorage()) as a float in [0, 1].
  float depth(std::size_t sample) const;

  // For the draw loop's bands: a clear's values, one word per sample each.
  struct PendingClear {
    std::uint32_t colour;  // RGBA8
    std::uint32_t depth;   // as stored
  };
  // Hands over the clear not yet written, if any: the caller then writes every row with
  // clearRows() before anything reads or draws there.
  std::optional<PendingClear> takePendingClear() {
    std::optional<PendingClear> clear = pending_;
    pending_.reset();
    return clear;
  }
  bool clearPending() const { return pending_.has_value(); }
  // Writes `clear` to every sample of rows [y0, y1]; calls for disjoint rows may run in parallel.
  void clearRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1);

 private:
  // This framebuffer with any pending clear written: the images are its observable state, so
  // even a const access writes a pending clear first (hence the mutable members).
  Framebuffer& settled() {
    if (pending_) writePendingClear();
    return *this;
  }
  const Framebuffer& settled() const {
    if (pending_) writePendingClear();
    return *this;
  }
  void writePendingClear() const;
  void fillRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1) const;

  std::uint32_t width_ = 0, height_ = 0, samples_ = 1;
  DepthFormat depthFormat_ = DepthFormat::D32Sfloat;
  mutable std::optional<PendingClear> pending_;
  mutable std::vector<std::uint8_t> colour_;
  mutable std::vector<std::uint32_t> depth_;
};

}  // namespace softraster
