// Framebuffer: a colour image (R8G8B8A8_UNORM, or B8G8R8A8_UNORM: the same four bytes per sample
// with red and blue swapped; or either as sRGB) and a depth image (formats.hpp), row 0 at the top,
// with 1 or 4 samples per pixel (samples of a pixel are adjacent, in Vulkan's sample order).
// Depth is kept as the format stores it: UNORM depth as its integer, D32_SFLOAT as its float's
// bits; depthValues() reads it back as floats. A depth/stencil format also has a stencil image,
// one byte per sample in the same order. resolve() averages colour samples as lavapipe's
// resolve blit does (sRGB ones decoded to linear and encoded again) and keeps depth and stencil
// sample 0.
// Made by Framebuffer::create, which checks the size, format and sample count and returns the
// error as a Result (a default-constructed Framebuffer has no pixels and no draw accepts it).
// clear() is deferred: it remembers the values, and the next draw that runs in the Context's
// bands writes them band by band, on the band's own thread just before drawing there (so the
// rows are in that core's cache when drawn); any other access to the images writes the whole
// clear first, so a pending clear is never observable. Not thread-safe: one thread at a time
// draws into or reads a Framebuffer (even a const read may write a pending clear).
// Accessors do not check their coordinates beyond an assert (they are preconditions, as for std::vector's operator[]).
#pragma once

#include <softraster/formats.hpp>
#include <softraster/math.hpp>
#include <softraster/status.hpp>

#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace softraster {

// The largest width and height create() accepts: lavapipe's maxFramebufferWidth and Height.
inline constexpr std::uint32_t kMaxFramebufferSize = 16384;

class Framebuffer {
 public:
  Framebuffer() = default;  // no pixels: only a target for assignment

  // A width x height framebuffer with `samples` samples per pixel (1, or 4: Vulkan's standard
  // 4x pattern), or the error: "framebuffer size WxH: width and height must be 1..16384",
  // "framebuffer samples N: must be 1 or 4", "unknown depth format", "unknown colour format".
  // A format with a stencil aspect (hasStencil) gets a stencil image, cleared to 0.
  static Result<Framebuffer> create(std::uint32_t width, std::uint32_t height,
                                    DepthFormat depthFormat = DepthFormat::D32Sfloat, std::uint32_t samples = 1,
                                    ColourFormat colourFormat = ColourFormat::R8G8B8A8Unorm);

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t samples() const { return samples_; }
  DepthFormat depthFormat() const { return depthFormat_; }
  ColourFormat colourFormat() const { return colourFormat_; }

  // A single-sample framebuffer: colour = average of the samples (float sum in sample order,
  // times 0.25, stored as UNORM8; sRGB red, green and blue summed as linear values and encoded as
  // the fragment stage stores sRGB), depth = sample 0. A single-sample framebuffer resolves to a copy.
  Framebuffer resolve() const;
  // The same resolve into `out`, reusing its storage when it already has this framebuffer's size
  // and formats with one sample (no allocation per frame).
  void resolveInto(Framebuffer& out) const;

  // Clears colour (converted as a UNORM8 store converts; sRGB red, green and blue as lavapipe's
  // clear encodes them, srgb.hpp's linearToSrgbClearByte), depth (as a depth clear converts:
  // lrint(depth * (2^n - 1)) for UNORM formats) and stencil, if the format has it. Deferred, as
  // the top of this file says.
  void clear(Vec4 colour, float depth, std::uint8_t stencil = 0);

  // 4 bytes per sample in the colour format's order (RGBA, or BGRA); samples() samples per pixel.
  std::vector<std::uint8_t>& colour() { return settled().colour_; }
  const std::vector<std::uint8_t>& colour() const { return settled().colour_; }

  // Depth as stored, one value per sample (see the top of this file).
  std::vector<std::uint32_t>& depthStorage() { return settled().depth_; }
  const std::vector<std::uint32_t>& depthStorage() const { return settled().depth_; }
  // Stencil, one byte per sample in depthStorage()'s order; empty without a stencil aspect.
  std::vector<std::uint8_t>& stencilStorage() { return settled().stencil_; }
  const std::vector<std::uint8_t>& stencilStorage() const { return settled().stencil_; }
  // Depth of one sample (index into depthStorage()) as a float: in [0, 1] for Vulkan depth (the
  // UNORM integer divided by 2^n - 1), 1/w for the 1/z buffer (D32_SFLOAT's float as stored).
  float depth(std::size_t sample) const;
  // Every sample's depth as depth() converts it, in depthStorage()'s order (one allocation; the
  // Into form reuses `out`'s storage).
  std::vector<float> depthValues() const;
  void depthValuesInto(std::vector<float>& out) const;

  // Index of sample `sample` of pixel (x, y) in depthStorage(), and times 4 in colour().
  std::size_t sampleIndex(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0) const {
    assert(x < width_ && y < height_ && sample < samples_);
    return (static_cast<std::size_t>(y) * width_ + x) * samples_ + sample;
  }
  // The R, G, B and A bytes of one sample of pixel (x, y), in that order whatever the format
  // stores; (0, 0) is the top-left pixel.
  std::array<std::uint8_t, 4> colourAt(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0) const {
    const std::uint8_t* p = colour().data() + 4 * sampleIndex(x, y, sample);
    if (swapsRedBlue(colourFormat_)) return {p[2], p[1], p[0], p[3]};
    return {p[0], p[1], p[2], p[3]};
  }
  // One sample's depth as depth() converts it.
  float depthAt(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0) const { return depth(sampleIndex(x, y, sample)); }

  // For the draw loop's bands: a clear's values, one word per sample each.
  struct PendingClear {
    std::uint32_t colour;  // as stored (RGBA8 or BGRA8)
    std::uint32_t depth;   // as stored
    std::uint8_t stencil;  // written only where the format has stencil
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
  Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat, std::uint32_t samples,
              ColourFormat colourFormat);

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
  ColourFormat colourFormat_ = ColourFormat::R8G8B8A8Unorm;
  mutable std::optional<PendingClear> pending_;
  mutable std::vector<std::uint8_t> colour_;
  mutable std::vector<std::uint32_t> depth_;
  mutable std::vector<std::uint8_t> stencil_;  // empty without a stencil aspect
};

}  // namespace softraster
