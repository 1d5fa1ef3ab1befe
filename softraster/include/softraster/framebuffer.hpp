// Framebuffer: one or several colour images (colour attachments 0.., each of its own format:
// R8G8B8A8_UNORM, or B8G8R8A8_UNORM: the same four bytes per sample
// with red and blue swapped; or either as sRGB; or A2B10G10R10_UNORM_PACK32, one word per sample;
// or R16G16B16A16_SFLOAT / R32G32B32A32_SFLOAT, four halves / floats per sample) and a depth image
// (formats.hpp), row 0 at the top,
// with 1 or 4 samples per pixel (samples of a pixel are adjacent, in Vulkan's sample order).
// Depth is kept as the format stores it: UNORM depth as its integer, D32_SFLOAT as its float's
// bits; depthValues() reads it back as floats. A depth/stencil format also has a stencil image,
// one byte per sample in the same order. resolve() averages colour samples as lavapipe's
// resolve blit does (sRGB ones decoded to linear and encoded again, 10-bit and float ones averaged
// as floats and stored as a fragment stores them) and keeps depth and stencil sample 0.
// Attachment 0 is the one the accessors without an attachment number read; a fragment shader's
// output location i goes to attachment i.
// Made by Framebuffer::create, which checks the size, format and sample count and returns the
// error as a Result (a default-constructed Framebuffer has no pixels and no draw accepts it).
// clear() is deferred: it remembers the values, and the next draw that runs in the Context's
// bands writes them band by band, on the band's own thread just before drawing there (so the
// rows are in that core's cache when drawn); any other access to the images writes the whole
// clear first, so a pending clear is never observable. Not thread-safe: one thread at a time
// draws into or reads a Framebuffer (even a const read may write a pending clear).
// Accessors do not check their coordinates beyond an assert (they are preconditions, as for std::vector's operator[]).
// A single-sample framebuffer also keeps, per 32x32 tile, bounds on the depth stored there
// (detail/fast/depth_tiles.hpp): a clear sets them, the fast path's draws keep them, and
// everything else that may write depth forgets them, the mutable depthStorage() included. They
// are a cache that never changes a pixel: a draw uses them only to skip tiles where no fragment
// could pass the depth test.
#pragma once

#include <softraster/formats.hpp>
#include <softraster/math.hpp>
#include <softraster/state.hpp>
#include <softraster/status.hpp>

#include <array>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace softraster {

class Framebuffer;

namespace detail {
// Bounds on the depth stored in one tile of a single-sample framebuffer, as keys
// (depthTileKey: UNORM depth as its integer, D32 as its float): every sample there has lo <= key
// <= hi. [-inf, +inf] when nothing is known.
struct DepthTileRange {
  float lo, hi;
};
inline constexpr int kDepthTileSize = 32;  // pixels per side, tiles at multiples of it
// A stored depth word as a key: ordered as the depth test orders the format's values.
inline float depthTileKey(DepthFormat format, std::uint32_t word) {
  return unormDepthBits(format) == 0 ? std::bit_cast<float>(word) : static_cast<float>(word);
}
struct FramebufferAccess;
}  // namespace detail

// The largest width and height create() accepts: lavapipe's maxFramebufferWidth and Height.
inline constexpr std::uint32_t kMaxFramebufferSize = 16384;

