// Frame comparison and the diff heatmaps (see compare.hpp).
#include "compare/compare.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

namespace crosscheck {
namespace {

// The clear values a pixel is compared with to tell whether anything covered it: the colour as
// the format stores its clear (softraster::colourClearValue), as a Frame holds it (R, G, B, A
// bytes, or a wider format's texel words).
struct ClearValues {
  std::array<std::uint8_t, 4> colour;
  std::array<std::uint32_t, 4> colourWords;
  std::uint32_t depth;
  std::uint8_t stencil;
};

// The clear values of colour attachment 0, or of `format` cleared to `colour` (a later one).
ClearValues clearValues(const Scene& scene, softraster::ColourFormat format, softraster::Vec4 colour) {
  ClearValues clear{};
  clear.colourWords = softraster::colourClearValue(format, colour);
  std::memcpy(clear.colour.data(), clear.colourWords.data(), 4);
  if (softraster::swapsRedBlue(format)) std::swap(clear.colour[0], clear.colour[2]);
  clear.depth = softraster::depthClearValue(scene.depthFormat, scene.clearDepth);
  clear.stencil = scene.clearStencil;
  return clear;
}
ClearValues clearValues(const Scene& scene) { return clearValues(scene, scene.colourFormat, scene.clearColour); }

// A frame's samples: with MSAA every sample as stored before the resolve, else the pixels (one
// sample each). Sample s of pixel i is at i * samples + s.
struct Samples {
  const std::uint8_t* rgba;
  const std::uint32_t* words;   // a wider format's stored texels (rgba is their view), else null
  std::uint32_t texelWords;     // words per texel: 1, 2 (four halves) or 4 (four floats)
  const std::uint32_t* depth;
  const std::uint8_t* stencil;  // null without a stencil aspect
  std::uint32_t samples;
};

Samples samplesOf(const Frame& f, bool resolved = false) {
  const std::uint32_t texelWords = softraster::colourBytes(f.colourFormat) / 4;
  if (f.samples > 1 && !resolved)
    return {f.sampleRgba.data(), f.sampleColourWords.empty() ? nullptr : f.sampleColourWords.data(), texelWords,
            f.sampleDepthStorage.data(), f.sampleStencil.empty() ? nullptr : f.sampleStencil.data(), f.samples};
  return {f.rgba.data(), f.colourWords.empty() ? nullptr : f.colourWords.data(), texelWords, f.depthStorage.data(),
          f.stencil.empty() ? nullptr : f.stencil.data(), 1};
}

// The resolved colour (the pixels themselves without MSAA) as Samples of one sample each.
Samples resolvedOf(const Frame& f) { return samplesOf(f, true); }

// The same of colour attachment k + 1 (Frame::moreColour[k]), with the frame's depth and stencil.
Samples samplesOf(const Frame& f, const ColourImage& image, bool resolved = false) {
  Samples s = samplesOf(f, resolved);
  s.texelWords = softraster::colourBytes(image.colourFormat) / 4;
  const bool multisampled = f.samples > 1 && !resolved;
  const std::vector<std::uint8_t>& rgba = multisampled ? image.sampleRgba : image.rgba;
  const std::vector<std::uint32_t>& words = multisampled ? image.sampleColourWords : image.colourWords;
  s.rgba = rgba.data();
  s.words = words.empty() ? nullptr : words.data();
  return s;
}

// A float's bits (`bits` wide, sign in the top bit) as an integer that orders as the values do,
// one step per representable value; -0 is one step below +0, so a sign of zero counts too.
std::int64_t orderedFloat(std::uint32_t value, int bits) {
  const std::uint32_t sign = 1u << (bits - 1);
  const std::int64_t magnitude = value & (sign - 1);
  return (value & sign) ? -magnitude - 1 : magnitude;
}

// Channel ch (0..3 = R, G, B, A) of sample k in the format's own steps: a byte; of A2B10G10R10 the
// 10-bit (alpha: 2-bit) value; of a float format the value's place among its format's floats
// (orderedFloat), so differences are in units in the last place.
std::int64_t channel(const Samples& f, std::size_t k, int ch) {
  if (!f.words) return f.rgba[4 * k + ch];
  const std::uint32_t* texel = f.words + k * f.texelWords;
  if (f.texelWords == 1) return softraster::tenBitChannel(texel[0], ch);
  if (f.texelWords == 2) return orderedFloat((texel[ch / 2] >> (16 * (ch % 2))) & 0xffffu, 16);
  return orderedFloat(texel[ch], 32);
}

// |a - b| of one channel, at most INT_MAX (float formats can differ by more steps).
int channelDelta(const Samples& a, const Samples& b, std::size_t k, int ch) {
  const std::int64_t d = channel(a, k, ch) - channel(b, k, ch);
  return static_cast<int>(std::min<std::int64_t>(d < 0 ? -d : d, std::numeric_limits<int>::max()));
}

bool sampleCovered(const Samples& f, std::size_t k, const ClearValues& clear) {
  const bool colourCleared = f.words ? std::equal(f.words + k * f.texelWords, f.words + (k + 1) * f.texelWords,
                                                  clear.colourWords.begin())
                                     : std::equal(clear.colour.begin(), clear.colour.end(), f.rgba + 4 * k);
  return f.depth[k] != clear.depth || (f.stencil && f.stencil[k] != clear.stencil) || !colourCleared;
}

// Whether each sample of pixel i is covered, one bit per sample.
unsigned coverageMask(const Samples& f, std::size_t i, const ClearValues& clear) {
  unsigned mask = 0;
  for (std::uint32_t s = 0; s < f.samples; ++s) mask |= unsigned{sampleCovered(f, i * f.samples + s, clear)} << s;
  return mask;
}

// What tells a frame's covered samples: its samples and clear values, of every colour attachment.
struct CoverageSources {
  std::vector<Samples> samples;  // attachment 0, then Frame::moreColour's
  std::vector<ClearValues> clears;
};

CoverageSources coverageSources(const Frame& f, const Scene& scene) {
  CoverageSources sources{{samplesOf(f)}, {clearValues(scene)}};
  for (std::size_t k = 0; k < f.moreColour.size() && k < scene.moreColour.size(); ++k) {
    sources.samples.push_back(samplesOf(f, f.moreColour[k]));
    sources.clears.push_back(clearValues(scene, scene.moreColour[k].format, scene.moreColour[k].clearColour));
  }
  return sources;
}

// A sample is covered when its depth or stencil, or its colour in any attachment, is not the clear's.
unsigned coverageMask(const CoverageSources& f, std::size_t i) {
  unsigned mask = 0;
  for (std::size_t k = 0; k < f.samples.size(); ++k) mask |= coverageMask(f.samples[k], i, f.clears[k]);
  return mask;
}

// |a - b| of two stored depths, in depth units ([0, 1] range): whole steps of 1/(2^n - 1) for
// UNORM formats, the float difference for D32_SFLOAT (infinite where only one side is NaN).
double depthDelta(std::uint32_t a, std::uint32_t b, softraster::DepthFormat format) {
  const int bits = softraster::unormDepthBits(format);
  if (bits != 0) {
    const auto steps = a > b ? a - b : b - a;
    return static_cast<double>(steps) / static_cast<double>((1u << bits) - 1);
  }
  const float za = std::bit_cast<float>(a), zb = std::bit_cast<float>(b);
  const bool nanA = std::isnan(za), nanB = std::isnan(zb);
  if (nanA || nanB) return nanA && nanB ? 0.0 : std::numeric_limits<double>::infinity();
  return std::fabs(double{za} - double{zb});
}

}  // namespace

std::string colourDeltaUnit(softraster::ColourFormat format) {
  if (softraster::isTenBit(format)) return "10-bit steps (alpha 2-bit)";
  if (softraster::isFloat(format)) return softraster::colourBytes(format) == 8 ? "half ULPs" : "float ULPs";
  return "8-bit steps";
}

Comparison compareFrames(const Frame& a, const Frame& b, const Scene& scene) {
  Comparison c;
  if (a.width != b.width || a.height != b.height || a.depthFormat != b.depthFormat || a.stencil.size() != b.stencil.size()) {
    c.failures.push_back("image sizes or depth formats differ");
    return c;
  }
  if (a.colourWords.size() != b.colourWords.size() || a.sampleColourWords.size() != b.sampleColourWords.size()) {
    c.failures.push_back("colour formats differ");
    return c;
  }
  if (a.samples != b.samples || a.sampleRgba.size() != b.sampleRgba.size() ||
      a.sampleStencil.size() != b.sampleStencil.size()) {
    c.failures.push_back("sample counts differ");
    return c;
  }
  if (a.moreColour.size() != b.moreColour.size() || a.moreColour.size() != scene.moreColour.size()) {
    c.failures.push_back("colour attachment counts differ");
    return c;
  }
  for (std::size_t k = 0; k < a.moreColour.size(); ++k) {
    const ColourImage &ia = a.moreColour[k], &ib = b.moreColour[k];
    if (ia.colourFormat != ib.colourFormat || ia.rgba.size() != a.rgba.size() || ib.rgba.size() != b.rgba.size() ||
        ia.colourWords.size() != ib.colourWords.size() || ia.sampleRgba.size() != a.sampleRgba.size() ||
        ib.sampleRgba.size() != b.sampleRgba.size() || ia.sampleColourWords.size() != ib.sampleColourWords.size()) {
      c.failures.push_back("colour attachment " + std::to_string(k + 1) + "'s formats or sizes differ");
      return c;
    }
  }
  const Samples sa = samplesOf(a), sb = samplesOf(b), ra = resolvedOf(a), rb = resolvedOf(b);
  const std::uint32_t samples = sa.samples;
  c.colourUnit = colourDeltaUnit(a.colourFormat);
  c.samples = samples;
  const Tolerance& tol = scene.tolerance;
  const CoverageSources coverageA = coverageSources(a, scene), coverageB = coverageSources(b, scene);
  // Colour attachments 1..: every sample and the resolve, compared as attachment 0's colour is.
  struct More {
    Samples sa, sb, ra, rb;
  };
  std::vector<More> more;
  for (std::size_t k = 0; k < a.moreColour.size(); ++k) {
    more.push_back({samplesOf(a, a.moreColour[k]), samplesOf(b, b.moreColour[k]), samplesOf(a, a.moreColour[k], true),
                    samplesOf(b, b.moreColour[k], true)});
    AttachmentComparison& m = c.moreColour.emplace_back();
    m.colourUnit = colourDeltaUnit(a.moreColour[k].colourFormat);
  }
  c.pixels = static_cast<std::uint64_t>(a.width) * a.height;
  std::array<std::uint64_t, 4> sums{};
  double squaredErrorRgb = 0;
  for (std::size_t i = 0; i < c.pixels; ++i) {
    if (coverageMask(coverageA, i) != coverageMask(coverageB, i)) ++c.coverageMismatches;
    for (std::size_t k = 0; k < more.size(); ++k) {
      AttachmentComparison& m = c.moreColour[k];
      bool moreOver = false;
      const auto measure = [&](const Samples& x, const Samples& y, std::size_t sample) {
        for (int ch = 0; ch < 4; ++ch) {
          const int d = channelDelta(x, y, sample, ch);
          m.colourMaxDelta[ch] = std::max(m.colourMaxDelta[ch], d);
          moreOver = moreOver || d > tol.colourThreshold;
        }
      };
      for (std::uint32_t s = 0; s < samples; ++s) measure(more[k].sa, more[k].sb, i * samples + s);
      measure(more[k].ra, more[k].rb, i);
      if (moreOver) ++m.colourPixelsOver;
    }
    bool over = false, depthOver = false, stencilDiffers = false;
    for (std::uint32_t s = 0; s < samples; ++s) {  // every sample (the pixel itself with one)
      const std::size_t k = i * samples + s;
      stencilDiffers = stencilDiffers || (sa.stencil && sa.stencil[k] != sb.stencil[k]);
      for (int ch = 0; ch < 4; ++ch) {
        const int d = channelDelta(sa, sb, k, ch);
        c.colourMaxDelta[ch] = std::max(c.colourMaxDelta[ch], d);
        over = over || d > tol.colourThreshold;
      }
      const double dz = depthDelta(sa.depth[k], sb.depth[k], a.depthFormat);
      c.depthMaxDelta = std::max(c.depthMaxDelta, dz);
      depthOver = depthOver || dz > tol.depthThreshold;
    }
    for (int ch = 0; ch < 4; ++ch) {  // the resolved colour (the pixel's one sample without MSAA)
      const int d = channelDelta(ra, rb, i, ch);
      c.resolvedColourMaxDelta[ch] = std::max(c.resolvedColourMaxDelta[ch], d);
      c.colourMaxDelta[ch] = std::max(c.colourMaxDelta[ch], d);
      sums[ch] += static_cast<std::uint64_t>(d);
      const double viewDelta = static_cast<double>(a.rgba[4 * i + ch]) - static_cast<double>(b.rgba[4 * i + ch]);
      if (ch < 3) squaredErrorRgb += viewDelta * viewDelta;
      over = over || d > tol.colourThreshold;
    }
    if (over) ++c.colourPixelsOver;
    if (depthOver) ++c.depthPixelsOver;
    if (stencilDiffers) ++c.stencilMismatches;
  }
  for (int ch = 0; ch < 4; ++ch) c.colourMeanDelta[ch] = double(sums[ch]) / double(c.pixels);
  const double mse = squaredErrorRgb / (3.0 * double(c.pixels));
  c.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  c.failures = limitFailures(c, tol);
  return c;
}

std::uint64_t coveredPixels(const Frame& frame, const Scene& scene) {
  const CoverageSources coverage = coverageSources(frame, scene);
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < frame.depthStorage.size(); ++i) count += coverageMask(coverage, i) != 0;
  return count;
}

