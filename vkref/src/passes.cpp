// vkref passes (see passes.hpp): barriers, dynamic rendering, clears, draws, MSAA resolve.
#include "passes.hpp"

#include "errors.hpp"
#include "pipelines.hpp"

#include <cstring>
#include <vector>

namespace vkref::detail {
namespace {

using softraster::Status;

constexpr VkPipelineStageFlags2 kDepthStages =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
// A depth resolve writes in the colour-attachment-output stage.
constexpr VkPipelineStageFlags2 kDepthWriteStages = kDepthStages | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
constexpr VkAccessFlags2 kDepthWriteAccess =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;

// Every image to its attachment layout. From UNDEFINED: the old contents (of an earlier
// submission) are discarded, as the clear replaces them anyway.
void toAttachments(VkCommandBuffer cmd, const Targets& t) {
  std::vector<VkImageMemoryBarrier2> barriers;
  std::vector<const Image*> colourImages = {&t.colour, &t.msColour};
  for (const ColourTarget& more : t.moreColour) {
    colourImages.push_back(&more.image);
    colourImages.push_back(&more.msImage);
  }
  for (const Image* image : colourImages) {
    if (*image)
      barriers.push_back(imageBarrier(image->handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_NONE,
                                      VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                                      VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
  }
  for (const Image* image : {&t.depth, &t.msDepth}) {
    if (*image)
      barriers.push_back(imageBarrier(image->handle(), depthAspects(t.depthFormat), VK_PIPELINE_STAGE_2_NONE,
                                      VK_ACCESS_2_NONE, kDepthWriteStages,
                                      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | kDepthWriteAccess,
                                      VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL));
  }
  barrier(cmd, barriers);
}

// Clears, then with MSAA resolves at the end: colour averaged, depth (and stencil) from sample 0.
// Every colour attachment is cleared to its own colour (given as floats: Vulkan converts them to
// the attachment's format) and resolved alike; colour attachment i is fragment output location i.
// A depth/stencil format is also the stencil attachment (the same view), cleared to clearStencil.
void beginRendering(VkCommandBuffer cmd, const FramePass& pass) {
  const Targets& t = *pass.targets;
  const bool ms = t.multisampled();
  const auto attachment = [&](const Image& single, const Image& multi, const std::array<float, 4>& c) {
    return VkRenderingAttachmentInfo{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                     .imageView = ms ? multi.view() : single.view(),
                                     .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                     .resolveMode = ms ? VK_RESOLVE_MODE_AVERAGE_BIT : VK_RESOLVE_MODE_NONE,
                                     .resolveImageView = ms ? single.view() : VK_NULL_HANDLE,
                                     .resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                     .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                     .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                     .clearValue = {.color = {.float32 = {c[0], c[1], c[2], c[3]}}}};
  };
  std::vector<VkRenderingAttachmentInfo> colour;
  colour.push_back(attachment(t.colour, t.msColour, pass.clearColour));
  for (std::size_t i = 0; i < t.moreColour.size(); ++i)
    colour.push_back(attachment(t.moreColour[i].image, t.moreColour[i].msImage, pass.moreColour[i].clearColour));
  const VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = ms ? t.msDepth.view() : t.depth.view(),
                                        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                        .resolveMode = ms ? VK_RESOLVE_MODE_SAMPLE_ZERO_BIT : VK_RESOLVE_MODE_NONE,
                                        .resolveImageView = ms ? t.depth.view() : VK_NULL_HANDLE,
                                        .resolveImageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .clearValue = {.depthStencil = {pass.clearDepth, pass.clearStencil}}};
  const VkRenderingInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                             .renderArea = {{0, 0}, {t.width, t.height}},
                             .layerCount = 1,
                             .colorAttachmentCount = static_cast<std::uint32_t>(colour.size()),
                             .pColorAttachments = colour.data(),
                             .pDepthAttachment = &depth,
                             .pStencilAttachment = t.hasStencil() ? &depth : nullptr};
  vkCmdBeginRendering(cmd, &info);
}

// The draws in order. A pipeline, push constants or uniform block equal to the previous draw's
// are not bound again (bound state persists across draws, and all pipelines share one layout).
void recordDraws(VkCommandBuffer cmd, const FramePass& pass, std::span<const PassDraw> draws) {
  if (pass.indices) vkCmdBindIndexBuffer(cmd, pass.indices, 0, VK_INDEX_TYPE_UINT32);
  VkPipeline bound = VK_NULL_HANDLE;
  std::span<const std::byte> pushed;
  bool uniformsBound = false;
  std::uint32_t boundOffset = 0;
  VkDescriptorSet boundTextures = VK_NULL_HANDLE;
  for (const PassDraw& d : draws) {
    if (d.pipeline != bound) {
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
      bound = d.pipeline;
    }
    if (d.bindVertices) vkCmdBindVertexBuffers(cmd, 0, 1, &pass.vertices, &d.vertexOffset);
    if (!d.pushConstants.empty() &&
        !(d.pushConstants.size() == pushed.size() &&
          std::memcmp(d.pushConstants.data(), pushed.data(), pushed.size()) == 0)) {
      vkCmdPushConstants(cmd, pass.layout, kPushConstantStages, 0, static_cast<std::uint32_t>(d.pushConstants.size()),
                         d.pushConstants.data());
      pushed = d.pushConstants;
    }
    if (d.bindUniforms && !(uniformsBound && boundOffset == d.uniformOffset)) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.layout, 0, 1, &pass.uniforms, 1,
                              &d.uniformOffset);
      uniformsBound = true;
      boundOffset = d.uniformOffset;
    }
    if (d.textures != VK_NULL_HANDLE && d.textures != boundTextures) {
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pass.layout, 1, 1, &d.textures, 0, nullptr);
      boundTextures = d.textures;
    }
    if (d.indexed)
      vkCmdDrawIndexed(cmd, d.count, 1, d.firstIndex, 0, 0);
    else
      vkCmdDraw(cmd, d.count, 1, 0, 0);
  }
}

