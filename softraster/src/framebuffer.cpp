// Framebuffer creation (the checks create() documents), storage of each colour attachment, clears (deferred: see
// framebuffer.hpp; the colour swizzled to the format's byte order), the MSAA resolve (SSE2 where
// the build has it, two pixels at a time with AVX2 where the CPU has it, the same operations per
// channel, so blind to the channels' order;
// A2B10G10R10 and the float formats per channel in float, stored as a fragment stores them;
// stencil keeps sample 0 as depth does) and depth read-out (one sample, or all of them as floats).
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/half.hpp>
#include <softraster/detail/fragment/srgb.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace softraster {

std::uint32_t depthClearValue(DepthFormat format, float depth) {
  const int bits = unormDepthBits(format);
  if (bits == 0) return std::bit_cast<std::uint32_t>(depth);
  return static_cast<std::uint32_t>(std::lrint(static_cast<double>(depth) * ((1u << bits) - 1)));
}

Result<Framebuffer> Framebuffer::create(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat,
                                        std::uint32_t samples, ColourFormat colourFormat) {
  return create(width, height, depthFormat, samples, std::span<const ColourFormat>(&colourFormat, 1));
}

Result<Framebuffer> Framebuffer::create(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat,
                                        std::uint32_t samples, std::span<const ColourFormat> colourFormats) {
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
  if (colourFormats.empty() || colourFormats.size() > kMaxColourAttachments) {
    return Status::error("framebuffer colour attachments " + std::to_string(colourFormats.size()) + ": must be 1.." +
                         std::to_string(kMaxColourAttachments));
  }
  for (const ColourFormat colourFormat : colourFormats) {
    if (colourFormat != ColourFormat::R8G8B8A8Unorm && colourFormat != ColourFormat::B8G8R8A8Unorm &&
        colourFormat != ColourFormat::R8G8B8A8Srgb && colourFormat != ColourFormat::B8G8R8A8Srgb &&
        colourFormat != ColourFormat::A2B10G10R10Unorm && colourFormat != ColourFormat::R16G16B16A16Sfloat &&
        colourFormat != ColourFormat::R32G32B32A32Sfloat) {
      return Status::error("unknown colour format");
    }
  }
  return Framebuffer(width, height, depthFormat, samples, colourFormats);
}

Framebuffer::Framebuffer(std::uint32_t width, std::uint32_t height, DepthFormat depthFormat, std::uint32_t samples,
                         std::span<const ColourFormat> colourFormats)
    : width_(width),
      height_(height),
      samples_(samples),
      depthFormat_(depthFormat),
      colourFormat_(colourFormats[0]),
      moreFormats_(colourFormats.begin() + 1, colourFormats.end()),
      colour_(static_cast<std::size_t>(width) * height * samples * colourBytes(colourFormats[0]), 0),
      depth_(static_cast<std::size_t>(width) * height * samples, 0),
      stencil_(hasStencil(depthFormat) ? static_cast<std::size_t>(width) * height * samples : 0, 0) {
  for (const ColourFormat format : moreFormats_) {
    moreColour_.emplace_back(static_cast<std::size_t>(width) * height * samples * colourBytes(format), 0);
  }
  if (samples == 1) {  // every word 0: the key of a 0 word (0.0 as D32 too)
    const std::size_t tiles = static_cast<std::size_t>(detail::FramebufferAccess::depthTilesPerRow(*this)) *
                              ((height + detail::kDepthTileSize - 1) / detail::kDepthTileSize);
    depthTiles_.assign(tiles, {0.0f, 0.0f});
  }
}

void Framebuffer::forgetDepthTiles() {
  std::fill(depthTiles_.begin(), depthTiles_.end(),
            detail::DepthTileRange{-std::numeric_limits<float>::infinity(), std::numeric_limits<float>::infinity()});
}

Framebuffer Framebuffer::resolve() const {
  Framebuffer out;
  resolveInto(out);
  return out;
}

