// vkref passes: command recording. The render pass of a frame: its depth passes first (each
// rendering depth alone into its image, then a barrier that makes the image a sampled texture
// for the fragment stage), its images moved to attachment
// layouts, dynamic rendering that clears every colour attachment (each to its own colour) and
// depth, the draws (each binding only what differs from the draw before it), the MSAA resolve of
// every attachment at the end of rendering, and the barrier that leaves the single-sample images
// ready to be copied. Also the command buffers and the fence
// a prepared frame owns, and their submission.
// Deliberately no pipeline building (pipelines), no buffers or images (resources), no copies to
// the host (readback), and no pass reads another's colour: only depth passes feed later ones.
#pragma once

#include "device.hpp"
#include "resources.hpp"

#include <vkref/frame.hpp>

#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

namespace vkref::detail {

// One draw as the pass records it.
struct PassDraw {
  VkPipeline pipeline = VK_NULL_HANDLE;
  bool bindVertices = false;      // the program reads vertices...
  VkDeviceSize vertexOffset = 0;  // ...from here in the frame's vertex buffer
  bool indexed = false;
  std::uint32_t firstIndex = 0;            // into the frame's index buffer, when indexed
  std::uint32_t count = 0;                 // indices when indexed, else vertices
  std::span<const std::byte> pushConstants;  // empty: the previous draw's stay
  bool bindUniforms = false;       // the draw has a uniform block...
  std::uint32_t uniformOffset = 0;  // ...at this dynamic offset in the frame's uniform buffer
  VkDescriptorSet textures = VK_NULL_HANDLE;  // set 1 (the draw's textures), or null when it samples none
};

// A depth pass recorded before the frame's own rendering: its image (D32_SFLOAT, single-sample,
// sampled later), cleared to clearDepth, and its draws.
struct DepthPassRecord {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  std::uint32_t width = 0, height = 0;
  float clearDepth = 1.0f;
  std::span<const PassDraw> draws;
};

// Everything the render pass of a frame reads.
struct FramePass {
  const Targets* targets = nullptr;
  std::array<float, 4> clearColour{};
  std::span<const ColourAttachment> moreColour;  // clear colours of targets->moreColour, in order
  float clearDepth = 1.0f;
  std::uint32_t clearStencil = 0;  // with a depth/stencil format
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkBuffer vertices = VK_NULL_HANDLE;  // the frame's buffers (null when no draw uses one)
  VkBuffer indices = VK_NULL_HANDLE;
  VkDescriptorSet uniforms = VK_NULL_HANDLE;  // the frame's uniform blocks (null when no draw has one)
  std::span<const PassDraw> draws;
  std::span<const DepthPassRecord> depthPasses;  // rendered first, in order
};

// Records the whole render pass into `cmd`, from vkBeginCommandBuffer to vkEndCommandBuffer.
// The command buffer may be submitted again and again: each submission clears and draws anew.
softraster::Status recordRenderPass(VkCommandBuffer cmd, const FramePass& pass);

// An image memory barrier on the whole of a single-layer image of `levels` mip levels.
VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
                                   VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                                   VkImageLayout from, VkImageLayout to, std::uint32_t levels = 1);
void barrier(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images,
             const VkMemoryBarrier2* memory = nullptr);

// A prepared frame's command pool with its two command buffers (the render pass; the copies to
// the host) and the fence their submissions wait on. Neither copied nor moved: its owner holds
// it by unique_ptr.
class Commands {
 public:
  static softraster::Result<std::unique_ptr<Commands>> create(const Device& device);
  ~Commands();  // waits for a submission that was not seen to finish, then destroys everything
  Commands(const Commands&) = delete;
  Commands& operator=(const Commands&) = delete;

  VkCommandBuffer render() const { return buffers_[0]; }
  VkCommandBuffer copy() const { return buffers_[1]; }
  // Submits `cmd` (one of the two) and waits for it to finish.
  softraster::Status submitAndWait(VkCommandBuffer cmd);

 private:
  explicit Commands(const Device& device) : device_(device.device), queue_(device.queue) {}
  VkDevice device_;
  VkQueue queue_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  std::array<VkCommandBuffer, 2> buffers_{};
  VkFence fence_ = VK_NULL_HANDLE;
  bool pending_ = false;
};

}  // namespace vkref::detail
