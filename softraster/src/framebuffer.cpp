// Framebuffer creation (the checks create() documents), storage, clears (deferred: see
// framebuffer.hpp; the colour swizzled to the format's byte order), the MSAA resolve (SSE2 where
// the build has it, the same operations per channel, so blind to the channels' order; stencil
// keeps sample 0 as depth does) and depth read-out (one sample, or all of them as floats).
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/srgb.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace softraster {

std::uint32_t depthClearValue(DepthFormat format, float depth) {
  const int bits = unormDepthBits(format);
  if (bits == 0) return std::bit_cast<std::uint32_t>(depth);
  return static_cast<std::uint32_t>(std::lrint(static_cast<double>(depth) * ((1u << bits) - 1)));
}

Result<Framebuffer> Framebuffer::create(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat,
                                        std::uint32_t samples, ColourFormat colourFormat) {
  if (width == 0 || height == 0 || width > kMaxFramebufferSize || height > kMaxFramebufferSize) {
    return Status::error("framebuffer size " + std::to_string(width) + "x" + std::to_string(height) +
                         ": width and height must be 1.." + std::to_string(kMaxFramebufferSize));
  }
  if (samples != 1 && samples != 4) {
    return Status::error("framebuffer samples " + std::to_string(samples) + ": must be 1 or 4");
  }
  if (depthFormat != DepthFormat::D16Unorm && depthFormat != DepthFormat::X8D24UnormPack32 &&
      depthFormat != DepthFormat::D32Sfloat && depthFormat != DepthFormat::D24UnormS8Uint &&
      depthFormat != DepthFormat::D32SfloatS8Uint) {
    return Status::error("unknown depth format");
  }
  if (colourFormat != ColourFormat::R8G8B8A8Unorm && colourFormat != ColourFormat::B8G8R8A8Unorm &&
      colourFormat != ColourFormat::R8G8B8A8Srgb && colourFormat != ColourFormat::B8G8R8A8Srgb) {
    return Status::error("unknown colour format");
  }
  return Framebuffer(width, height, depthFormat, samples, colourFormat);
}

Framebuffer::Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat, std::uint32_t samples,
                         ColourFormat colourFormat)
    : width_(width),
      height_(height),
      samples_(samples),
      depthFormat_(depthFormat),
      colourFormat_(colourFormat),
      colour_(static_cast<std::size_t>(width) * height * samples * 4, 0),
      depth_(static_cast<std::size_t>(width) * height * samples, 0),
      stencil_(hasStencil(depthFormat) ? static_cast<std::size_t>(width) * height * samples : 0, 0) {}

Framebuffer Framebuffer::resolve() const {
  Framebuffer out(width_, height_, depthFormat_, 1, colourFormat_);
  resolveInto(out);
  return out;
}

