// vkref samples (see samples.hpp): the per-sample read-back's pipelines, views, dispatch and
// unpacking.
#include "samples.hpp"

#include "errors.hpp"
#include "passes.hpp"
#include "readback.hpp"

#include <read_samples_colour_comp.spv.h>
#include <read_samples_comp.spv.h>
#include <read_samples_stencil_comp.spv.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <span>
#include <string>
#include <vector>

namespace vkref::detail {
namespace {

using softraster::Status;

constexpr std::uint32_t kGroupSize = 8;  // read_samples.comp's local size in x and y
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;

struct PushConstants {
  std::uint32_t width, height, samples;
  std::uint32_t colourWords;  // per sample: 1, 2 or 4
};

// Every stage the render pass wrote the multisampled images in (a depth resolve reads depth in
// the colour-attachment-output stage).
constexpr VkPipelineStageFlags2 kAttachmentStages = VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT |
                                                    VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT |
                                                    VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;

// The variant's bindings: colour 0, depth 1, stencil 2 (with `stencil`), the buffer 3; with
// `colourOnly` colour and the buffer alone.
Status createVariant(VkDevice device, std::span<const std::uint32_t> spirv, bool stencil, bool colourOnly,
                     SampleReader::Variant& v) {
  std::array<VkDescriptorSetLayoutBinding, 4> bindings{};
  std::uint32_t count = 0;
  for (std::uint32_t b : {0u, 1u, 2u, 3u}) {
    if ((b == 2 && !stencil) || ((b == 1 || b == 2) && colourOnly)) continue;
    bindings[count++] = {b, b == 3 ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : kSampled, 1, VK_SHADER_STAGE_COMPUTE_BIT,
                         nullptr};
  }
  const VkDescriptorSetLayoutCreateInfo setInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                .bindingCount = count,
                                                .pBindings = bindings.data()};
  if (Status s = check(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &v.setLayout), "vkCreateDescriptorSetLayout");
      !s)
    return s;
  const VkPushConstantRange push{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(PushConstants)};
  const VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                              .setLayoutCount = 1,
                                              .pSetLayouts = &v.setLayout,
                                              .pushConstantRangeCount = 1,
                                              .pPushConstantRanges = &push};
  if (Status s = check(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &v.layout), "vkCreatePipelineLayout"); !s)
    return s;
  const VkShaderModuleCreateInfo moduleInfo{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                            .codeSize = spirv.size() * sizeof(std::uint32_t),
                                            .pCode = spirv.data()};
  VkShaderModule module = VK_NULL_HANDLE;
  if (Status s = check(vkCreateShaderModule(device, &moduleInfo, nullptr, &module), "vkCreateShaderModule"); !s) return s;
  const VkComputePipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO,
                                         .stage = {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                                                   .stage = VK_SHADER_STAGE_COMPUTE_BIT,
                                                   .module = module,
                                                   .pName = "main"},
                                         .layout = v.layout};
  const Status s =
      check(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &v.pipeline), "vkCreateComputePipelines");
  vkDestroyShaderModule(device, module, nullptr);
  return s;
}

// A stored UNORM depth c as a sampled view returns it: float(c) * float(1 / (2^bits - 1))
// (llvmpipe's lp_build_unsigned_norm_to_float for widths up to 24 bits).
float sampledUnorm(std::uint32_t c, int bits) {
  const float scale = static_cast<float>(1.0 / ((1u << bits) - 1));
  return static_cast<float>(c) * scale;
}

// The stored c whose sampled value is exactly `value`, the largest where two share it, or the
// nearest to value * (2^bits - 1) when none has it. Distinct c give distinct floats but for one
// pair: 16777214 and 16777215 both read 1.0 with 24 bits (none with 16), so a D24 sample at
// 16777214 reads as 16777215; sample 0 is taken from the resolve (exact) instead (unpack).
std::uint32_t unormFromSampled(float value, int bits) {
  const std::int64_t maxValue = (std::int64_t{1} << bits) - 1;
  const auto nearest = static_cast<std::int64_t>(std::nearbyint(static_cast<double>(value) * static_cast<double>(maxValue)));
  for (std::int64_t c = nearest + 2; c >= nearest - 2; --c) {
    if (c < 0 || c > maxValue) continue;
    if (sampledUnorm(static_cast<std::uint32_t>(c), bits) == value) return static_cast<std::uint32_t>(c);
  }
  return static_cast<std::uint32_t>(std::clamp<std::int64_t>(nearest, 0, maxValue));
}

}  // namespace