namespace {

#if defined(__x86_64__)
// The UNORM8 4x resolve below (its SSE2 loop) two pixels at a time, one per 128-bit lane of an
// AVX2 vector: the same operations on every channel, so the same bytes. Returns the pixels done.
[[gnu::target("avx2")]] std::size_t resolveUnorm8Samples4Avx2(std::size_t pixels, const std::uint8_t* in,
                                                              std::uint8_t* out, float toFloat, float average) {
  const __m256i zero = _mm256_setzero_si256();
  const __m256 scale = _mm256_set1_ps(toFloat), quarter = _mm256_set1_ps(average);
  const __m256 magic = _mm256_set1_ps(8388608.0f), max = _mm256_set1_ps(255.0f), one = _mm256_set1_ps(1.0f);
  std::size_t p = 0;
  for (; p + 2 <= pixels; p += 2) {
    const __m256i texels = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(in + 16 * p));
    const __m256i low = _mm256_unpacklo_epi8(texels, zero), high = _mm256_unpackhi_epi8(texels, zero);
    const __m256 s0 = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_unpacklo_epi16(low, zero)), scale);
    const __m256 s1 = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_unpackhi_epi16(low, zero)), scale);
    const __m256 s2 = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_unpacklo_epi16(high, zero)), scale);
    const __m256 s3 = _mm256_mul_ps(_mm256_cvtepi32_ps(_mm256_unpackhi_epi16(high, zero)), scale);
    const __m256 v = _mm256_mul_ps(_mm256_add_ps(_mm256_add_ps(_mm256_add_ps(s0, s1), s2), s3), quarter);
    const __m256 clamped = _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), one);
    const __m256 rounded = _mm256_sub_ps(_mm256_add_ps(_mm256_mul_ps(clamped, max), magic), magic);
    const __m256i words = _mm256_cvttps_epi32(rounded);
    const __m256i bytes = _mm256_packus_epi16(_mm256_packs_epi32(words, zero), zero);
    const int first = _mm256_extract_epi32(bytes, 0), second = _mm256_extract_epi32(bytes, 4);
    std::memcpy(out + 4 * p, &first, sizeof first);
    std::memcpy(out + 4 * p + 4, &second, sizeof second);
  }
  return p;
}
#endif

// `pixels` pixels of `samples` samples each of `format` in `in` averaged into one sample each in
// `out`, as framebuffer.hpp's resolve() says.
void resolveColour(ColourFormat format, std::uint32_t samples, std::size_t pixels, const std::uint8_t* in,
                   std::uint8_t* out) {
  const float toFloat = static_cast<float>(1.0 / 255.0);  // how lavapipe's texel fetch converts UNORM8
  const float average = 1.0f / static_cast<float>(samples);
  const bool srgb = isSrgb(format);
  const std::uint32_t bytes = colourBytes(format);
  if (samples == 1) {
    if (pixels != 0) std::memcpy(out, in, pixels * bytes);
    return;
  }
  std::size_t p = 0;
  if (isTenBit(format) || isFloat(format)) {
    // lavapipe's resolve shader: each sample fetched as floats, summed from +0 in sample order and
    // multiplied under FTZ and DAZ (the 10-bit values are never denormal), stored as a fragment.
    const detail::ColourBlend store = detail::colourBlend(BlendState{}, format);
    const float toFloat10 = static_cast<float>(1.0 / 1023.0), toFloat2 = static_cast<float>(1.0 / 3.0);
    for (; p < pixels; ++p) {
      std::uint8_t* pixel = out + bytes * p;
      const std::uint8_t* first = in + bytes * p * samples;
      float sum[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (std::uint32_t s = 0; s < samples; ++s) {
        float values[4];  // the texel fetch's floats: 10-bit v * float(1/1023), halves widened exactly
        if (bytes == 4) {
          std::uint32_t word;
          std::memcpy(&word, first + 4 * s, sizeof word);
          for (int c = 0; c < 4; ++c) {
            values[c] = static_cast<float>(tenBitChannel(word, c)) * (c < 3 ? toFloat10 : toFloat2);
          }
        } else if (bytes == 8) {
          std::uint16_t halves[4];
          std::memcpy(halves, first + 8 * s, sizeof halves);
          for (int c = 0; c < 4; ++c) values[c] = detail::floatFromHalf(halves[c]);
        } else {
          std::memcpy(values, first + 16 * s, sizeof values);
        }
        for (int c = 0; c < 4; ++c) sum[c] = detail::flushDenormal(sum[c] + detail::flushDenormal(values[c]));
      }
      const Vec4 mean{detail::flushDenormal(sum[0] * average), detail::flushDenormal(sum[1] * average),
                      detail::flushDenormal(sum[2] * average), detail::flushDenormal(sum[3] * average)};
      detail::blendColour(pixel, mean, store);
    }
    return;
  }
#if defined(__SSE2__)
  if (samples == 4 && !srgb) {  // the loop below with the four channels of a pixel in four lanes
#if defined(__x86_64__)
    if (__builtin_cpu_supports("avx2")) p = resolveUnorm8Samples4Avx2(pixels, in, out, toFloat, average);
#endif
    const __m128i zero = _mm_setzero_si128();
    const __m128 scale = _mm_set1_ps(toFloat), quarter = _mm_set1_ps(average);
    const __m128 magic = _mm_set1_ps(8388608.0f), max = _mm_set1_ps(255.0f);
    for (; p < pixels; ++p) {
      const __m128i texels = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + 16 * p));
      const __m128i low = _mm_unpacklo_epi8(texels, zero), high = _mm_unpackhi_epi8(texels, zero);
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
      std::memcpy(out + 4 * p, &rgba, sizeof rgba);
    }
  }
