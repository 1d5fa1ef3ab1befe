// vkref: renders a frame through a real Vulkan pipeline (Mesa lavapipe by default), headless,
// and reads colour (R8G8B8A8_UNORM) and depth (D16_UNORM, X8_D24_UNORM_PACK32 or D32_SFLOAT)
// back to host memory.
// The pipeline is built from softraster::PipelineState, the same value softraster draws with;
// a state Vulkan here cannot express is reported as an error.
// Deliberately not a general Vulkan wrapper: no window, no swapchain, one frame per call.
#pragma once

#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vkref {

// A compiled shader pair and the vertex layout its vertex stage reads.
struct ShaderProgram {
  std::string name;
  std::span<const std::uint32_t> vertexSpirv;
  std::span<const std::uint32_t> fragmentSpirv;
  std::vector<softraster::VertexAttribute> attributes;
  std::uint32_t vertexStride = 0;  // bytes
};

struct DrawCall {
  const ShaderProgram* program = nullptr;
  softraster::PipelineState state;
  std::vector<std::byte> vertexData;        // vertexStride bytes per vertex
  bool indexed = true;                      // vkCmdDrawIndexed with `indices`, else vkCmdDraw of all vertices
  std::vector<std::uint32_t> indices;       // assembled by state.topology
  std::vector<std::byte> pushConstants;     // visible to vertex and fragment stages, <= 128 bytes
};

struct FrameRequest {
  std::uint32_t width = 0, height = 0;
  std::array<float, 4> clearColour{0, 0, 0, 0};
  float clearDepth = 1.0f;
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  std::uint32_t samples = 1;  // 1, or 4: rendered multisampled, colour resolved (average) and
                              // depth resolved (sample 0) before read-back
  std::vector<DrawCall> draws;
};

struct FrameImages {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgba;          // width*height*4, row 0 at the top
  std::vector<float> depth;                // width*height, as floats in [0, 1]
  std::vector<std::uint32_t> depthStorage; // width*height, as stored: UNORM integer or the float's bits
};

struct DeviceOptions {
  std::string deviceName;   // substring of VkPhysicalDeviceProperties::deviceName; empty: lavapipe
  bool validation = false;  // enable VK_LAYER_KHRONOS_validation and collect its messages
};

class Renderer {
 public:
  // Returns nullptr and sets *error (one line) when no usable Vulkan device exists.
  static std::unique_ptr<Renderer> create(const DeviceOptions& options, std::string* error);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Renders the frame; returns false and sets *error on failure.
  bool render(const FrameRequest& request, FrameImages* out, std::string* error);

  std::string deviceName() const;
  // Messages reported by the validation layer since creation (warnings and errors).
  std::vector<std::string> validationMessages() const;

  struct Impl;

 private:
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace vkref