std::uint64_t colourDifferingPixels(const Frame& a, const Frame& b) {
  if (a.rgba.size() != b.rgba.size() || a.colourWords.size() != b.colourWords.size()) {
    return std::max(a.rgba.size(), b.rgba.size()) / 4;
  }
  const std::size_t pixels = a.rgba.size() / 4, words = pixels == 0 ? 0 : a.colourWords.size() / pixels;
  std::uint64_t n = 0;
  for (std::size_t i = 0; i < pixels; ++i) {
    const bool bytes = !std::equal(a.rgba.begin() + 4 * i, a.rgba.begin() + 4 * i + 4, b.rgba.begin() + 4 * i);
    const bool stored = words != 0 && !std::equal(a.colourWords.begin() + words * i, a.colourWords.begin() + words * (i + 1),
                                                  b.colourWords.begin() + words * i);
    n += bytes || stored;
  }
  return n;
}

std::vector<std::uint8_t> diffHeatmap(const Frame& a, const Frame& b, const Scene& scene) {
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  std::vector<std::uint8_t> out(4 * pixels, 0);
  if (a.colourWords.size() != b.colourWords.size()) return out;
  const CoverageSources coverageA = coverageSources(a, scene), coverageB = coverageSources(b, scene);
  const Samples ra = resolvedOf(a), rb = resolvedOf(b);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* p = &out[4 * i];
    p[3] = 255;
    if ((coverageMask(coverageA, i) != 0) != (coverageMask(coverageB, i) != 0)) {
      p[0] = 255, p[1] = 0, p[2] = 255;
      continue;
    }
    int d = 0;
    for (int ch = 0; ch < 4; ++ch) d = std::max(d, channelDelta(ra, rb, i, ch));
    if (d == 0) continue;
    if (d <= scene.tolerance.colourThreshold) {
      p[2] = 255;
    } else {
      p[0] = 255;
      p[1] = static_cast<std::uint8_t>(std::min(255, d * 2));
    }
  }
  return out;
}

