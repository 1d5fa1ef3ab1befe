// Renders a Scene with either renderer into a Frame: RGBA8 colour and float depth, row 0 at the
// top. Both adapters hand the renderers the same vertices and uniforms (made by each draw's row
// of shaders/shading_models.hpp), indices, matrices and PipelineState, and time one span each
// (Frame::milliseconds). openVulkan is the one place a vkref::Renderer is opened.
// Deliberately one call, one frame (the vkref::Renderer keeps only its compiled pipelines).
#pragma once

#include "scene/scene.hpp"

#include <softraster/pipeline.hpp>
#include <softraster/status.hpp>
#include <vkref/renderer.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace crosscheck {

struct Frame {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;
  std::vector<float> depth;                 // as floats in [0, 1], for views
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  std::vector<std::uint32_t> depthStorage;  // as the format stores it, for exact comparison
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

// A Vulkan renderer on the device the options pick (lavapipe by default); the error is vkref's
// one line, without a prefix ("no Vulkan driver found ...").
softraster::Result<std::unique_ptr<vkref::Renderer>> openVulkan(const vkref::DeviceOptions& options);

}  // namespace crosscheck
