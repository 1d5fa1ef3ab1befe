// Framebuffer storage, clears (deferred: see framebuffer.hpp), the MSAA resolve and depth read-out.
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace softraster {

std::uint32_t depthClearValue(DepthFormat format, float depth) {
  const int bits = unormDepthBits(format);
  if (bits == 0) return std::bit_cast<std::uint32_t>(depth);
  return static_cast<std::uint32_t>(std::lrint(static_cast<double>(depth) * ((1u << bits) - 1)));
}

Framebuffer::Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat, std::uint32_t samples)
    : width_(width),
      height_(height),
      samples_(samples),
      depthFormat_(depthFormat),
      colour_(static_cast<std::size_t>(width) * height * samples * 4, 0),
      depth_(static_cast<std::size_t>(width) * height * samples, 0) {}

Framebuffer Framebuffer::resolve() const {
  Framebuffer out(width_, height_, depthFormat_, 1);
  resolveInto(out);
  return out;
}

void Framebuffer::resolveInto(Framebuffer& out) const {
  settled();
  if (&out == this) {  // resolving in place: a single-sample framebuffer is its own resolve
    if (samples_ != 1) out = resolve();
    return;
  }
  if (out.width_ != width_ || out.height_ != height_ || out.depthFormat_ != depthFormat_ || out.samples_ != 1) {
    out = Framebuffer(width_, height_, depthFormat_, 1);
  }
  out.pending_.reset();  // every sample of `out` is written here
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  const float toFloat = static_cast<float>(1.0 / 255.0);  // how lavapipe's texel fetch converts UNORM8
  const float average = 1.0f / static_cast<float>(samples_);
  for (std::size_t p = 0; p < pixels; ++p) {
    for (int c = 0; c < 4; ++c) {
      float sum = 0.0f;
      for (std::uint32_t s = 0; s < samples_; ++s) sum = sum + static_cast<float>(colour_[(p * samples_ + s) * 4 + c]) * toFloat;
      out.colour_[p * 4 + c] = samples_ == 1 ? colour_[p * 4 + c] : detail::unorm8FromFloat(sum * average);
    }
    out.depth_[p] = depth_[p * samples_];
  }
}

void Framebuffer::clear(Vec4 colour, float depth) {
  std::uint8_t rgba[4];
  detail::storeColour(rgba, colour);
  PendingClear clear;
  std::memcpy(&clear.colour, rgba, sizeof clear.colour);
  clear.depth = depthClearValue(depthFormat_, depth);
  pending_ = clear;
}

namespace {

// `count` 32-bit words from `out` on set to `value`, in 64-byte pieces (a memset-speed fill).
void fillWords(std::uint8_t* out, std::size_t count, std::uint32_t value) {
  std::uint32_t piece[16];
  for (std::uint32_t& w : piece) w = value;
  std::size_t i = 0;
  for (; i + 16 <= count; i += 16) std::memcpy(out + 4 * i, piece, sizeof piece);
  for (; i < count; ++i) std::memcpy(out + 4 * i, &value, sizeof value);
}

}  // namespace

void Framebuffer::clearRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1) { fillRows(clear, y0, y1); }

void Framebuffer::fillRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1) const {
  if (y0 > y1 || y0 >= height_) return;
  y1 = std::min(y1, height_ - 1);
  const std::size_t perRow = static_cast<std::size_t>(width_) * samples_;
  const std::size_t first = y0 * perRow, count = (y1 - y0 + 1) * perRow;
  fillWords(colour_.data() + 4 * first, count, clear.colour);
  fillWords(reinterpret_cast<std::uint8_t*>(depth_.data() + first), count, clear.depth);
}

void Framebuffer::writePendingClear() const {
  const PendingClear clear = *pending_;
  pending_.reset();
  if (height_ != 0) fillRows(clear, 0, height_ - 1);
}

float Framebuffer::depth(std::size_t sample) const {
  settled();
  const int bits = unormDepthBits(depthFormat_);
  if (bits == 0) return std::bit_cast<float>(depth_[sample]);
  return static_cast<float>(static_cast<double>(depth_[sample]) / ((1u << bits) - 1));
}

}  // namespace softraster
