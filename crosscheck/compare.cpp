// Frame comparison and the diff heatmap (see compare.hpp).
#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace crosscheck {
namespace {

std::array<std::uint8_t, 4> clearColourBytes(const Scene& scene) {
  auto toByte = [](float v) {
    const float c = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
    return static_cast<std::uint8_t>(std::nearbyint(c * 255.0f));
  };
  return {toByte(scene.clearColour.x), toByte(scene.clearColour.y), toByte(scene.clearColour.z),
          toByte(scene.clearColour.w)};
}

bool covered(const Frame& f, std::size_t i, const std::array<std::uint8_t, 4>& clear, float clearDepth) {
  return f.depth[i] != clearDepth || !std::equal(clear.begin(), clear.end(), f.rgba.begin() + static_cast<std::ptrdiff_t>(4 * i));
}

std::string formatLimit(const char* metric, double value, double limit) {
  std::ostringstream s;
  s << metric << " " << value << " > " << limit;
  return s.str();
}

}  // namespace

Comparison compareFrames(const Frame& a, const Frame& b, const Scene& scene) {
  Comparison c;
  if (a.width != b.width || a.height != b.height) {
    c.failures.push_back("image sizes differ");
    return c;
  }
  const Tolerance& tol = scene.tolerance;
  const auto clear = clearColourBytes(scene);
  c.pixels = static_cast<std::uint64_t>(a.width) * a.height;
  std::array<std::uint64_t, 4> sums{};
  double squaredErrorRgb = 0;
  for (std::size_t i = 0; i < c.pixels; ++i) {
    if (covered(a, i, clear, scene.clearDepth) != covered(b, i, clear, scene.clearDepth)) ++c.coverageMismatches;
    bool over = false;
    for (int ch = 0; ch < 4; ++ch) {
      const int d = std::abs(int{a.rgba[4 * i + ch]} - int{b.rgba[4 * i + ch]});
      c.colourMaxDelta[ch] = std::max(c.colourMaxDelta[ch], d);
      sums[ch] += static_cast<std::uint64_t>(d);
      if (ch < 3) squaredErrorRgb += double(d) * d;
      over = over || d > tol.colourThreshold;
    }
    if (over) ++c.colourPixelsOver;
    const float za = a.depth[i], zb = b.depth[i];
    const bool nanA = std::isnan(za), nanB = std::isnan(zb);
    const double dz = (nanA || nanB) ? (nanA && nanB ? 0.0 : std::numeric_limits<double>::infinity())
                                     : std::fabs(double{za} - double{zb});
    c.depthMaxDelta = std::max(c.depthMaxDelta, dz);
    if (dz > tol.depthThreshold) ++c.depthPixelsOver;
  }
  for (int ch = 0; ch < 4; ++ch) c.colourMeanDelta[ch] = double(sums[ch]) / double(c.pixels);
  const double mse = squaredErrorRgb / (3.0 * double(c.pixels));
  c.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);

  if (c.coverageMismatches > tol.maxCoverageMismatches)
    c.failures.push_back(formatLimit("coverage_mismatches", double(c.coverageMismatches), double(tol.maxCoverageMismatches)));
  if (c.colourPixelsOver > tol.maxColourPixelsOver)
    c.failures.push_back(formatLimit("colour_pixels_over", double(c.colourPixelsOver), double(tol.maxColourPixelsOver)));
  if (c.depthPixelsOver > tol.maxDepthPixelsOver)
    c.failures.push_back(formatLimit("depth_pixels_over", double(c.depthPixelsOver), double(tol.maxDepthPixelsOver)));
  return c;
}

std::vector<std::uint8_t> diffHeatmap(const Frame& a, const Frame& b, const Scene& scene) {
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  std::vector<std::uint8_t> out(4 * pixels, 0);
  const auto clear = clearColourBytes(scene);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint8_t* p = &out[4 * i];
    p[3] = 255;
    if (covered(a, i, clear, scene.clearDepth) != covered(b, i, clear, scene.clearDepth)) {
      p[0] = 255, p[1] = 0, p[2] = 255;
      continue;
    }
    int d = 0;
    for (int ch = 0; ch < 4; ++ch) d = std::max(d, std::abs(int{a.rgba[4 * i + ch]} - int{b.rgba[4 * i + ch]}));
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

}  // namespace crosscheck
