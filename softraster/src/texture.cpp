// Texture creation, the mip chain both renderers upload, and which sampler states softraster
// matches exactly (texture.hpp). Sampling itself is inline (detail/texture/sample.hpp), so it is
// compiled into each draw's instruction set.
#include <softraster/texture.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace softraster {

Result<Texture> Texture::create(TextureFormat format, std::uint32_t width, std::uint32_t height,
                                std::span<const std::uint8_t> rgba, bool mipmaps) {
  if (format != TextureFormat::R8G8B8A8Unorm && format != TextureFormat::R8G8B8A8Srgb) {
    return Status::error("unknown texture format");
  }
  if (width == 0 || height == 0 || width > kMaxDimension || height > kMaxDimension) {
    return Status::error("texture size " + std::to_string(width) + "x" + std::to_string(height) +
                         " is outside 1.." + std::to_string(kMaxDimension) + " (maxImageDimension2D)");
  }
  const std::size_t bytes = std::size_t{width} * height * 4;
  if (rgba.size() != bytes) {
    return Status::error("texture data has " + std::to_string(rgba.size()) + " bytes where " +
                         std::to_string(width) + "x" + std::to_string(height) + " RGBA8 needs " + std::to_string(bytes));
  }
  Texture t;
  t.format_ = format;
  t.levels_.push_back({width, height, std::vector<std::uint8_t>(rgba.begin(), rgba.end())});
  while (mipmaps && (t.levels_.back().width > 1 || t.levels_.back().height > 1)) {
    TextureLevel next = generateMipLevel(t.levels_.back());
    t.levels_.push_back(std::move(next));
  }
  return t;
}

Result<Texture> Texture::fromDepth(const Framebuffer& framebuffer) {
  if (framebuffer.depthFormat() != DepthFormat::D32Sfloat) {
    return Status::error("a depth texture is made from a D32_SFLOAT framebuffer only");
  }
  if (framebuffer.samples() != 1) return Status::error("a depth texture is made from a single-sample framebuffer only");
  if (framebuffer.width() == 0 || framebuffer.height() == 0) return Status::error("the framebuffer has no pixels");
  if (framebuffer.width() > kMaxDimension || framebuffer.height() > kMaxDimension) {
    return Status::error("a depth texture is at most " + std::to_string(kMaxDimension) + " texels wide and high");
  }
  const std::vector<std::uint32_t>& depth = framebuffer.depthStorage();  // D32_SFLOAT: the float's bits
  Texture t;
  t.format_ = TextureFormat::D32Sfloat;
  TextureLevel level{framebuffer.width(), framebuffer.height(), std::vector<std::uint8_t>(depth.size() * 4)};
  std::memcpy(level.rgba.data(), depth.data(), level.rgba.size());
  t.levels_.push_back(std::move(level));
  return t;
}

TextureLevel Texture::generateMipLevel(const TextureLevel& level) {
  TextureLevel next;
  next.width = std::max(1u, level.width / 2);
  next.height = std::max(1u, level.height / 2);
  next.rgba.resize(std::size_t{next.width} * next.height * 4);
  const auto at = [&](std::uint32_t x, std::uint32_t y, int c) {
    x = std::min(x, level.width - 1);
    y = std::min(y, level.height - 1);
    return static_cast<unsigned>(level.rgba[(std::size_t{y} * level.width + x) * 4 + static_cast<unsigned>(c)]);
  };
  for (std::uint32_t y = 0; y < next.height; ++y) {
    for (std::uint32_t x = 0; x < next.width; ++x) {
      for (int c = 0; c < 4; ++c) {
        const unsigned sum = at(2 * x, 2 * y, c) + at(2 * x + 1, 2 * y, c) + at(2 * x, 2 * y + 1, c) +
                             at(2 * x + 1, 2 * y + 1, c);
        next.rgba[(std::size_t{y} * next.width + x) * 4 + static_cast<unsigned>(c)] = static_cast<std::uint8_t>((sum + 2) / 4);
      }
    }
  }
  return next;
}

Status Sampler2D::validate() const {
  if (texture == nullptr || texture->levels() == 0) return Status::error("the sampler has no texture");
  const bool depth = texture->format() == TextureFormat::D32Sfloat;
  if (sampler.compareEnable && !depth) return Status::error("a comparison sampler needs a depth texture");
  if (sampler.compareOp > CompareOp::Always) return Status::error("unknown compare op");
  if (depth && (sampler.magFilter != Filter::Nearest || sampler.minFilter != Filter::Nearest)) {
    return Status::error("a depth texture is sampled with nearest filters only (lavapipe gives depth formats no "
                         "SAMPLED_IMAGE_FILTER_LINEAR, so Vulkan forbids linear filtering of them there)");
  }
  if (detail::texture::usesFloatPath(texture->format(), sampler) && sampler.minFilter != sampler.magFilter) {
    return Status::error(
        "different min and mag filters with sRGB, depth, mirrored repeat or clamp to border are not matched by softraster "
        "yet (lavapipe switches between them per pixel on its float path)");
  }
  for (float v : {sampler.mipLodBias, sampler.minLod, sampler.maxLod}) {
    if (!std::isfinite(v)) return Status::error("sampler LOD bias and clamps must be finite");
  }
  if (!(sampler.minLod <= sampler.maxLod)) return Status::error("sampler minLod must not exceed maxLod (VUID-VkSamplerCreateInfo-maxLod-01973)");
  if (!(std::fabs(sampler.mipLodBias) <= 16.0f)) {
    return Status::error("sampler mipLodBias must be within maxSamplerLodBias (16)");
  }
  return {};
}

}  // namespace softraster