softraster::Result<std::unique_ptr<SampleReader>> SampleReader::create(const Device& device) {
  std::unique_ptr<SampleReader> reader(new SampleReader(device.device));
  if (Status s = createVariant(device.device, read_samples_comp_spirv, false, false, reader->variants_[0]); !s) return s;
  if (Status s = createVariant(device.device, read_samples_stencil_comp_spirv, true, false, reader->variants_[1]); !s)
    return s;
  if (Status s = createVariant(device.device, read_samples_colour_comp_spirv, false, true, reader->variants_[2]); !s)
    return s;
  return reader;
}

SampleReader::~SampleReader() {
  for (const Variant& v : variants_) {
    vkDestroyPipeline(device_, v.pipeline, nullptr);
    vkDestroyPipelineLayout(device_, v.layout, nullptr);
    vkDestroyDescriptorSetLayout(device_, v.setLayout, nullptr);
  }
}

softraster::Result<std::unique_ptr<FrameSamples>> FrameSamples::create(const Device& device, const SampleReader& reader,
                                                                       const Targets& targets) {
  const bool stencil = targets.hasStencil();
  std::unique_ptr<FrameSamples> f(new FrameSamples(device.device, reader, targets));
  auto view = [&](VkImageAspectFlags aspect, VkImageView& out) {
    const VkImageViewCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                     .image = targets.msDepth.handle(),
                                     .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                     .format = targets.depthFormat,
                                     .subresourceRange = {aspect, 0, 1, 0, 1}};
    return check(vkCreateImageView(device.device, &info, nullptr, &out), "vkCreateImageView");
  };
  if (Status s = view(VK_IMAGE_ASPECT_DEPTH_BIT, f->depthView_); !s) return s;
  if (stencil) {
    if (Status s = view(VK_IMAGE_ASPECT_STENCIL_BIT, f->stencilView_); !s) return s;
  }
  const VkDeviceSize pixels = VkDeviceSize{targets.width} * targets.height;
  const VkDeviceSize samples = pixels * static_cast<VkDeviceSize>(targets.samples);
  auto buffer =
      Buffer::create(device, ((colourWords(targets.colourFormat) + 1) * samples + pixels) * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  if (!buffer) return buffer.status();
  f->buffer_ = std::move(*buffer);
  const auto more = static_cast<std::uint32_t>(targets.moreColour.size());
  for (const ColourTarget& target : targets.moreColour) {
    auto moreBuffer = Buffer::create(device, colourWords(target.format) * samples * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!moreBuffer) return moreBuffer.status();
    f->moreBuffers_.push_back(std::move(*moreBuffer));
  }

  const VkDescriptorPoolSize sizes[2] = {{kSampled, 3 + more}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1 + more}};
  const VkDescriptorPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                            .maxSets = 1 + more,
                                            .poolSizeCount = 2,
                                            .pPoolSizes = sizes};
  if (Status s = check(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &f->pool_), "vkCreateDescriptorPool"); !s)
    return s;
  const VkDescriptorSetAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                              .descriptorPool = f->pool_,
                                              .descriptorSetCount = 1,
                                              .pSetLayouts = &f->variant_.setLayout};
  if (Status s = check(vkAllocateDescriptorSets(device.device, &allocInfo, &f->set_), "vkAllocateDescriptorSets"); !s)
    return s;
  const VkDescriptorImageInfo images[3] = {
      {VK_NULL_HANDLE, targets.msColour.bitsView(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
      {VK_NULL_HANDLE, f->depthView_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
      {VK_NULL_HANDLE, f->stencilView_, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL}};
  const VkDescriptorBufferInfo bufferInfo{f->buffer_.handle(), 0, VK_WHOLE_SIZE};
  std::array<VkWriteDescriptorSet, 4> writes{};
  std::uint32_t count = 0;
  for (std::uint32_t b = 0; b < 3; ++b) {
    if (b == 2 && !stencil) continue;
    writes[count++] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                       .dstSet = f->set_,
                       .dstBinding = b,
                       .descriptorCount = 1,
                       .descriptorType = kSampled,
                       .pImageInfo = &images[b]};
  }
  writes[count++] = {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                     .dstSet = f->set_,
                     .dstBinding = 3,
                     .descriptorCount = 1,
                     .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                     .pBufferInfo = &bufferInfo};
  vkUpdateDescriptorSets(device.device, count, writes.data(), 0, nullptr);

  // Each colour attachment after the first: its multisampled image's bits and its own buffer.
  if (more > 0) {
    f->moreSets_.resize(more);
    const std::vector<VkDescriptorSetLayout> layouts(more, f->colourOnly_.setLayout);
    const VkDescriptorSetAllocateInfo moreInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                               .descriptorPool = f->pool_,
                                               .descriptorSetCount = more,
                                               .pSetLayouts = layouts.data()};
    if (Status s = check(vkAllocateDescriptorSets(device.device, &moreInfo, f->moreSets_.data()), "vkAllocateDescriptorSets");
        !s)
      return s;
  }
  for (std::uint32_t i = 0; i < more; ++i) {
    const VkDescriptorImageInfo image{VK_NULL_HANDLE, targets.moreColour[i].msImage.bitsView(),
                                      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    const VkDescriptorBufferInfo moreBuffer{f->moreBuffers_[i].handle(), 0, VK_WHOLE_SIZE};
    const VkWriteDescriptorSet moreWrites[2] = {{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                                 .dstSet = f->moreSets_[i],
                                                 .dstBinding = 0,
                                                 .descriptorCount = 1,
                                                 .descriptorType = kSampled,
                                                 .pImageInfo = &image},
                                                {.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                                 .dstSet = f->moreSets_[i],
                                                 .dstBinding = 3,
                                                 .descriptorCount = 1,
                                                 .descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER,
                                                 .pBufferInfo = &moreBuffer}};
    vkUpdateDescriptorSets(device.device, 2, moreWrites, 0, nullptr);
  }
  return f;
}

FrameSamples::~FrameSamples() {
  vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees the set
  vkDestroyImageView(device_, stencilView_, nullptr);
  vkDestroyImageView(device_, depthView_, nullptr);
}

void FrameSamples::record(VkCommandBuffer cmd) const {
  const Targets& t = targets_;
  const VkImageAspectFlags depth = depthAspects(t.depthFormat);
  constexpr VkAccessFlags2 kWrites =
      VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
  const auto colourToRead = [](const Image& image) {
    return imageBarrier(image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  };
  const auto colourBack = [](const Image& image) {
    return imageBarrier(image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                        VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  };
  std::vector<VkImageMemoryBarrier2> toRead = {
      colourToRead(t.msColour),
      imageBarrier(t.msDepth.handle(), depth, kAttachmentStages, kWrites, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                   VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)};
  for (const ColourTarget& more : t.moreColour) toRead.push_back(colourToRead(more.msImage));
  barrier(cmd, toRead);
  const std::uint32_t groupsX = (t.width + kGroupSize - 1) / kGroupSize, groupsY = (t.height + kGroupSize - 1) / kGroupSize;
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, variant_.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, variant_.layout, 0, 1, &set_, 0, nullptr);
  const PushConstants push{t.width, t.height, static_cast<std::uint32_t>(t.samples), colourWords(t.colourFormat)};
  vkCmdPushConstants(cmd, variant_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof push, &push);
  vkCmdDispatch(cmd, groupsX, groupsY, 1);
  if (!t.moreColour.empty()) vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, colourOnly_.pipeline);
  for (std::size_t i = 0; i < t.moreColour.size(); ++i) {
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, colourOnly_.layout, 0, 1, &moreSets_[i], 0, nullptr);
    const PushConstants morePush{t.width, t.height, static_cast<std::uint32_t>(t.samples),
                                 colourWords(t.moreColour[i].format)};
    vkCmdPushConstants(cmd, colourOnly_.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof morePush, &morePush);
    vkCmdDispatch(cmd, groupsX, groupsY, 1);
  }
  std::vector<VkImageMemoryBarrier2> back = {
      colourBack(t.msColour),
      imageBarrier(t.msDepth.handle(), depth, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE,
                   kAttachmentStages, kWrites, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL)};
  for (const ColourTarget& more : t.moreColour) back.push_back(colourBack(more.msImage));
  const VkMemoryBarrier2 toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                .srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                .srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                                .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
  barrier(cmd, back, &toHost);
}

