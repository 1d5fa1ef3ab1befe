// vkref readback: the copies of a frame's single-sample colour (every attachment's) and depth
// images into host buffers, and their unpacking into FrameImages: colour as RGBA8 bytes (and, for
// the 10-bit and float formats, their stored words; attachments after the first in
// FrameImages::moreColour), depth as floats in [0, 1] and
// as stored (D16 and X8_D24 as UNORM integers, D32_SFLOAT as the float's bits; a depth/stencil
// format's depth aspect as its depth-only twin's) and the stencil aspect as bytes.
// Deliberately no resolve (passes resolves MSAA while rendering; samples.hpp reads the samples), no layout changes (passes leaves
// the images ready to copy) and no format conversion beyond depth's and colour's byte view
// (B8G8R8A8 is read back with red and blue swapped into R, G, B, A; wider formats as
// softraster::Framebuffer::viewBytes shows them).
#pragma once

#include "device.hpp"
#include "resources.hpp"
#include "samples.hpp"

#include <vkref/frame.hpp>

#include <softraster/framebuffer.hpp>
#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <span>
#include <vector>

namespace vkref::detail {

// Where a frame's images are copied to: tightly packed rows, row 0 at the top.
struct HostImages {
  softraster::ColourFormat colourFormat = softraster::ColourFormat::R8G8B8A8Unorm;
  softraster::DepthFormat depthFormat = softraster::DepthFormat::D32Sfloat;
  Buffer colour, depth;
  Buffer stencil;  // with a depth/stencil format: one byte per pixel
  // Colour attachments 1.. (Targets::moreColour): their formats and buffers, in order.
  std::vector<softraster::ColourFormat> moreColourFormats;
  std::vector<Buffer> moreColour;
};

// `moreColourFormats`: the formats of targets.moreColour, in order.
softraster::Result<HostImages> createHostImages(const Device& device, const Targets& targets,
                                                softraster::ColourFormat colourFormat,
                                                std::span<const softraster::ColourFormat> moreColourFormats,
                                                softraster::DepthFormat depthFormat);

// Records the copies of `targets` (in TRANSFER_SRC_OPTIMAL layout) into `host`, and the barrier
// that makes them visible to the host, from vkBeginCommandBuffer to vkEndCommandBuffer.
// With `samples` (a multisampled frame) the per-sample read-back is recorded after the copies.
softraster::Status recordCopies(VkCommandBuffer cmd, const Targets& targets, const HostImages& host,
                                const FrameSamples* samples = nullptr);

// The images in `host` after the copies have run, colour as R, G, B, A bytes whatever the format.
FrameImages unpack(const HostImages& host, std::uint32_t width, std::uint32_t height);

// `count` stored colour texels of `format` (colourBytes each) as FrameImages holds them: `rgba`
// their R, G, B, A byte view, `words` the texels themselves for a format wider than 8 bits per
// channel (left empty for the 8-bit formats, whose view is exact).
void colourFromStorage(softraster::ColourFormat format, const void* texels, std::size_t count,
                       std::vector<std::uint8_t>& rgba, std::vector<std::uint32_t>& words);

}  // namespace vkref::detail
