// Scene images (see artifacts.hpp).
#include "output/artifacts.hpp"

#include "compare/compare.hpp"
#include "output/image_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <system_error>
#include <vector>

namespace crosscheck {

std::pair<float, float> sharedDepthRange(const Frame& soft, const Frame& vulkan, float clearDepth) {
  float lo = 1, hi = 0;
  for (const Frame* frame : {&soft, &vulkan}) {
    for (const float z : frame->depth) {
      if (z != clearDepth && std::isfinite(z)) lo = std::min(lo, z), hi = std::max(hi, z);
    }
  }
  if (lo < hi) return {lo, hi};
  if (lo == hi && lo != clearDepth) return {std::min(lo, clearDepth), std::max(lo, clearDepth)};
  return {0.0f, 1.0f};
}

// Bit-identical colour and depth (depth compared as bits, so NaN equals NaN and -0 differs from 0).
// With MSAA every sample too (colour, depth as stored, stencil); every colour attachment.
bool identicalFrames(const Frame& a, const Frame& b) {
  const auto sameColour = [](const ColourImage& x, const ColourImage& y) {
    return x.colourFormat == y.colourFormat && x.rgba == y.rgba && x.colourWords == y.colourWords &&
           x.sampleRgba == y.sampleRgba && x.sampleColourWords == y.sampleColourWords;
  };
  return a.width == b.width && a.height == b.height && a.rgba == b.rgba && a.stencil == b.stencil && a.depth.size() == b.depth.size() &&
         std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)) == 0 && a.samples == b.samples &&
         a.sampleRgba == b.sampleRgba && a.sampleDepthStorage == b.sampleDepthStorage && a.sampleStencil == b.sampleStencil &&
         a.colourWords == b.colourWords && a.sampleColourWords == b.sampleColourWords &&
         std::equal(a.moreColour.begin(), a.moreColour.end(), b.moreColour.begin(), b.moreColour.end(), sameColour);
}

// Colour attachment k + 1 of a frame (Frame::moreColour[k]) in place of its first, with the
// frame's depth and stencil: what that attachment's images are drawn from (its resolve, or its
// one sample). Its coverage in a heatmap is judged against attachment 0's clear values, the same
// for both frames, so only a difference in its colour shows.
Frame attachmentFrame(const Frame& f, std::size_t k) {
  Frame out;
  out.width = f.width;
  out.height = f.height;
  out.depthFormat = f.depthFormat;
  out.depth = f.depth;
  out.depthStorage = f.depthStorage;
  out.stencil = f.stencil;
  out.colourFormat = f.moreColour[k].colourFormat;
  out.rgba = f.moreColour[k].rgba;
  out.colourWords = f.moreColour[k].colourWords;
  return out;
}

// Both frames carry colour attachment k + 1 alike.
bool hasAttachment(const Frame& soft, const Frame& vulkan, std::size_t k) {
  return k < soft.moreColour.size() && k < vulkan.moreColour.size() &&
         soft.moreColour[k].colourFormat == vulkan.moreColour[k].colourFormat &&
         soft.moreColour[k].rgba.size() == soft.rgba.size() && vulkan.moreColour[k].rgba.size() == vulkan.rgba.size() &&
         soft.moreColour[k].colourWords.size() == vulkan.moreColour[k].colourWords.size();
}

// Sample s of an MSAA frame as a one-sample frame (colour, depth as stored, stencil): what the
// per-sample images are drawn from.
Frame sampleFrame(const Frame& f, std::uint32_t s) {
  Frame out;
  out.width = f.width;
  out.height = f.height;
  out.depthFormat = f.depthFormat;
  const std::size_t pixels = std::size_t{f.width} * f.height;
  out.rgba.resize(4 * pixels);
  out.depthStorage.resize(pixels);
  if (!f.sampleStencil.empty()) out.stencil.resize(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    const std::size_t k = i * f.samples + s;
    std::memcpy(&out.rgba[4 * i], &f.sampleRgba[4 * k], 4);
    out.depthStorage[i] = f.sampleDepthStorage[k];
    if (!out.stencil.empty()) out.stencil[i] = f.sampleStencil[k];
  }
  return out;
}

