// vkref frames: what a caller hands the Renderer (a FrameRequest of DrawCalls, each with its
// ShaderProgram and softraster::PipelineState), what it gets back (FrameImages: colour, depth as
// floats, depth as stored and stencil; with MSAA also every sample) and the handle of a frame
// prepared once and submitted many times.
// A frame may render depth passes first (shadow maps) whose depth its draws then sample.
// Deliberately plain values: no Vulkan type appears here, and nothing in a request is kept after
// Renderer::prepare returns (vertices, indices and uniform blocks are uploaded, push constants recorded).
#pragma once

#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>
#include <softraster/texture.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vkref {

// A compiled shader pair and the vertex layout its vertex stage reads. Programs with the same
// SPIR-V and layout share their pipelines, whatever object or name they come in.
struct ShaderProgram {
  std::string name;  // for messages
  std::span<const std::uint32_t> vertexSpirv;
  std::span<const std::uint32_t> fragmentSpirv;
  std::vector<softraster::VertexAttribute> attributes;
  std::uint32_t vertexStride = 0;  // bytes
};

// A texture a draw samples: a combined image sampler at set 1, binding i (i its place in
// DrawCall::textures), visible to the fragment stage. Every level is uploaded by prepare, once per
// texture however many draws sample it; nothing of it is kept after prepare returns.
// Or, with depthPass >= 0, the depth image FrameRequest::depthPasses[depthPass] rendered earlier in
// the same frame (a shadow map; `texture` then stays null), sampled with `sampler` (a comparison
// sampler for sampler2DShadow, or a plain one).
struct TextureBinding {
  const softraster::Texture* texture = nullptr;
  softraster::SamplerState sampler;
  int depthPass = -1;
};

// Combined image samplers a draw may bind (set 1, bindings 0..kMaxTextures-1).
inline constexpr std::size_t kMaxTextures = 2;

struct DrawCall {
  const ShaderProgram* program = nullptr;
  softraster::PipelineState state;
  std::vector<std::byte> vertexData;        // vertexStride bytes per vertex
  bool indexed = true;                      // vkCmdDrawIndexed with `indices`, else vkCmdDraw of all vertices
  std::vector<std::uint32_t> indices;       // assembled by state.topology
  std::vector<std::byte> pushConstants;     // visible to vertex and fragment stages, <= 128 bytes
  // The uniform block at set 0, binding 0 (std140), visible to vertex and fragment stages, for
  // uniforms that do not fit the push constants; at most maxUniformBufferRange bytes. Empty: the
  // program reads none.
  std::vector<std::byte> uniformData;
  std::vector<TextureBinding> textures;     // at most kMaxTextures
};

// A pass that renders depth alone, before the frame's own draws, into a D32_SFLOAT image of its
// own size with no colour attachment (its draws' programs write no colour), then left for later
// draws to sample (TextureBinding::depthPass). Its draws sample nothing themselves.
struct DepthPass {
  std::uint32_t width = 0, height = 0;
  float clearDepth = 1.0f;
  std::vector<DrawCall> draws;
};

// A colour attachment after the first: the fragment shader's output location i + 1 goes to
// FrameRequest::moreColour[i], blended by each draw's PipelineState::moreBlend[i]; its own format
// and clear colour (as the scene gives it, converted as a clear of that format converts).
struct ColourAttachment {
  softraster::ColourFormat format = softraster::ColourFormat::R8G8B8A8Unorm;
  std::array<float, 4> clearColour{0, 0, 0, 0};
};

struct FrameRequest {
  std::uint32_t width = 0, height = 0;
  std::array<float, 4> clearColour{0, 0, 0, 0};
  float clearDepth = 1.0f;
  std::uint8_t clearStencil = 0;  // with a depth/stencil format
  softraster::ColourFormat colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  // Colour attachments 1.. (at most softraster::kMaxColourAttachments - 1), each resolved and read
  // back like the first (FrameImages::moreColour); every draw's program writes their locations.
  std::vector<ColourAttachment> moreColour;
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  std::uint32_t samples = 1;  // 1, or 4: rendered multisampled, colour resolved (average) and
                              // depth and stencil resolved (sample 0); read back both the
                              // resolve and every sample (FrameImages)
  std::vector<DrawCall> draws;  // drawn in order; a draw with nothing to assemble is skipped
  std::vector<DepthPass> depthPasses;  // rendered first, in order, each with the barriers its samplers need
};

// The colour of one attachment after the first, read back as FrameImages holds the first's:
// its resolve (or single sample) as R, G, B, A bytes and, for formats wider than 8 bits, as
// stored words; with MSAA every sample too (the samples of a pixel adjacent).
struct ColourImages {
  std::vector<std::uint8_t> rgba;
  std::vector<std::uint32_t> colourWords;
  std::vector<std::uint8_t> sampleRgba;
  std::vector<std::uint32_t> sampleColourWords;
};

struct FrameImages {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;          // width*height*4, R, G, B, A whatever the format; row 0 at the top
  // A2B10G10R10 and the float formats: each pixel's stored texel as words (one, two for four
  // halves, four for four floats; rgba is then its view, Framebuffer::viewBytes); empty for the
  // 8-bit formats, whose rgba is exact.
  std::vector<std::uint32_t> colourWords;
  std::vector<float> depth;                // width*height, as floats in [0, 1]
  std::vector<std::uint32_t> depthStorage; // width*height, as stored: UNORM integer or the float's bits
  std::vector<std::uint8_t> stencil;       // width*height with a depth/stencil format, else empty
  // With MSAA the four above are the resolve (colour averaged, depth and stencil sample 0), and
  // the images before it follow: every sample, in softraster::Framebuffer's order (the samples of
  // a pixel adjacent, in Vulkan's sample order: index (y * width + x) * samples + s). With one
  // sample `samples` is 1 and these stay empty.
  std::uint32_t samples = 1;
  std::vector<std::uint8_t> sampleRgba;           // 4 bytes per sample
  std::vector<std::uint32_t> sampleColourWords;   // as `colourWords`
  std::vector<float> sampleDepth;                 // as `depth`
  std::vector<std::uint32_t> sampleDepthStorage;  // as `depthStorage`
  std::vector<std::uint8_t> sampleStencil;        // with a depth/stencil format, else empty
  std::vector<ColourImages> moreColour;  // colour attachments 1.., as FrameRequest::moreColour
};

// A frame made ready by Renderer::prepare: its images, its uploaded vertices and indices and its
// recorded command buffers (the pipelines stay in the Renderer's cache). Submit it as often as
// wanted; every submission clears and draws the whole frame again. Movable, not copyable; used by
// one thread at a time; destroy it before the Renderer that prepared it.
class PreparedFrame {
 public:
  PreparedFrame();  // empty: prepares nothing, and submitting it is an error
  PreparedFrame(PreparedFrame&&) noexcept;
  PreparedFrame& operator=(PreparedFrame&&) noexcept;
  ~PreparedFrame();

  bool empty() const { return !impl_; }
  std::uint32_t width() const;
  std::uint32_t height() const;

  struct Impl;

 private:
  friend class Renderer;
  explicit PreparedFrame(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vkref
