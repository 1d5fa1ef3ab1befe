// vkref textures (see textures.hpp): upload, samplers, descriptor sets.
#include "textures.hpp"

#include "errors.hpp"
#include "passes.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace vkref::detail {
namespace {

using softraster::Status;

VkFormat formatOf(softraster::TextureFormat f) {
  return f == softraster::TextureFormat::R8G8B8A8Srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
}

VkFilter filterOf(softraster::Filter f) { return f == softraster::Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST; }

VkSamplerAddressMode addressOf(softraster::AddressMode m) {
  switch (m) {
    case softraster::AddressMode::Repeat: return VK_SAMPLER_ADDRESS_MODE_REPEAT;
    case softraster::AddressMode::MirroredRepeat: return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    case softraster::AddressMode::ClampToEdge: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    case softraster::AddressMode::ClampToBorder: return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
  }
  return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}

VkBorderColor borderOf(softraster::BorderColor c) {
  switch (c) {
    case softraster::BorderColor::TransparentBlack: return VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    case softraster::BorderColor::OpaqueBlack: return VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
    case softraster::BorderColor::OpaqueWhite: return VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
  }
  return VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
}

// Copies every level of each texture from `staging` into its image and leaves it ready to be
// sampled: one command buffer, submitted once and waited for.
Status upload(const Device& device, std::span<const softraster::Texture* const> textures, std::span<const Image> images,
              const Buffer& staging, std::span<const VkDeviceSize> offsets) {
  VkCommandPool pool = VK_NULL_HANDLE;
  const VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                         .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                         .queueFamilyIndex = device.queueFamily};
  if (Status s = check(vkCreateCommandPool(device.device, &poolInfo, nullptr, &pool), "vkCreateCommandPool"); !s)
    return s;
  VkFence fence = VK_NULL_HANDLE;
  const auto cleanup = [&] {
    if (fence) vkDestroyFence(device.device, fence, nullptr);
    vkDestroyCommandPool(device.device, pool, nullptr);
  };
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  const VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = pool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
  const VkFenceCreateInfo fenceInfo{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                       .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  Status status = check(vkAllocateCommandBuffers(device.device, &allocInfo, &cmd), "vkAllocateCommandBuffers");
  if (status) status = check(vkCreateFence(device.device, &fenceInfo, nullptr, &fence), "vkCreateFence");
  if (status) status = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  if (!status) {
    cleanup();
    return status;
  }
  for (std::size_t t = 0; t < textures.size(); ++t) {
    const softraster::Texture& texture = *textures[t];
    const VkImageMemoryBarrier2 toCopy =
        imageBarrier(images[t].handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE,
                     VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                     VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, texture.levels());
    barrier(cmd, std::span(&toCopy, 1));
    std::vector<VkBufferImageCopy> regions;
    VkDeviceSize offset = offsets[t];
    for (std::uint32_t l = 0; l < texture.levels(); ++l) {
      const softraster::TextureLevel& level = texture.level(l);
      regions.push_back({.bufferOffset = offset,
                         .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1},
                         .imageExtent = {level.width, level.height, 1}});
      offset += level.rgba.size();
    }
    vkCmdCopyBufferToImage(cmd, staging.handle(), images[t].handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           static_cast<std::uint32_t>(regions.size()), regions.data());
    const VkImageMemoryBarrier2 toSample =
        imageBarrier(images[t].handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                     VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, texture.levels());
    barrier(cmd, std::span(&toSample, 1));
  }
  status = check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
  if (status) status = check(vkQueueSubmit(device.queue, 1, &submit, fence), "vkQueueSubmit");
  if (status) status = check(vkWaitForFences(device.device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  cleanup();
  return status;
}

}  // namespace

softraster::Result<FrameTextures> FrameTextures::create(const Device& device, VkDescriptorSetLayout layout,
                                                        std::span<const DrawCall* const> draws,
                                                        std::span<const VkImageView> depthPassViews) {
  FrameTextures f;
  f.device_ = device.device;
  std::vector<const softraster::Texture*> textures;  // distinct, in first use order (not the passes' images)
  std::size_t textured = 0;
  for (const DrawCall* d : draws) {
    for (const TextureBinding& b : d->textures) {
      if (b.texture != nullptr && std::find(textures.begin(), textures.end(), b.texture) == textures.end())
        textures.push_back(b.texture);
    }
    textured += d->textures.empty() ? 0 : 1;
  }
  f.sets_.assign(draws.size(), VK_NULL_HANDLE);
  if (textured == 0) return f;

  // Every level of every texture, one after another, in a staging buffer.
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize total = 0;
  for (const softraster::Texture* t : textures) {
    offsets.push_back(total);
    for (std::uint32_t l = 0; l < t->levels(); ++l) total += t->level(l).rgba.size();
  }
  Buffer staging;
  if (total > 0) {
    auto created = Buffer::create(device, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    if (!created) return created.status();
    staging = std::move(*created);
  }
  for (std::size_t i = 0; i < textures.size(); ++i) {
    VkDeviceSize at = offsets[i];
    for (std::uint32_t l = 0; l < textures[i]->levels(); ++l) {
      const std::vector<std::uint8_t>& bytes = textures[i]->level(l).rgba;
      std::memcpy(static_cast<std::byte*>(staging.mapped()) + at, bytes.data(), bytes.size());
      at += bytes.size();
    }
    auto image = Image::create(device, formatOf(textures[i]->format()),
                               VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                               textures[i]->width(), textures[i]->height(), VK_SAMPLE_COUNT_1_BIT, textures[i]->levels());
    if (!image) return image.status();
    f.images_.push_back(std::move(*image));
  }
  if (!textures.empty()) {
    if (Status s = upload(device, textures, f.images_, staging, offsets); !s) return s;
  }

  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, static_cast<std::uint32_t>(textured * kMaxTextures)};
  const VkDescriptorPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                            .maxSets = static_cast<std::uint32_t>(textured),
                                            .poolSizeCount = 1,
                                            .pPoolSizes = &size};
  if (Status s = check(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &f.pool_), "vkCreateDescriptorPool"); !s)
    return s;
  for (std::size_t i = 0; i < draws.size(); ++i) {
    if (draws[i]->textures.empty()) continue;
    const VkDescriptorSetAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                                .descriptorPool = f.pool_,
                                                .descriptorSetCount = 1,
                                                .pSetLayouts = &layout};
    if (Status s = check(vkAllocateDescriptorSets(device.device, &allocInfo, &f.sets_[i]), "vkAllocateDescriptorSets"); !s)
      return s;
    std::vector<VkDescriptorImageInfo> infos;
    for (const TextureBinding& b : draws[i]->textures) {
      const softraster::SamplerState& st = b.sampler;
      const VkSamplerCreateInfo samplerInfo{.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
                                            .magFilter = filterOf(st.magFilter),
                                            .minFilter = filterOf(st.minFilter),
                                            .mipmapMode = st.mipmapMode == softraster::MipmapMode::Linear
                                                              ? VK_SAMPLER_MIPMAP_MODE_LINEAR
                                                              : VK_SAMPLER_MIPMAP_MODE_NEAREST,
                                            .addressModeU = addressOf(st.addressModeU),
                                            .addressModeV = addressOf(st.addressModeV),
                                            .addressModeW = VK_SAMPLER_ADDRESS_MODE_REPEAT,
                                            .mipLodBias = st.mipLodBias,
                                            .anisotropyEnable = VK_FALSE,
                                            .maxAnisotropy = 1.0f,
                                            .compareEnable = st.compareEnable ? VK_TRUE : VK_FALSE,
                                            .compareOp = static_cast<VkCompareOp>(st.compareOp),  // same order as Vulkan's
                                            .minLod = st.minLod,
                                            .maxLod = st.maxLod,
                                            .borderColor = borderOf(st.borderColor),
                                            .unnormalizedCoordinates = VK_FALSE};
      VkSampler sampler = VK_NULL_HANDLE;
      if (Status s = check(vkCreateSampler(device.device, &samplerInfo, nullptr, &sampler), "vkCreateSampler"); !s)
        return s;
      f.samplers_.push_back(sampler);
      if (b.texture == nullptr) {  // a depth pass's image, left in this layout by its pass
        infos.push_back({sampler, depthPassViews[static_cast<std::size_t>(b.depthPass)],
                         VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
        continue;
      }
      const std::size_t image = static_cast<std::size_t>(std::find(textures.begin(), textures.end(), b.texture) - textures.begin());
      infos.push_back({sampler, f.images_[image].view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
    }
    // Bindings the draw leaves empty get its first texture again: lavapipe reads every binding
    // of a set when it is bound (an unwritten one crashes it), whatever the shader samples.
    while (infos.size() < kMaxTextures) infos.push_back(infos.front());
    std::vector<VkWriteDescriptorSet> writes;
    for (std::uint32_t b = 0; b < infos.size(); ++b) {
      writes.push_back({.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                        .dstSet = f.sets_[i],
                        .dstBinding = b,
                        .descriptorCount = 1,
                        .descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                        .pImageInfo = &infos[b]});
    }
    vkUpdateDescriptorSets(device.device, static_cast<std::uint32_t>(writes.size()), writes.data(), 0, nullptr);
  }
  return f;
}

FrameTextures::FrameTextures(FrameTextures&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      images_(std::move(other.images_)),
      samplers_(std::move(other.samplers_)),
      pool_(std::exchange(other.pool_, VK_NULL_HANDLE)),
      sets_(std::move(other.sets_)) {}

FrameTextures& FrameTextures::operator=(FrameTextures&& other) noexcept {
  if (this != &other) {
    destroy();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    images_ = std::move(other.images_);
    samplers_ = std::move(other.samplers_);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    sets_ = std::move(other.sets_);
  }
  return *this;
}

FrameTextures::~FrameTextures() { destroy(); }

void FrameTextures::destroy() {
  if (!device_) return;
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees the sets
  for (VkSampler s : samplers_) vkDestroySampler(device_, s, nullptr);
  samplers_.clear();
  images_.clear();
  device_ = VK_NULL_HANDLE;
}

}  // namespace vkref::detail
