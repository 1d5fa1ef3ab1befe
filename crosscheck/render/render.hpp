// Renders a Scene with either renderer into a Frame: RGBA8 colour (of every colour attachment),
// float depth and (with a depth/stencil format) stencil, row 0 at the top; with MSAA the resolve
// and every sample. Both adapters hand the renderers the same vertices and uniforms (made by each draw's row
// of shaders/shading_models.hpp), indices, matrices and PipelineState, and time one span each
// (Frame::milliseconds). openVulkan is the one place a vkref::Renderer is opened.
// renderSoftraster / renderVulkan are one call, one frame. For steady-state frames (the bench) a
// scene is made ready once and drawn again and again: SoftrasterScene (Context, framebuffer and
// draws built once) and prepareVulkan / readVulkan around vkref's submit; the one-frame calls
// are built from them, so both measure the same work.
// Deliberately no timing loop, statistics or comparison here (run/bench.cpp, compare/).
#pragma once

#include "scene/scene.hpp"

#include <shading_models.hpp>

#include <softraster/pass.hpp>
#include <softraster/pipeline.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace crosscheck {

// One colour attachment after the first, as Frame holds the first's colour (below).
struct ColourImage {
  softraster::ColourFormat colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  std::vector<std::uint8_t> rgba;                 // the resolve (or the one sample), R, G, B, A bytes
  std::vector<std::uint32_t> colourWords;         // a wider format's texels, else empty
  std::vector<std::uint8_t> sampleRgba;           // with MSAA, every sample
  std::vector<std::uint32_t> sampleColourWords;   // as colourWords
};

struct Frame {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;           // R, G, B, A bytes (of a wider format: a view of colourWords)
  softraster::ColourFormat colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  // A2B10G10R10 and the float formats: each pixel's stored texel as words (1, 2 or 4), compared
  // in the format's own steps (compare/); empty for 8-bit formats.
  std::vector<std::uint32_t> colourWords;
  std::vector<float> depth;                 // as floats in [0, 1], for views
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  std::vector<std::uint32_t> depthStorage;  // as the format stores it, for exact comparison
  std::vector<std::uint8_t> stencil;        // one byte per pixel with a depth/stencil format, else empty
  // With MSAA the four above are the resolve (colour averaged, depth and stencil sample 0), and the
  // samples before it follow, in softraster::Framebuffer's order ((y * width + x) * samples + s,
  // Vulkan's sample order); with one sample these stay empty and `samples` is 1.
  std::uint32_t samples = 1;
  std::vector<std::uint8_t> sampleRgba;           // 4 bytes per sample
  std::vector<std::uint32_t> sampleColourWords;   // as colourWords
  std::vector<std::uint32_t> sampleDepthStorage;  // as depthStorage
  std::vector<std::uint8_t> sampleStencil;        // as stencil
  std::vector<ColourImage> moreColour;      // colour attachments 1.. (Scene::moreColour)
  double milliseconds = 0;                  // the renderer's timed span (render.cpp): softraster's clear,
                                            // draws and resolve; vkref's submit (the same work)
};

// Errors: "softraster: draw 'NAME': what is wrong", "vulkan: what is wrong".
softraster::Result<Frame> renderSoftraster(const Scene& scene, const softraster::ContextOptions& options = {});
// The scene drawn by softraster, every sample as stored (not resolved, depth in its format):
// what the fast path's bit-identity test compares with the scalar path's.
softraster::Result<softraster::Framebuffer> renderSoftrasterSamples(const Scene& scene,
                                                                   const softraster::ContextOptions& options);
softraster::Result<Frame> renderVulkan(const Scene& scene, vkref::Renderer& renderer);

// A scene made ready for softraster once: a Context with `options` (it owns its threads), the
// framebuffer and every draw's vertices and uniforms in its shading model's types. Each render()
// draws one whole frame (its depth passes, clear, draws, MSAA resolve) and times exactly that span. Keeps a
// reference to `scene`, which must outlive it.
class SoftrasterScene {
 public:
  SoftrasterScene(const Scene& scene, const softraster::ContextOptions& options);
  // One frame; the error is "softraster: draw 'NAME': what is wrong".
  softraster::Status render();
  double milliseconds() const { return milliseconds_; }  // the last render()'s span
  unsigned threads() const { return context_.threads(); }
  // The last rendered frame: a copy (frame()) or the images themselves (takeFrame(), after which
  // only render() may be called again).
  Frame frame() const;
  Frame takeFrame();
  // The last frame before any resolve: every sample as stored.
  const softraster::Framebuffer& samples() const { return framebuffer_; }

 private:
  softraster::Framebuffer& output() { return scene_.samples > 1 ? resolved_ : framebuffer_; }
  // A depth pass: its framebuffer (D32_SFLOAT, colour writes masked off), its draws with the
  // depth_only model, and the texture its depth becomes each frame (at a fixed address, which the
  // draws sampling it hold).
  struct Pass {
    softraster::Framebuffer framebuffer;
    std::unique_ptr<softraster::Texture> depth;
    std::vector<shaders::SoftrasterDraw> draws;
    std::vector<softraster::PipelineState> states;  // the pass's state with each draw's topology and polygon mode
  };
  const Scene& scene_;
  softraster::ContextOptions options_;
  softraster::Context context_;
  softraster::Framebuffer framebuffer_, resolved_;  // resolved_: the MSAA resolve's output
  softraster::Status framebufferStatus_;              // why framebuffer_ could not be made, if so
  std::vector<Pass> passes_;
  std::vector<shaders::SoftrasterDraw> draws_;
  std::vector<softraster::Vec4> clearColours_;  // one per colour attachment (kept: no allocation per frame)
  double milliseconds_ = 0;
  // Each framebuffer's draws of a frame as one pass (softraster/pass.hpp); last, so that it ends
  // (draws what an interrupted frame kept) before the framebuffers go.
  softraster::Pass pass_;
};

// The scene made ready on `renderer` (images, uploads, pipelines, recorded commands), to be
// submitted as often as wanted; readVulkan reads the last submission back as a Frame (without
// milliseconds). Errors: "vulkan: what is wrong".
softraster::Result<vkref::PreparedFrame> prepareVulkan(const Scene& scene, vkref::Renderer& renderer);
softraster::Result<Frame> readVulkan(const Scene& scene, vkref::Renderer& renderer, const vkref::PreparedFrame& prepared);

// A Vulkan renderer on the device the options pick (lavapipe by default); the error is vkref's
// one line, without a prefix ("no Vulkan driver found ...").
softraster::Result<std::unique_ptr<vkref::Renderer>> openVulkan(const vkref::DeviceOptions& options);

}  // namespace crosscheck