// Both frames carry every sample, alike.
bool hasSamples(const Frame& soft, const Frame& vulkan) {
  const std::size_t samples = std::size_t{soft.width} * soft.height * soft.samples;
  return soft.samples > 1 && soft.samples == vulkan.samples && soft.width == vulkan.width && soft.height == vulkan.height &&
         soft.sampleRgba.size() == 4 * samples && vulkan.sampleRgba.size() == 4 * samples &&
         soft.sampleDepthStorage.size() == samples && vulkan.sampleDepthStorage.size() == samples &&
         soft.sampleStencil.size() == vulkan.sampleStencil.size() && (soft.sampleStencil.empty() || soft.sampleStencil.size() == samples);
}

// RGBA averaged over factor x factor blocks (partial blocks at the right and bottom edges), rounded.
std::vector<std::uint8_t> boxDownscale(const Frame& frame, std::uint32_t factor) {
  const std::uint32_t w = (frame.width + factor - 1) / factor, h = (frame.height + factor - 1) / factor;
  std::vector<std::uint8_t> out(std::size_t{w} * h * 4);
  for (std::uint32_t y = 0; y < h; ++y) {
    for (std::uint32_t x = 0; x < w; ++x) {
      std::uint32_t sum[4] = {0, 0, 0, 0}, n = 0;
      for (std::uint32_t sy = y * factor; sy < std::min(frame.height, (y + 1) * factor); ++sy) {
        for (std::uint32_t sx = x * factor; sx < std::min(frame.width, (x + 1) * factor); ++sx, ++n) {
          for (int c = 0; c < 4; ++c) sum[c] += frame.rgba[(std::size_t{sy} * frame.width + sx) * 4 + c];
        }
      }
      for (int c = 0; c < 4; ++c) out[(std::size_t{y} * w + x) * 4 + c] = static_cast<std::uint8_t>((sum[c] + n / 2) / n);
    }
  }
  return out;
}

softraster::Status writeSceneImages(const std::filesystem::path& root, const std::filesystem::path& folder,
                                    SceneResult* result, const Scene& scene, const Frame& soft, const Frame& vulkan,
                                    SceneImageSet set) {
  const auto [lo, hi] = sharedDepthRange(soft, vulkan, scene.clearDepth);
  result->depthViewRange = {lo, hi};
  result->imageRoot = root;
  result->images.clear();
  softraster::Status status;
  const auto write = [&](const char* kind, const char* file, const Frame& frame, const std::vector<std::uint8_t>& rgba) {
    const std::filesystem::path relative = folder / file;
    status = writePng(root / relative, frame.width, frame.height, rgba);
    if (status) result->images.push_back({kind, relative});
    return status.ok();
  };
  if (set == SceneImageSet::Compact && identicalFrames(soft, vulkan)) {
    const std::uint32_t factor = std::max<std::uint32_t>(1, (std::max(soft.width, soft.height) + kPreviewSize - 1) / kPreviewSize);
    const std::filesystem::path relative = folder / "preview.png";
    status = writePng(root / relative, (soft.width + factor - 1) / factor, (soft.height + factor - 1) / factor,
                      boxDownscale(soft, factor));
    if (status) result->images.push_back({"preview", relative});
    return status;
  }
  // Stops at the first image that cannot be written (the later ones are not even computed).
  static_cast<void>(write("soft", "soft.png", soft, soft.rgba) && write("vulkan", "vulkan.png", vulkan, vulkan.rgba) &&
                    write("diff", "diff.png", soft, diffHeatmap(soft, vulkan, scene)) &&
                    write("soft.depth", "soft.depth.png", soft, depthToGrey(soft.depth, scene.clearDepth, lo, hi)) &&
                    write("vulkan.depth", "vulkan.depth.png", vulkan, depthToGrey(vulkan.depth, scene.clearDepth, lo, hi)) &&
                    write("depth.diff", "depth.diff.png", soft, depthDiffHeatmap(soft, vulkan, scene)));
  if (status && !soft.stencil.empty() && soft.stencil.size() == vulkan.stencil.size()) {
    static_cast<void>(write("soft.stencil", "soft.stencil.png", soft, stencilToGrey(soft)) &&
                      write("vulkan.stencil", "vulkan.stencil.png", vulkan, stencilToGrey(vulkan)) &&
                      write("stencil.diff", "stencil.diff.png", soft, stencilDiffHeatmap(soft, vulkan)));
  }
  // Each colour attachment after the first (its resolve): both colours and their difference.
  for (std::size_t k = 0; status && hasAttachment(soft, vulkan, k); ++k) {
    const Frame a = attachmentFrame(soft, k), b = attachmentFrame(vulkan, k);
    const std::string n = std::to_string(k + 1);
    static_cast<void>(write(("soft.attachment" + n).c_str(), ("soft.attachment" + n + ".png").c_str(), a, a.rgba) &&
                      write(("vulkan.attachment" + n).c_str(), ("vulkan.attachment" + n + ".png").c_str(), b, b.rgba) &&
                      write(("attachment" + n + ".diff").c_str(), ("attachment" + n + ".diff.png").c_str(), a,
                            diffHeatmap(a, b, scene)));
  }
  // With MSAA, each sample as stored before the resolve: both colours and their difference.
  for (std::uint32_t s = 0; status && hasSamples(soft, vulkan) && s < soft.samples; ++s) {
    const Frame a = sampleFrame(soft, s), b = sampleFrame(vulkan, s);
    const std::string n = std::to_string(s);
    static_cast<void>(write(("soft.sample" + n).c_str(), ("soft.sample" + n + ".png").c_str(), a, a.rgba) &&
                      write(("vulkan.sample" + n).c_str(), ("vulkan.sample" + n + ".png").c_str(), b, b.rgba) &&
                      write(("sample" + n + ".diff").c_str(), ("sample" + n + ".diff.png").c_str(), a, diffHeatmap(a, b, scene)));
  }
  return status;
}

