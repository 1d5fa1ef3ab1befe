// vkref device: the Vulkan instance (with VK_LAYER_KHRONOS_validation and a debug messenger that
// collects its warnings and errors, when asked), the pick of lavapipe or of a named device, the
// features and formats it offers, and its one graphics queue.
// Deliberately nothing per frame (images and buffers: resources; pipelines: pipelines; command
// buffers: passes) and no printing: validation messages are kept for the caller to read.
#pragma once

#include <vkref/renderer.hpp>

#include <softraster/framebuffer.hpp>
#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <iterator>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace vkref::detail {

// The colour and depth formats are the request's. Indexed by softraster::ColourFormat.
inline constexpr VkFormat kColourFormats[] = {VK_FORMAT_R8G8B8A8_UNORM,
                                              VK_FORMAT_B8G8R8A8_UNORM,
                                              VK_FORMAT_R8G8B8A8_SRGB,
                                              VK_FORMAT_B8G8R8A8_SRGB,
                                              VK_FORMAT_A2B10G10R10_UNORM_PACK32,
                                              VK_FORMAT_R16G16B16A16_SFLOAT,
                                              VK_FORMAT_R32G32B32A32_SFLOAT};
// 32-bit words per texel of a colour format, and the unsigned integer format of that many words
// (a view in the same compatibility class) through which a shader reads its bits unconverted.
inline constexpr std::uint32_t colourWords(VkFormat format) {
  return format == VK_FORMAT_R16G16B16A16_SFLOAT ? 2u : format == VK_FORMAT_R32G32B32A32_SFLOAT ? 4u : 1u;
}
inline constexpr VkFormat colourBitsFormat(VkFormat format) {
  return colourWords(format) == 4 ? VK_FORMAT_R32G32B32A32_UINT
         : colourWords(format) == 2 ? VK_FORMAT_R32G32_UINT
                                    : VK_FORMAT_R32_UINT;
}
// Indexed by softraster::DepthFormat.
inline constexpr VkFormat kDepthFormats[] = {VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D32_SFLOAT,
                                             VK_FORMAT_D24_UNORM_S8_UINT, VK_FORMAT_D32_SFLOAT_S8_UINT};

// The aspects of a depth (or depth/stencil) format: barriers and views name them all.
inline constexpr VkImageAspectFlags depthAspects(VkFormat format) {
  return format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_D32_SFLOAT_S8_UINT
             ? VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT
             : VK_IMAGE_ASPECT_DEPTH_BIT;
}

// An open device. Not movable: the debug messenger holds its address.
class Device {
 public:
  static softraster::Result<std::unique_ptr<Device>> create(const DeviceOptions& options);
  ~Device();  // waits for the device to be idle, then destroys it, the messenger and the instance
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceLimits limits{};
  VkPhysicalDeviceFeatures features{};  // the core features enabled on `device`
  bool bresenhamLines = false;          // VK_EXT_line_rasterization with bresenhamLines enabled
  bool rectangularLines = false;        // ... with rectangularLines enabled (explicit rectangular mode)
  bool stippledRectangularLines = false;  // ... with stippledRectangularLines enabled
  bool stippledBresenhamLines = false;    // ... with stippledBresenhamLines enabled
  bool provokingVertexLast = false;     // VK_EXT_provoking_vertex with provokingVertexLast enabled
  std::array<bool, std::size(kDepthFormats)> depthFormatUsable{};  // can be rendered to and copied
  std::array<bool, std::size(kColourFormats)> colourFormatUsable{};  // can be rendered to, blended, copied
  std::string name;

  // Messages the validation layer reported so far (thread-safe: the layer may call from any thread).
  std::vector<std::string> messages() const;
  void addMessage(const char* text);

 private:
  Device() = default;
  softraster::Status createInstance(bool validation);
  softraster::Status pickDevice(const std::string& wanted);
  softraster::Status createDevice();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice_ = VK_NULL_HANDLE;
  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;
};

}  // namespace vkref::detail