#endif
  for (; p < pixels; ++p) {
    for (int c = 0; c < 4; ++c) {
      const bool linear = srgb && c < 3;  // sRGB red, green, blue: averaged as linear values
      float sum = 0.0f;
      for (std::uint32_t s = 0; s < samples; ++s) {
        const std::uint8_t byte = in[(p * samples + s) * 4 + c];
        sum = sum + (linear ? detail::srgbToLinear(byte) : static_cast<float>(byte) * toFloat);
      }
      out[p * 4 + c] = linear ? detail::linearToSrgbByte(sum * average) : detail::unorm8FromFloat(sum * average);
    }
  }
}

}  // namespace

void Framebuffer::resolveInto(Framebuffer& out) const {
  settled();
  if (&out == this) {  // resolving in place: a single-sample framebuffer is its own resolve
    if (samples_ != 1) out = resolve();
    return;
  }
  prepareResolve(out);
  if (height_ > 0) resolveRows(out, 0, height_ - 1);
}

void Framebuffer::prepareResolve(Framebuffer& out) const {
  assert(&out != this);
  settled();
  if (out.width_ != width_ || out.height_ != height_ || out.depthFormat_ != depthFormat_ || out.samples_ != 1 ||
      out.colourFormat_ != colourFormat_ || out.moreFormats_ != moreFormats_) {
    std::vector<ColourFormat> formats{colourFormat_};
    formats.insert(formats.end(), moreFormats_.begin(), moreFormats_.end());
    out = Framebuffer(width_, height_, depthFormat_, 1, formats);
  }
  out.pending_.reset();  // every sample of `out` is written by resolveRows
  out.forgetDepthTiles();
}

void Framebuffer::resolveRows(Framebuffer& out, std::uint32_t y0, std::uint32_t y1) const {
  assert(&out != this && out.samples_ == 1 && out.width_ == width_ && out.height_ == height_ && y0 <= y1 && y1 < height_);
  const std::size_t first = static_cast<std::size_t>(y0) * width_;
  const std::size_t pixels = static_cast<std::size_t>(y1 - y0 + 1) * width_;
  if (!out.stencil_.empty()) {
    for (std::size_t q = first; q < first + pixels; ++q) out.stencil_[q] = stencil_[q * samples_];
  }
  for (std::size_t p = first; p < first + pixels; ++p) out.depth_[p] = depth_[p * samples_];
  const auto resolveAttachment = [&](ColourFormat format, const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& to) {
    const std::size_t bytes = colourBytes(format);
    resolveColour(format, samples_, pixels, in.data() + bytes * samples_ * first, to.data() + bytes * first);
  };
  resolveAttachment(colourFormat_, colour_, out.colour_);
  for (std::size_t a = 0; a < moreFormats_.size(); ++a) resolveAttachment(moreFormats_[a], moreColour_[a], out.moreColour_[a]);
}

namespace {

// A clear value's channel as Mesa's generated format packer converts it for a UNORM channel of
// `one` (1023, or 3 for the 2-bit alpha): CLAMP to [0, 1] (NaN to 0), times `one` in float, then
// util_iround (round half to even). Not the fragment path's truncating 16-bit route.
std::uint32_t clearUnorm(float v, float one) {
  const float clamped = v > 0.0f ? (v > 1.0f ? 1.0f : v) : 0.0f;
  return static_cast<std::uint32_t>(std::nearbyint(clamped * one));
}

}  // namespace

std::array<std::uint32_t, 4> colourClearValue(ColourFormat format, Vec4 colour) {
  std::array<std::uint32_t, 4> words{0, 0, 0, 0};
  if (format == ColourFormat::R32G32B32A32Sfloat) {  // as given
    const float values[4] = {colour.x, colour.y, colour.z, colour.w};
    std::memcpy(words.data(), values, sizeof values);
    return words;
  }
  if (format == ColourFormat::R16G16B16A16Sfloat) {  // _mesa_float_to_float16_rtz
    const std::uint16_t halves[4] = {detail::halfFromFloatTowardZero(colour.x), detail::halfFromFloatTowardZero(colour.y),
                                     detail::halfFromFloatTowardZero(colour.z), detail::halfFromFloatTowardZero(colour.w)};
    std::memcpy(words.data(), halves, sizeof halves);
    return words;
  }
  if (isTenBit(format)) {  // util_pack_color's R10G10B10A2 packer
    words[0] = packTenBit(clearUnorm(colour.x, 1023.0f), clearUnorm(colour.y, 1023.0f), clearUnorm(colour.z, 1023.0f),
                          clearUnorm(colour.w, 3.0f));
    return words;
  }
  if (swapsRedBlue(format)) std::swap(colour.x, colour.z);
  std::uint8_t bytes[4];
  detail::storeColour(bytes, colour);
  if (isSrgb(format)) {  // util_pack_color: red, green and blue through Giesen's table
    bytes[0] = detail::linearToSrgbClearByte(colour.x);
    bytes[1] = detail::linearToSrgbClearByte(colour.y);
    bytes[2] = detail::linearToSrgbClearByte(colour.z);
  }
  std::memcpy(words.data(), bytes, sizeof bytes);
  return words;
}