// A colour clear value as the format stores it: the colourBytes(format) bytes of a sample as
// little-endian words (one, two for halves, four for floats; the rest 0). clear() below says how
// each format converts it.
std::array<std::uint32_t, 4> colourClearValue(ColourFormat format, Vec4 colour);

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
  // The same with one colour attachment per format (1..kMaxColourAttachments of them), or the
  // error above or "framebuffer colour attachments N: must be 1..8".
  static Result<Framebuffer> create(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat,
                                    std::uint32_t samples, std::span<const ColourFormat> colourFormats);

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  std::uint32_t samples() const { return samples_; }
  DepthFormat depthFormat() const { return depthFormat_; }
  std::uint32_t colourAttachments() const { return 1 + static_cast<std::uint32_t>(moreFormats_.size()); }
  ColourFormat colourFormat(std::uint32_t attachment = 0) const {
    assert(attachment < colourAttachments());
    return attachment == 0 ? colourFormat_ : moreFormats_[attachment - 1];
  }

  // A single-sample framebuffer: colour = average of the samples (every attachment) (float sum in sample order,
  // times 0.25, stored as UNORM8; sRGB red, green and blue summed as linear values and encoded as
  // the fragment stage stores sRGB; A2B10G10R10 channels summed as v * float(1/1023) (alpha
  // float(1/3)) and stored as a fragment stores them; float channels summed from +0 and multiplied
  // with the resolve shader's FTZ and DAZ, halves stored toward zero), depth = sample 0. A
  // single-sample framebuffer resolves to a copy.
  Framebuffer resolve() const;
  // The same resolve into `out`, reusing its storage when it already has this framebuffer's size
  // and formats with one sample (no allocation per frame). Context::resolveInto (pipeline.hpp)
  // does it on the Context's threads.
  void resolveInto(Framebuffer& out) const;
  // resolveInto in two steps, for a caller that shares the rows out among threads:
  // prepareResolve gives `out` this framebuffer's size and formats with one sample (writing any
  // pending clear of this one first), then resolveRows(out, y0, y1) resolves rows [y0, y1];
  // calls for disjoint rows may run in parallel. `out` must not be this framebuffer.
  void prepareResolve(Framebuffer& out) const;
  void resolveRows(Framebuffer& out, std::uint32_t y0, std::uint32_t y1) const;

  // Clears every colour attachment to `colour` (converted as a UNORM8 store converts; sRGB red, green and blue as lavapipe's
  // clear encodes them, srgb.hpp's linearToSrgbClearByte; A2B10G10R10 as Mesa's format packer
  // does, round(clamp(v) * 1023), alpha round(clamp(a) * 3); halves toward zero, floats as given),
  // depth (as a depth clear converts:
  // lrint(depth * (2^n - 1)) for UNORM formats) and stencil, if the format has it. Deferred, as
  // the top of this file says.
  void clear(Vec4 colour, float depth, std::uint8_t stencil = 0);
  // The same with attachment i cleared to colours[i] (one colour per attachment; a missing one is
  // colours' last, or black without any).
  void clear(std::span<const Vec4> colours, float depth, std::uint8_t stencil = 0);

  // colourBytes(colourFormat(attachment)) bytes per sample in the colour format's order (RGBA, or
  // BGRA; A2B10G10R10's little-endian word; four halves or floats, red first); samples() samples
  // per pixel.
  std::vector<std::uint8_t>& colour(std::uint32_t attachment = 0) {
    assert(attachment < colourAttachments());
    return attachment == 0 ? settled().colour_ : settled().moreColour_[attachment - 1];
  }
  const std::vector<std::uint8_t>& colour(std::uint32_t attachment = 0) const {
    assert(attachment < colourAttachments());
    return attachment == 0 ? settled().colour_ : settled().moreColour_[attachment - 1];
  }

  // Depth as stored, one value per sample (see the top of this file). The mutable one forgets the
  // tiles' depth bounds (top of this file): write through the reference before the next draw,
  // or call it again after a draw before writing.
  std::vector<std::uint32_t>& depthStorage() {
    forgetDepthTiles();
    return settled().depth_;
  }
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

  // Index of sample `sample` of pixel (x, y) in depthStorage(), and times colourBytes in colour().
  std::size_t sampleIndex(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0) const {
    assert(x < width_ && y < height_ && sample < samples_);
    return (static_cast<std::size_t>(y) * width_ + x) * samples_ + sample;
  }
  // The R, G, B and A bytes of one sample of pixel (x, y) of a colour attachment, in that order
  // whatever the format stores; (0, 0) is the top-left pixel. The 10-bit and float formats are
  // scaled to bytes (viewBytes: a view; their exact bits are in colour()).
  std::array<std::uint8_t, 4> colourAt(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0,
                                       std::uint32_t attachment = 0) const {
    const ColourFormat format = colourFormat(attachment);
    return viewBytes(format, colour(attachment).data() + colourBytes(format) * sampleIndex(x, y, sample));
  }
  // One stored sample of `format` as R, G, B, A bytes: 8-bit formats as stored (B8G8R8A8's red and
  // blue swapped back); a 10-bit v as (v * 255 + 511) / 1023 (the nearest byte), the 2-bit alpha a
  // as a * 85; halves and floats clamped to [0, 1] (NaN to 0) and rounded as a UNORM8 store.
  static std::array<std::uint8_t, 4> viewBytes(ColourFormat format, const std::uint8_t* sample);
  // One sample's depth as depth() converts it.
  float depthAt(std::uint32_t x, std::uint32_t y, std::uint32_t sample = 0) const { return depth(sampleIndex(x, y, sample)); }

  // For the draw loop's bands: a clear's values, one word per sample each.
  struct PendingClear {
    std::array<std::array<std::uint32_t, 4>, kMaxColourAttachments> colour;  // per attachment, as stored (colourClearValue)
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
              std::span<const ColourFormat> colourFormats);

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
  // Every tile's depth bounds [-inf, +inf] (nothing known).
  void forgetDepthTiles();

  friend struct detail::FramebufferAccess;

  std::uint32_t width_ = 0, height_ = 0, samples_ = 1;
  DepthFormat depthFormat_ = DepthFormat::D32Sfloat;
  ColourFormat colourFormat_ = ColourFormat::R8G8B8A8Unorm;
  mutable std::optional<PendingClear> pending_;
  std::vector<ColourFormat> moreFormats_;  // colour attachments 1..
  mutable std::vector<std::uint8_t> colour_;  // attachment 0
  mutable std::vector<std::vector<std::uint8_t>> moreColour_;  // attachments 1..
  mutable std::vector<std::uint32_t> depth_;
  mutable std::vector<std::uint8_t> stencil_;  // empty without a stencil aspect
  // Single-sample only (else empty): per tile of kDepthTileSize pixels square, row by row.
  std::vector<detail::DepthTileRange> depthTiles_;
};

namespace detail {
// What softraster's draws reach inside a Framebuffer beyond its public interface.
struct FramebufferAccess {
  // The depth words, without forgetting the tiles' bounds: for a fragment stage, whose draw
  // either keeps the bounds or has forgotten them (detail/fast/depth_tiles.hpp).
  static std::uint32_t* depthWords(Framebuffer& f) { return f.settled().depth_.data(); }
  // The tiles' bounds, ceil(width / kDepthTileSize) per row; empty with 4 samples.
  static std::span<DepthTileRange> depthTiles(Framebuffer& f) { return f.depthTiles_; }
  static std::uint32_t depthTilesPerRow(const Framebuffer& f) {
    return (f.width_ + kDepthTileSize - 1) / kDepthTileSize;
  }
  static void forgetDepthTiles(Framebuffer& f) { f.forgetDepthTiles(); }
};
}  // namespace detail

}  // namespace softraster