// One depth pass: its image to the attachment layout (old contents discarded), depth cleared and
// drawn with no colour attachment, then to SHADER_READ_ONLY_OPTIMAL with its writes made visible
// to the fragment shaders' sampled reads of the passes and the frame that follow.
void recordDepthPass(VkCommandBuffer cmd, const FramePass& frame, const DepthPassRecord& pass) {
  const VkImageMemoryBarrier2 toAttachment =
      imageBarrier(pass.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, kDepthStages,
                   VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                   VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
  barrier(cmd, std::span(&toAttachment, 1));
  const VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                        .imageView = pass.view,
                                        .imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                        .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                        .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                        .clearValue = {.depthStencil = {pass.clearDepth, 0}}};
  const VkRenderingInfo info{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                             .renderArea = {{0, 0}, {pass.width, pass.height}},
                             .layerCount = 1,
                             .colorAttachmentCount = 0,
                             .pDepthAttachment = &depth};
  vkCmdBeginRendering(cmd, &info);
  recordDraws(cmd, frame, pass.draws);
  vkCmdEndRendering(cmd);
  const VkImageMemoryBarrier2 toSampled = imageBarrier(
      pass.image, VK_IMAGE_ASPECT_DEPTH_BIT, kDepthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
      VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
      VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  barrier(cmd, std::span(&toSampled, 1));
}

// The single-sample images (rendered to, or resolved into) ready to be copied out.
void toTransferSource(VkCommandBuffer cmd, const Targets& t) {
  const auto colour = [](const Image& image) {
    return imageBarrier(image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
                        VK_ACCESS_2_TRANSFER_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
  };
  std::vector<VkImageMemoryBarrier2> barriers = {
      colour(t.colour),
      imageBarrier(t.depth.handle(), depthAspects(t.depthFormat), kDepthWriteStages, kDepthWriteAccess,
                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)};
  for (const ColourTarget& more : t.moreColour) barriers.push_back(colour(more.image));
  barrier(cmd, barriers);
}

}  // namespace

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
                                   VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                                   VkImageLayout from, VkImageLayout to, std::uint32_t levels) {
  return {.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
          .srcStageMask = srcStage,
          .srcAccessMask = srcAccess,
          .dstStageMask = dstStage,
          .dstAccessMask = dstAccess,
          .oldLayout = from,
          .newLayout = to,
          .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
          .image = image,
          .subresourceRange = {aspect, 0, levels, 0, 1}};
}

void barrier(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images, const VkMemoryBarrier2* memory) {
  const VkDependencyInfo info{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                              .memoryBarrierCount = memory ? 1u : 0u,
                              .pMemoryBarriers = memory,
                              .imageMemoryBarrierCount = static_cast<std::uint32_t>(images.size()),
                              .pImageMemoryBarriers = images.data()};
  vkCmdPipelineBarrier2(cmd, &info);
}

Status recordRenderPass(VkCommandBuffer cmd, const FramePass& pass) {
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  if (Status s = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"); !s) return s;
  for (const DepthPassRecord& depthPass : pass.depthPasses) recordDepthPass(cmd, pass, depthPass);
  toAttachments(cmd, *pass.targets);
  beginRendering(cmd, pass);
  recordDraws(cmd, pass, pass.draws);
  vkCmdEndRendering(cmd);  // the MSAA resolve happens here
  toTransferSource(cmd, *pass.targets);
  return check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

// ---- Commands ----------------------------------------------------------------------------------

softraster::Result<std::unique_ptr<Commands>> Commands::create(const Device& device) {
  std::unique_ptr<Commands> c(new Commands(device));
  const VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                         .queueFamilyIndex = device.queueFamily};
  if (Status s = check(vkCreateCommandPool(c->device_, &poolInfo, nullptr, &c->pool_), "vkCreateCommandPool"); !s)
    return s;
  const VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = c->pool_,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = static_cast<std::uint32_t>(c->buffers_.size())};
  if (Status s = check(vkAllocateCommandBuffers(c->device_, &allocInfo, c->buffers_.data()), "vkAllocateCommandBuffers");
      !s)
    return s;
  const VkFenceCreateInfo fenceInfo{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (Status s = check(vkCreateFence(c->device_, &fenceInfo, nullptr, &c->fence_), "vkCreateFence"); !s) return s;
  return c;
}

Commands::~Commands() {
  if (pending_) vkQueueWaitIdle(queue_);
  vkDestroyFence(device_, fence_, nullptr);
  vkDestroyCommandPool(device_, pool_, nullptr);  // frees the command buffers
}

Status Commands::submitAndWait(VkCommandBuffer cmd) {
  if (Status s = check(vkResetFences(device_, 1, &fence_), "vkResetFences"); !s) return s;
  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
  if (Status s = check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit"); !s) return s;
  pending_ = true;
  if (Status s = check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences"); !s) return s;
  pending_ = false;
  return {};
}

}  // namespace vkref::detail
