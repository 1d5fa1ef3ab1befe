// vkref resources: buffers and images with their memory, the images a frame renders into, and
// the upload of a frame's vertices, indices and uniform blocks into one buffer each, and the
// descriptor set of its uniform blocks.
// Deliberately simple: buffers are host-visible, coherent and mapped for their whole life (on
// lavapipe all memory is host memory, so there are no staging copies), images are 2D with one
// layer (and one level, or a texture's chain), and every object has its own allocation (a frame
// has a handful of them, however many draws it holds), so there is no sub-allocator. No command
// is recorded here.
#pragma once

#include "device.hpp"

#include <vkref/frame.hpp>

#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <vector>

namespace vkref::detail {

// A host-visible, coherent buffer, mapped from creation to destruction. Move-only.
class Buffer {
 public:
  static softraster::Result<Buffer> create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage);
  Buffer() = default;  // no buffer
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  ~Buffer();

  VkBuffer handle() const { return buffer_; }
  void* mapped() const { return mapped_; }

 private:
  void destroy();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;
};

// An optimally tiled 2D image (device-local where the device has such memory) and a view of it.
// Move-only.
class Image {
 public:
  // `bitsFormat`, if given and not `format`: the image is created mutable and gets a second view
  // of that (compatible) format, bitsView(): e.g. a colour image read as R32_UINT, its bits unconverted.
  static softraster::Result<Image> create(const Device& device, VkFormat format, VkImageUsageFlags usage,
                                          VkImageAspectFlags aspect, std::uint32_t width, std::uint32_t height,
                                          VkSampleCountFlagBits samples, std::uint32_t levels = 1,
                                          VkFormat bitsFormat = VK_FORMAT_UNDEFINED);
  Image() = default;  // no image
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  ~Image();

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  VkImageView bitsView() const { return bitsView_ ? bitsView_ : view_; }
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

 private:
  void destroy();
  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
  VkImageView bitsView_ = VK_NULL_HANDLE;  // only with a bitsFormat
};

// A colour attachment after the first (FrameRequest::moreColour): made, resolved and read like
// the first (Targets' colour and msColour).
struct ColourTarget {
  VkFormat format = VK_FORMAT_UNDEFINED;
  Image image;    // single-sampled, copied out
  Image msImage;  // empty unless samples > 1
};

// The images one frame renders into. `colour` and `depth` are single-sampled and copied out;
// with MSAA the draws go to `msColour` and `msDepth`, which resolve into them and are also
// sampled by the per-sample read-back (samples.hpp). Colour attachments after the first are in
// `moreColour`, each with the same usage as the first.
struct Targets {
  std::uint32_t width = 0, height = 0;
  VkFormat colourFormat = VK_FORMAT_UNDEFINED;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  Image colour, depth;
  Image msColour, msDepth;  // empty unless samples > 1
  std::vector<ColourTarget> moreColour;  // attachments 1..

  bool multisampled() const { return samples != VK_SAMPLE_COUNT_1_BIT; }
  bool hasStencil() const { return (depthAspects(depthFormat) & VK_IMAGE_ASPECT_STENCIL_BIT) != 0; }
};

// `moreColourFormats`: the formats of colour attachments 1.., one ColourTarget each.
softraster::Result<Targets> createTargets(const Device& device, std::uint32_t width, std::uint32_t height,
                                          VkFormat colourFormat, std::span<const VkFormat> moreColourFormats,
                                          VkFormat depthFormat, VkSampleCountFlagBits samples);

// Every vertex, index and uniform block of a frame, in one vertex buffer, one index buffer and one
// uniform buffer (each empty when no draw has any), and where each draw's share begins.
struct Geometry {
  struct Range {
    VkDeviceSize vertexOffset = 0;   // bytes into `vertices`
    std::uint32_t firstIndex = 0;    // indices into `indices`
    std::uint32_t uniformOffset = 0;  // bytes into `uniforms`: the draw's dynamic offset
  };
  Buffer vertices, indices, uniforms;
  VkDeviceSize uniformRange = 0;  // bytes every draw's block is bound with (the largest block)
  std::vector<Range> ranges;      // one per draw uploaded, in the same order
};

// Uploads the vertex data of each draw whose program reads vertices, the indices of each indexed
// draw and each draw's uniform block (at offsets the device's alignment allows). Every draw must
// have a program.
softraster::Result<Geometry> uploadGeometry(const Device& device, std::span<const DrawCall* const> draws);

// The descriptor set that binds a frame's uniform buffer as a dynamic uniform buffer (set 0,
// binding 0; each draw picks its block by dynamic offset), with the pool it comes from. Move-only.
class UniformSet {
 public:
  // A set for `geometry.uniforms`, or an empty one when the frame has no uniform blocks.
  static softraster::Result<UniformSet> create(const Device& device, VkDescriptorSetLayout layout,
                                               const Geometry& geometry);
  UniformSet() = default;
  UniformSet(UniformSet&& other) noexcept;
  UniformSet& operator=(UniformSet&& other) noexcept;
  ~UniformSet();

  VkDescriptorSet handle() const { return set_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
};

}  // namespace vkref::detail
