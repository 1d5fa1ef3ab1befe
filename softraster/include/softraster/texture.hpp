// Textures for shader twins: a Texture (format, size, mip chain), a SamplerState mirroring
// VkSamplerCreateInfo, and Sampler2D, the pair a shader's uniforms hold where the GLSL declares
// a `sampler2D`. A twin samples it with softraster::texture(sampler, u, v), as the GLSL calls
// texture(sampler, vec2(u, v)), from its fragment function over FloatBatch (simd.hpp): the 8
// lanes are two 2x2 quads, and the level of detail comes from the differences inside each quad,
// as lavapipe computes it (detail/texture/). A twin that samples declares
// `static constexpr bool kQuads = true`; softraster then shades it in quads on every path (the
// scalar path too), with the quad's uncovered pixels as helpers, so derivatives exist everywhere.
//
// Exactness: lavapipe's two paths, chosen as it chooses them: 8-bit fixed-point filtering (its
// "AoS" path) for R8G8B8A8_UNORM with repeat or clamp to edge in both directions, and its float
// path for sRGB (its polynomial decode), mirrored repeat and clamp to border; LOD per quad with
// its piecewise-linear log2, mip selection, LOD bias and clamps, the min/mag switch.
// Sampler2D::validate() refuses the one combination not matched yet (different min and mag
// filters on the float path), so a scene using it is an error, not a silent difference.
// Depth textures (shadow maps): a D32_SFLOAT Texture made from a Framebuffer's depth
// (Texture::fromDepth), one level, sampled on the float path either as a colour (depth, 0, 0, 1)
// by texture() or through a comparison sampler (SamplerState::compareEnable, GLSL's
// sampler2DShadow) by textureShadow(): the texel compared with the reference, 1 or 0. Nearest
// filtering only: lavapipe gives depth formats no SAMPLED_IMAGE_FILTER_LINEAR, so Vulkan forbids
// a linear filter on them there (percentage-closer filtering is the shader's to do, tap by tap).
// Deliberately absent: 1D/3D/cube/array textures, anisotropy, texel offsets, explicit LOD and
// gradients, unnormalized coordinates, mipmapped or UNORM depth textures.
#pragma once

#include <softraster/framebuffer.hpp>
#include <softraster/math.hpp>
#include <softraster/simd.hpp>
#include <softraster/state.hpp>
#include <softraster/status.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace softraster {

enum class TextureFormat : std::uint8_t { R8G8B8A8Unorm, R8G8B8A8Srgb, D32Sfloat };

// One mip level: width x height texels of 4 bytes, row 0 first: R, G, B, A, or for D32Sfloat
// the depth float's bytes (native order).
struct TextureLevel {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
};

class Texture {
 public:
  // lavapipe's maxImageDimension2D.
  static constexpr std::uint32_t kMaxDimension = 16384;

  // A texture from `rgba` (width * height * 4 bytes, row 0 first); with `mipmaps`, every level
  // down to 1x1 is made from the one above by generateMipLevel. Errors: a size of 0 or above
  // kMaxDimension, or `rgba` of the wrong length.
  static Result<Texture> create(TextureFormat format, std::uint32_t width, std::uint32_t height,
                                std::span<const std::uint8_t> rgba, bool mipmaps);

  // The next level of `level`: max(1, w/2) x max(1, h/2), each texel the rounded average
  // (sum + 2) / 4 of the 2x2 texels above it (an odd last row or column is read as its
  // neighbour's copy). Bytes are averaged as stored (for sRGB too: the one chain both renderers
  // upload, not a linear-light filter).
  static TextureLevel generateMipLevel(const TextureLevel& level);

  // A D32_SFLOAT texture of one level from the depth of a single-sample D32_SFLOAT framebuffer
  // (pixel (x, y) of the framebuffer is texel (x, y)): a shadow map from its pass. Errors: another
  // depth format, or a multisampled framebuffer.
  static Result<Texture> fromDepth(const Framebuffer& framebuffer);

  Texture() = default;  // no texels; sampling it gives (0, 0, 0, 0)
  TextureFormat format() const { return format_; }
  std::uint32_t levels() const { return static_cast<std::uint32_t>(levels_.size()); }
  const TextureLevel& level(std::uint32_t i) const { return levels_[i]; }
  std::uint32_t width() const { return levels_.empty() ? 0 : levels_[0].width; }
  std::uint32_t height() const { return levels_.empty() ? 0 : levels_[0].height; }

 private:
  TextureFormat format_ = TextureFormat::R8G8B8A8Unorm;
  std::vector<TextureLevel> levels_;
};

enum class Filter : std::uint8_t { Nearest, Linear };
enum class MipmapMode : std::uint8_t { Nearest, Linear };
enum class AddressMode : std::uint8_t { Repeat, MirroredRepeat, ClampToEdge, ClampToBorder };
enum class BorderColor : std::uint8_t { TransparentBlack, OpaqueBlack, OpaqueWhite };

// VkSamplerCreateInfo's fields that matter here, with its defaults where Vulkan has them.
struct SamplerState {
  Filter magFilter = Filter::Linear;
  Filter minFilter = Filter::Linear;
  MipmapMode mipmapMode = MipmapMode::Nearest;
  AddressMode addressModeU = AddressMode::Repeat;
  AddressMode addressModeV = AddressMode::Repeat;
  float mipLodBias = 0.0f;
  float minLod = 0.0f;
  float maxLod = 1000.0f;  // VK_LOD_CLAMP_NONE
  BorderColor borderColor = BorderColor::TransparentBlack;
  bool compareEnable = false;             // a comparison sampler: textureShadow() only
  CompareOp compareOp = CompareOp::Never;  // reference OP texel gives 1, else 0
};

// What a `sampler2D` uniform is: a texture (not owned; it must outlive the draws) and a sampler.
struct Sampler2D {
  const Texture* texture = nullptr;
  SamplerState sampler;

  // Whether softraster samples this exactly as lavapipe does (see the top of this file); one
  // error naming the state when not. Sampling an invalid Sampler2D never faults (it gives a
  // defined colour), but only a valid one is cross-checked.
  Status validate() const;
};

// GLSL texture(sampler, vec2(u, v)) over the two quads of a batch, implicit LOD.
inline Vec4T<FloatBatch> texture(const Sampler2D& sampler, FloatBatch u, FloatBatch v);

// GLSL texture(sampler2DShadow, vec3(u, v, reference)): per lane, 1 where `reference compareOp
// texel` holds for the nearest texel (an ordered compare; NotEqual is unordered), else 0. The sampler
// must be a comparison sampler on a depth texture (validate()); otherwise every lane is 0.
inline FloatBatch textureShadow(const Sampler2D& sampler, FloatBatch u, FloatBatch v, FloatBatch reference);

}  // namespace softraster

#include <softraster/detail/texture/sample.hpp>
