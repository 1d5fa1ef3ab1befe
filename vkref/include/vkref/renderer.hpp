// vkref: renders frames through a real Vulkan pipeline (Mesa lavapipe by default), headless, and
// reads colour (one or more attachments, each of softraster::ColourFormat's formats, returned as
// R, G, B, A bytes and, for the wider formats, as stored words) and depth (D16_UNORM,
// X8_D24_UNORM_PACK32, D32_SFLOAT, or the depth/stencil formats') back to host memory. Each
// pipeline is built from softraster::PipelineState, the same value softraster draws with; a
// state Vulkan here cannot express is reported as an error, never defaulted.
// A frame is prepared once (images, uploads, pipelines, recorded commands) and submitted as often
// as wanted, so a benchmark times steady-state frames; render() does all three steps at once.
// Deliberately not a general Vulkan wrapper: no window, no swapchain, 2D textures and depth passes only, one queue.
// Errors are softraster::Status / Result values of one line; the library never prints.
#pragma once

#include <vkref/frame.hpp>

#include <softraster/status.hpp>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace vkref {

struct DeviceOptions {
  std::string deviceName;   // substring of VkPhysicalDeviceProperties::deviceName; empty: lavapipe
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation and collect its messages
};

class Renderer {
 public:
  // Opens the device; an error when no usable Vulkan device exists.
  static softraster::Result<std::unique_ptr<Renderer>> create(const DeviceOptions& options);
  ~Renderer();  // destroy every PreparedFrame of this Renderer first
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Checks the request, creates its images, uploads its vertices and indices, takes its pipelines
  // from the cache (compiling the ones not seen before) and records its command buffers.
  softraster::Result<PreparedFrame> prepare(const FrameRequest& request);
  // Renders the prepared frame (clear, draws, resolve) and waits until it is done.
  softraster::Status submit(PreparedFrame& frame);
  // Copies the images of the last submission to host memory: colour resolved, depth as floats
  // and as stored. An error before the frame's first submission.
  softraster::Result<FrameImages> readBack(const PreparedFrame& frame);
  // prepare + submit + readBack, for a frame rendered once.
  softraster::Result<FrameImages> render(const FrameRequest& request);

  std::string deviceName() const;
  // Messages reported by the validation layer since creation (warnings and errors).
  std::vector<std::string> validationMessages() const;
  // Pipelines compiled so far; each is compiled once and kept until the Renderer is destroyed.
  std::size_t cachedPipelines() const;

  struct Impl;

 private:
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vkref
