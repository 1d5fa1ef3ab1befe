// vkref textures: a frame's sampled textures, uploaded once at prepare (every level, through a
// staging buffer and one submission), their samplers, and one descriptor set per textured draw
// (set 1: combined image samplers at bindings 0..n-1, pipelines.hpp's layout), which may also
// bind a depth pass's image (a shadow map, rendered in the frame; not uploaded).
// A texture sampled by several draws is uploaded once (by address); samplers are made per
// binding (a frame has a handful). Deliberately no cache across frames: a prepared frame owns
// everything it samples.
#pragma once

#include "device.hpp"
#include "resources.hpp"

#include <vkref/frame.hpp>

#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <span>
#include <vector>

namespace vkref::detail {

class FrameTextures {
 public:
  // Uploads the textures of `draws` and writes their descriptor sets (layout: set 1's); a binding
  // naming a depth pass gets depthPassViews[its pass] (in SHADER_READ_ONLY_OPTIMAL when sampled).
  static softraster::Result<FrameTextures> create(const Device& device, VkDescriptorSetLayout layout,
                                                  std::span<const DrawCall* const> draws,
                                                  std::span<const VkImageView> depthPassViews = {});
  FrameTextures() = default;
  FrameTextures(FrameTextures&& other) noexcept;
  FrameTextures& operator=(FrameTextures&& other) noexcept;
  ~FrameTextures();

  // The set of draw i (of the span given to create), or VK_NULL_HANDLE when it samples nothing.
  VkDescriptorSet setOf(std::size_t draw) const { return draw < sets_.size() ? sets_[draw] : VK_NULL_HANDLE; }

 private:
  void destroy();
  VkDevice device_ = VK_NULL_HANDLE;
  std::vector<Image> images_;
  std::vector<VkSampler> samplers_;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets_;
};

}  // namespace vkref::detail
