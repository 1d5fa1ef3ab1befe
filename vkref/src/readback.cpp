// vkref readback (see readback.hpp): copies to host buffers and depth unpacking.
#include "readback.hpp"

#include "errors.hpp"
#include "passes.hpp"

#include <array>
#include <cstring>
#include <utility>
#include <vector>

namespace vkref::detail {
namespace {

using softraster::Status;

// Bytes per depth texel as copied out, indexed by softraster::DepthFormat: D16 as 16-bit
// integers, X8_D24 (and D24_UNORM_S8_UINT's depth aspect) as 32-bit words with the depth in the
// low 24 bits, D32_SFLOAT (and D32_SFLOAT_S8_UINT's depth aspect) as floats. A stencil aspect is
// copied out as one byte per texel.
constexpr std::uint32_t kDepthTexelBytes[] = {2, 4, 4, 4, 4};

std::uint32_t depthTexelBytes(softraster::DepthFormat format) {
  return kDepthTexelBytes[static_cast<std::size_t>(format)];
}

}  // namespace

softraster::Result<HostImages> createHostImages(const Device& device, const Targets& targets,
                                                softraster::ColourFormat colourFormat,
                                                std::span<const softraster::ColourFormat> moreColourFormats,
                                                softraster::DepthFormat depthFormat) {
  HostImages host;
  host.colourFormat = colourFormat;
  host.depthFormat = depthFormat;
  const VkDeviceSize pixels = VkDeviceSize{targets.width} * targets.height;
  auto colour = Buffer::create(device, pixels * softraster::colourBytes(colourFormat), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!colour) return colour.status();
  host.colour = std::move(*colour);
  host.moreColourFormats.assign(moreColourFormats.begin(), moreColourFormats.end());
  for (softraster::ColourFormat format : moreColourFormats) {
    auto more = Buffer::create(device, pixels * softraster::colourBytes(format), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (!more) return more.status();
    host.moreColour.push_back(std::move(*more));
  }
  auto depth = Buffer::create(device, pixels * depthTexelBytes(depthFormat), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  if (!depth) return depth.status();
  host.depth = std::move(*depth);
  if (targets.hasStencil()) {
    auto stencil = Buffer::create(device, pixels, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
    if (!stencil) return stencil.status();
    host.stencil = std::move(*stencil);
  }
  return host;
}

Status recordCopies(VkCommandBuffer cmd, const Targets& targets, const HostImages& host, const FrameSamples* samples) {
  const VkCommandBufferBeginInfo begin{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  if (Status s = check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer"); !s) return s;
  const VkExtent3D extent{targets.width, targets.height, 1};
  const VkBufferImageCopy colourRegion{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, .imageExtent = extent};
  const VkBufferImageCopy depthRegion{.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1}, .imageExtent = extent};
  vkCmdCopyImageToBuffer(cmd, targets.colour.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.colour.handle(), 1,
                         &colourRegion);
  for (std::size_t i = 0; i < targets.moreColour.size(); ++i)
    vkCmdCopyImageToBuffer(cmd, targets.moreColour[i].image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           host.moreColour[i].handle(), 1, &colourRegion);
  vkCmdCopyImageToBuffer(cmd, targets.depth.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.depth.handle(), 1,
                         &depthRegion);
  if (targets.hasStencil()) {
    const VkBufferImageCopy stencilRegion{.imageSubresource = {VK_IMAGE_ASPECT_STENCIL_BIT, 0, 0, 1}, .imageExtent = extent};
    vkCmdCopyImageToBuffer(cmd, targets.depth.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, host.stencil.handle(), 1,
                           &stencilRegion);
  }
  const VkMemoryBarrier2 toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
  barrier(cmd, {}, &toHost);
  if (samples) samples->record(cmd);
  return check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

FrameImages unpack(const HostImages& host, std::uint32_t width, std::uint32_t height) {
  FrameImages out;
  const std::size_t pixels = std::size_t{width} * height;
  out.width = width;
  out.height = height;
  colourFromStorage(host.colourFormat, host.colour.mapped(), pixels, out.rgba, out.colourWords);
  out.moreColour.resize(host.moreColour.size());
  for (std::size_t i = 0; i < host.moreColour.size(); ++i)
    colourFromStorage(host.moreColourFormats[i], host.moreColour[i].mapped(), pixels, out.moreColour[i].rgba,
                      out.moreColour[i].colourWords);
  out.depth.resize(pixels);
  out.depthStorage.resize(pixels);
  const std::uint32_t texelBytes = depthTexelBytes(host.depthFormat);
  const auto* texels = static_cast<const std::uint8_t*>(host.depth.mapped());
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint32_t stored = 0;
    std::memcpy(&stored, texels + i * texelBytes, texelBytes);
    switch (softraster::depthAspect(host.depthFormat)) {
      case softraster::DepthFormat::D16Unorm: out.depth[i] = static_cast<float>(stored / 65535.0); break;
      case softraster::DepthFormat::X8D24UnormPack32:
        stored &= 0xffffffu;
        out.depth[i] = static_cast<float>(stored / 16777215.0);
        break;
      case softraster::DepthFormat::D32Sfloat: std::memcpy(&out.depth[i], &stored, 4); break;
      default: break;  // depthAspect gives one of the three
    }
    out.depthStorage[i] = stored;
  }
  if (host.stencil.handle() != VK_NULL_HANDLE) {
    out.stencil.resize(pixels);
    std::memcpy(out.stencil.data(), host.stencil.mapped(), pixels);
  }
  return out;
}

void colourFromStorage(softraster::ColourFormat format, const void* texels, std::size_t count,
                       std::vector<std::uint8_t>& rgba, std::vector<std::uint32_t>& words) {
  const std::size_t bytes = softraster::colourBytes(format);
  const auto* in = static_cast<const std::uint8_t*>(texels);
  rgba.resize(4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::array<std::uint8_t, 4> view = softraster::Framebuffer::viewBytes(format, in + bytes * i);
    std::memcpy(&rgba[4 * i], view.data(), 4);
  }
  words.clear();
  if (count > 0 && (softraster::isTenBit(format) || softraster::isFloat(format))) {
    words.resize(count * bytes / 4);
    std::memcpy(words.data(), in, count * bytes);
  }
}

}  // namespace vkref::detail