void Framebuffer::resolveInto(Framebuffer& out) const {
  settled();
  if (&out == this) {  // resolving in place: a single-sample framebuffer is its own resolve
    if (samples_ != 1) out = resolve();
    return;
  }
  if (out.width_ != width_ || out.height_ != height_ || out.depthFormat_ != depthFormat_ || out.samples_ != 1 ||
      out.colourFormat_ != colourFormat_) {
    out = Framebuffer(width_, height_, depthFormat_, 1, colourFormat_);
  }
  out.pending_.reset();  // every sample of `out` is written here
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  for (std::size_t q = 0; q < out.stencil_.size(); ++q) out.stencil_[q] = stencil_[q * samples_];
  const float toFloat = static_cast<float>(1.0 / 255.0);  // how lavapipe's texel fetch converts UNORM8
  const float average = 1.0f / static_cast<float>(samples_);
  const bool srgb = isSrgb(colourFormat_);
  std::size_t p = 0;
#if defined(__SSE2__)
  if (samples_ == 4 && !srgb) {  // the loop below with the four channels of a pixel in four lanes
    const __m128i zero = _mm_setzero_si128();
    const __m128 scale = _mm_set1_ps(toFloat), quarter = _mm_set1_ps(average);
    const __m128 magic = _mm_set1_ps(8388608.0f), max = _mm_set1_ps(255.0f);
    for (; p < pixels; ++p) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(colour_.data() + 16 * p));
      const __m128i low = _mm_unpacklo_epi8(bytes, zero), high = _mm_unpackhi_epi8(bytes, zero);
      const __m128 s0 = _mm_mul_ps(_mm_cvtepi32_ps(_mm_unpacklo_epi16(low, zero)), scale);
      const __m128 s1 = _mm_mul_ps(_mm_cvtepi32_ps(_mm_unpackhi_epi16(low, zero)), scale);
      const __m128 s2 = _mm_mul_ps(_mm_cvtepi32_ps(_mm_unpacklo_epi16(high, zero)), scale);
      const __m128 s3 = _mm_mul_ps(_mm_cvtepi32_ps(_mm_unpackhi_epi16(high, zero)), scale);
      const __m128 v = _mm_mul_ps(_mm_add_ps(_mm_add_ps(_mm_add_ps(s0, s1), s2), s3), quarter);
      // unorm8FromFloat: v > 0 ? min(v, 1) : 0 (v is never NaN here), then round half to even.
      const __m128 clamped = _mm_min_ps(_mm_max_ps(v, _mm_setzero_ps()), _mm_set1_ps(1.0f));
      const __m128 rounded = _mm_sub_ps(_mm_add_ps(_mm_mul_ps(clamped, max), magic), magic);
      const __m128i words = _mm_cvttps_epi32(rounded);
      const int rgba = _mm_cvtsi128_si32(_mm_packus_epi16(_mm_packs_epi32(words, zero), zero));
      std::memcpy(out.colour_.data() + 4 * p, &rgba, sizeof rgba);
      out.depth_[p] = depth_[p * 4];
    }
  }
#endif
  for (; p < pixels; ++p) {
    for (int c = 0; c < 4; ++c) {
      const bool linear = srgb && c < 3;  // sRGB red, green, blue: averaged as linear values
      float sum = 0.0f;
      for (std::uint32_t s = 0; s < samples_; ++s) {
        const std::uint8_t byte = colour_[(p * samples_ + s) * 4 + c];
        sum = sum + (linear ? detail::srgbToLinear(byte) : static_cast<float>(byte) * toFloat);
      }
      out.colour_[p * 4 + c] = samples_ == 1 ? colour_[p * 4 + c]
                               : linear     ? detail::linearToSrgbByte(sum * average)
                                            : detail::unorm8FromFloat(sum * average);
    }
    out.depth_[p] = depth_[p * samples_];
  }
}

void Framebuffer::clear(Vec4 colour, float depth, std::uint8_t stencil) {
  if (swapsRedBlue(colourFormat_)) std::swap(colour.x, colour.z);
  std::uint8_t bytes[4];
  detail::storeColour(bytes, colour);
  if (isSrgb(colourFormat_)) {  // util_pack_color: red, green and blue through Giesen's table
    bytes[0] = detail::linearToSrgbClearByte(colour.x);
    bytes[1] = detail::linearToSrgbClearByte(colour.y);
    bytes[2] = detail::linearToSrgbClearByte(colour.z);
  }
  PendingClear clear;
  std::memcpy(&clear.colour, bytes, sizeof clear.colour);
  clear.depth = depthClearValue(depthFormat_, depth);
  clear.stencil = stencil;
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
  if (!stencil_.empty()) std::memset(stencil_.data() + first, clear.stencil, count);
}

void Framebuffer::writePendingClear() const {
  const PendingClear clear = *pending_;
  pending_.reset();
  if (height_ != 0) fillRows(clear, 0, height_ - 1);
}

std::vector<float> Framebuffer::depthValues() const {
  std::vector<float> out;
  depthValuesInto(out);
  return out;
}

void Framebuffer::depthValuesInto(std::vector<float>& out) const {
  settled();
  out.resize(depth_.size());
  for (std::size_t i = 0; i < depth_.size(); ++i) out[i] = depth(i);
}

float Framebuffer::depth(std::size_t sample) const {
  settled();
  const int bits = unormDepthBits(depthFormat_);
  if (bits == 0) return std::bit_cast<float>(depth_[sample]);
  return static_cast<float>(static_cast<double>(depth_[sample]) / ((1u << bits) - 1));
}

}  // namespace softraster