softraster::Status writeCompareImages(const std::filesystem::path& dir, const Scene& scene, const Frame& soft,
                                      const Frame& vulkan) {
  softraster::Status written = writePng(dir / "soft.png", soft.width, soft.height, soft.rgba);
  if (written) written = writePng(dir / "vulkan.png", vulkan.width, vulkan.height, vulkan.rgba);
  if (written) written = writePng(dir / "diff.png", soft.width, soft.height, diffHeatmap(soft, vulkan, scene));
  if (written) written = writeDepthView(dir / "soft.depth.png", soft, scene.clearDepth, 0, 0);
  if (written) written = writeDepthView(dir / "vulkan.depth.png", vulkan, scene.clearDepth, 0, 0);
  if (written && !soft.stencil.empty() && soft.stencil.size() == vulkan.stencil.size()) {
    written = writePng(dir / "soft.stencil.png", soft.width, soft.height, stencilToGrey(soft));
    if (written) written = writePng(dir / "vulkan.stencil.png", vulkan.width, vulkan.height, stencilToGrey(vulkan));
    if (written) written = writePng(dir / "stencil.diff.png", soft.width, soft.height, stencilDiffHeatmap(soft, vulkan));
  }
  for (std::size_t k = 0; written && hasAttachment(soft, vulkan, k); ++k) {
    const Frame a = attachmentFrame(soft, k), b = attachmentFrame(vulkan, k);
    const std::string n = std::to_string(k + 1);
    written = writePng(dir / ("soft.attachment" + n + ".png"), a.width, a.height, a.rgba);
    if (written) written = writePng(dir / ("vulkan.attachment" + n + ".png"), b.width, b.height, b.rgba);
    if (written) {
      written = writePng(dir / ("attachment" + n + ".diff.png"), a.width, a.height, diffHeatmap(a, b, scene));
    }
  }
  return written;
}

softraster::Status writeDepthView(const std::filesystem::path& path, const Frame& frame, float clearDepth, float lo,
                                  float hi) {
  return writePng(path, frame.width, frame.height, depthToGrey(frame.depth, clearDepth, lo, hi));
}

softraster::Status copySceneFiles(SceneResult* result, const std::filesystem::path& root) {
  if (result->imageRoot.empty()) return {};
  std::vector<std::filesystem::path> files;
  for (const SceneImage& image : result->images) files.push_back(image.file);
  if (!result->pixelData.empty()) files.push_back(result->pixelData);
  for (const std::filesystem::path& file : files) {
    const std::filesystem::path from = result->imageRoot / file, to = root / file;
    std::error_code ec;
    if (std::filesystem::equivalent(from, to, ec)) continue;  // already there (merging into a shard's folder)
    ec.clear();
    std::filesystem::create_directories(to.parent_path(), ec);
    if (!ec) std::filesystem::copy_file(from, to, std::filesystem::copy_options::overwrite_existing, ec);
    if (ec) return softraster::Status::error(from.string() + ": cannot copy to " + to.string() + ": " + ec.message());
  }
  result->imageRoot = root;
  return {};
}

}  // namespace crosscheck
