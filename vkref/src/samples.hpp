// vkref samples: every sample of a multisampled frame read back, not only the resolve. Vulkan
// copies no multisampled image to a buffer (vkCmdCopyImageToBuffer: "srcImage must have a sample
// count equal to VK_SAMPLE_COUNT_1_BIT"), so a compute shader (vkref/shaders/read_samples.comp)
// fetches each sample of the colour, depth and stencil images with texelFetch and writes them
// into one host-visible storage buffer, in softraster's order (a pixel's samples adjacent, in
// Vulkan's sample order). Colour attachments after the first are read by a colour-only variant
// of the shader, dispatched once per attachment into a storage buffer of its own (the colour
// words alone, laid out as the first's). Recorded into the frame's copy command buffer, so it
// runs in readBack() and never in the timed submit().
// Deliberately no resolve and no single-sample path (frames with one sample need none of this),
// and no conversion of colour: every colour format is fetched as its bits, through an unsigned
// integer view of its texel's size (device.hpp's colourBitsFormat), and unpacked on the host as
// the resolve is (readback.hpp's colourFromStorage); depth in the five depth formats. The UNORM
// depth a sampled view returns as float(c) * float(1/(2^n - 1)) is turned back into c on the host;
// that float is one-to-one but for D24's 16777214 and 16777215 (both 1.0), read as 16777215 in
// samples 1..3 (sample 0 is the resolve's exact value).
#pragma once

#include "device.hpp"
#include "resources.hpp"

#include <vkref/frame.hpp>

#include <softraster/formats.hpp>
#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <memory>
#include <span>
#include <vector>

namespace vkref::detail {

// The compute pipelines (one for depth formats, one that also reads stencil, one that reads
// colour alone), their set layouts and pipeline layouts. One per Renderer, made when its first
// multisampled frame is prepared.
class SampleReader {
 public:
  static softraster::Result<std::unique_ptr<SampleReader>> create(const Device& device);
  ~SampleReader();
  SampleReader(const SampleReader&) = delete;
  SampleReader& operator=(const SampleReader&) = delete;

  struct Variant {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
  };
  const Variant& variant(bool stencil) const { return variants_[stencil ? 1 : 0]; }
  const Variant& colourOnly() const { return variants_[2]; }  // colour attachments after the first

 private:
  explicit SampleReader(VkDevice device) : device_(device) {}
  VkDevice device_;
  Variant variants_[3];
};

// One multisampled frame's share: views of its multisampled images, the storage buffers the
// samples land in (one, and one more per colour attachment after the first), and the descriptor
// sets that bind them.
class FrameSamples {
 public:
  static softraster::Result<std::unique_ptr<FrameSamples>> create(const Device& device, const SampleReader& reader,
                                                                  const Targets& targets);
  ~FrameSamples();
  FrameSamples(const FrameSamples&) = delete;
  FrameSamples& operator=(const FrameSamples&) = delete;

  // Records, after the render pass's submission: the multisampled images to
  // SHADER_READ_ONLY_OPTIMAL, the dispatches, the images back to their attachment layouts (so the
  // frame may be read again before it is submitted again) and the barrier that makes the buffer
  // visible to the host.
  void record(VkCommandBuffer cmd) const;
  // Fills out's samples, sampleRgba, sampleDepth, sampleDepthStorage and sampleStencil, and each
  // out.moreColour[i]'s sampleRgba and sampleColourWords (out.moreColour already holds one entry
  // per attachment after the first, of moreColourFormats[i]), from the buffers after the commands
  // ran. An error when sample 0 of depth or stencil differs from the sample-0 resolve already in
  // `out` (the read-back would be wrong, not the renderer).
  softraster::Status unpack(FrameImages& out, softraster::ColourFormat colourFormat,
                            std::span<const softraster::ColourFormat> moreColourFormats,
                            softraster::DepthFormat format) const;

 private:
  FrameSamples(VkDevice device, const SampleReader& reader, const Targets& targets)
      : device_(device), variant_(reader.variant(targets.hasStencil())), colourOnly_(reader.colourOnly()),
        targets_(targets) {}
  VkDevice device_;
  const SampleReader::Variant& variant_;
  const SampleReader::Variant& colourOnly_;
  const Targets& targets_;
  VkImageView depthView_ = VK_NULL_HANDLE, stencilView_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  Buffer buffer_;
  std::vector<VkDescriptorSet> moreSets_;  // per colour attachment after the first: colourOnly_'s set...
  std::vector<Buffer> moreBuffers_;        // ...and the buffer its samples land in
};

}  // namespace vkref::detail