std::vector<std::uint8_t> depthDiffHeatmap(const Frame& a, const Frame& b, const Scene& scene) {
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  std::vector<std::uint8_t> out(4 * pixels, 0);
  const double threshold = scene.tolerance.depthThreshold;
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* p = &out[4 * i];
    p[3] = 255;
    const float za = a.depth[i], zb = b.depth[i];
    if (std::isnan(za) || std::isnan(zb)) {
      if (std::isnan(za) != std::isnan(zb)) p[0] = 255, p[2] = 255;
      continue;
    }
    const double d = std::fabs(double{za} - double{zb});
    if (d == 0) continue;
    if (d <= threshold) {
      p[2] = 255;
      continue;
    }
    // Over the threshold: 0 at the threshold .. 1 at 2^16 times it (log2), red to yellow; with a
    // threshold of 0 the scale starts at 2^-24 (one step of float depth just below 1).
    const double base = threshold > 0 ? threshold : 0x1p-24;
    const double t = std::clamp(std::log2(d / base) / 16.0, 0.0, 1.0);
    p[0] = 255;
    p[1] = static_cast<std::uint8_t>(std::lround(64 + t * 191));
  }
  return out;
}

std::vector<std::uint8_t> stencilToGrey(const Frame& frame) {
  std::vector<std::uint8_t> out(4 * frame.stencil.size(), 255);
  for (std::size_t i = 0; i < frame.stencil.size(); ++i) out[4 * i] = out[4 * i + 1] = out[4 * i + 2] = frame.stencil[i];
  return out;
}

std::vector<std::uint8_t> stencilDiffHeatmap(const Frame& a, const Frame& b) {
  if (a.stencil.size() != b.stencil.size()) return {};
  std::vector<std::uint8_t> out(4 * a.stencil.size(), 0);
  for (std::size_t i = 0; i < a.stencil.size(); ++i) {
    std::uint8_t* p = &out[4 * i];
    p[3] = 255;
    if (a.stencil[i] != b.stencil[i]) p[0] = 255, p[2] = 255;
  }
  return out;
}

}  // namespace crosscheck