Status FrameSamples::unpack(FrameImages& out, softraster::ColourFormat colourFormat,
                            std::span<const softraster::ColourFormat> moreColourFormats,
                            softraster::DepthFormat format) const {
  const Targets& t = targets_;
  const std::size_t samples = static_cast<std::size_t>(t.samples);
  const std::size_t pixels = std::size_t{t.width} * t.height;
  const std::size_t n = pixels * samples;
  const auto* words = static_cast<const std::uint32_t*>(buffer_.mapped());
  out.samples = static_cast<std::uint32_t>(samples);
  colourFromStorage(colourFormat, words, n, out.sampleRgba, out.sampleColourWords);
  for (std::size_t i = 0; i < moreBuffers_.size() && i < out.moreColour.size() && i < moreColourFormats.size(); ++i)
    colourFromStorage(moreColourFormats[i], moreBuffers_[i].mapped(), n, out.moreColour[i].sampleRgba,
                      out.moreColour[i].sampleColourWords);
  words += n * colourWords(t.colourFormat);  // depth and stencil follow the colour
  out.sampleDepth.resize(n);
  out.sampleDepthStorage.resize(n);
  const int bits = softraster::unormDepthBits(format);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t word = words[i];
    float value;
    std::memcpy(&value, &word, 4);
    const std::uint32_t stored = bits != 0 ? unormFromSampled(value, bits) : word;
    out.sampleDepthStorage[i] = stored;
    out.sampleDepth[i] = bits == 16   ? static_cast<float>(stored / 65535.0)
                         : bits == 24 ? static_cast<float>(stored / 16777215.0)
                                      : value;
  }
  if (t.hasStencil()) {
    out.sampleStencil.resize(n);
    for (std::size_t p = 0; p < pixels; ++p) {
      for (std::size_t s = 0; s < samples; ++s)
        out.sampleStencil[p * samples + s] = static_cast<std::uint8_t>(words[n + p] >> (8 * s));
    }
  }
  // Sample 0 of depth and stencil is also what the resolve copied out: they must agree (a UNORM
  // depth up to the one value two stored depths share, where the resolve's exact value is kept).
  for (std::size_t p = 0; p < pixels; ++p) {
    std::uint32_t& sample0 = out.sampleDepthStorage[p * samples];
    if (bits != 0 && sample0 != out.depthStorage[p] &&
        sampledUnorm(sample0, bits) == sampledUnorm(out.depthStorage[p], bits)) {
      sample0 = out.depthStorage[p];
      out.sampleDepth[p * samples] = out.depth[p];
    }
    const bool depthDiffers = out.sampleDepthStorage[p * samples] != out.depthStorage[p];
    const bool stencilDiffers = !out.stencil.empty() && out.sampleStencil[p * samples] != out.stencil[p];
    if (depthDiffers || stencilDiffers)
      return Status::error("per-sample read-back: sample 0 of pixel (" + std::to_string(p % t.width) + ", " +
                           std::to_string(p / t.width) + ") has " + (depthDiffers ? "depth " : "stencil ") +
                           std::to_string(depthDiffers ? out.sampleDepthStorage[p * samples] : out.sampleStencil[p * samples]) +
                           ", the resolve " +
                           std::to_string(depthDiffers ? out.depthStorage[p] : out.stencil[p]));
  }
  return {};
}

}  // namespace vkref::detail