std::array<std::uint8_t, 4> Framebuffer::viewBytes(ColourFormat format, const std::uint8_t* p) {
  if (swapsRedBlue(format)) return {p[2], p[1], p[0], p[3]};
  if (isTenBit(format)) {
    std::uint32_t word;
    std::memcpy(&word, p, sizeof word);
    auto byte = [&](int c) { return static_cast<std::uint8_t>((tenBitChannel(word, c) * 255 + 511) / 1023); };
    return {byte(0), byte(1), byte(2), static_cast<std::uint8_t>(tenBitChannel(word, 3) * 85)};
  }
  if (isFloat(format)) {
    float values[4];
    if (format == ColourFormat::R16G16B16A16Sfloat) {
      std::uint16_t halves[4];
      std::memcpy(halves, p, sizeof halves);
      for (int c = 0; c < 4; ++c) values[c] = detail::floatFromHalf(halves[c]);
    } else {
      std::memcpy(values, p, sizeof values);
    }
    return {detail::unorm8FromFloat(values[0]), detail::unorm8FromFloat(values[1]), detail::unorm8FromFloat(values[2]),
            detail::unorm8FromFloat(values[3])};
  }
  return {p[0], p[1], p[2], p[3]};
}

void Framebuffer::clear(Vec4 colour, float depth, std::uint8_t stencil) {
  clear(std::span<const Vec4>(&colour, 1), depth, stencil);
}

void Framebuffer::clear(std::span<const Vec4> colours, float depth, std::uint8_t stencil) {
  PendingClear clear{};
  for (std::uint32_t a = 0; a < colourAttachments(); ++a) {
    const Vec4 colour = a < colours.size() ? colours[a] : colours.empty() ? Vec4{} : colours.back();
    clear.colour[a] = colourClearValue(colourFormat(a), colour);
  }
  clear.depth = depthClearValue(depthFormat_, depth);
  clear.stencil = stencil;
  pending_ = clear;
  const float key = detail::depthTileKey(depthFormat_, clear.depth);
  if (std::isnan(key)) {
    forgetDepthTiles();
  } else {
    std::fill(depthTiles_.begin(), depthTiles_.end(), detail::DepthTileRange{key, key});
  }
}

namespace {

// `count` values of `period` 32-bit words (1, 2 or 4) from `out` on set to `value`'s first
// `period` words, in 64-byte pieces (a memset-speed fill).
void fillWords(std::uint8_t* out, std::size_t count, const std::array<std::uint32_t, 4>& value, std::size_t period = 1) {
  std::uint32_t piece[16];
  for (std::size_t w = 0; w < 16; ++w) piece[w] = value[w % period];
  const std::size_t words = count * period;
  std::size_t i = 0;
  for (; i + 16 <= words; i += 16) std::memcpy(out + 4 * i, piece, sizeof piece);
  for (; i < words; ++i) std::memcpy(out + 4 * i, &piece[i % period], 4);
}

}  // namespace

void Framebuffer::clearRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1) { fillRows(clear, y0, y1); }

void Framebuffer::fillRows(const PendingClear& clear, std::uint32_t y0, std::uint32_t y1) const {
  if (y0 > y1 || y0 >= height_) return;
  y1 = std::min(y1, height_ - 1);
  const std::size_t perRow = static_cast<std::size_t>(width_) * samples_;
  const std::size_t first = y0 * perRow, count = (y1 - y0 + 1) * perRow;
  for (std::uint32_t a = 0; a < colourAttachments(); ++a) {
    const std::size_t period = colourBytes(colourFormat(a)) / 4;
    std::uint8_t* colour = a == 0 ? colour_.data() : moreColour_[a - 1].data();
    fillWords(colour + 4 * period * first, count, clear.colour[a], period);
  }
  fillWords(reinterpret_cast<std::uint8_t*>(depth_.data() + first), count, {clear.depth, 0, 0, 0});
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
