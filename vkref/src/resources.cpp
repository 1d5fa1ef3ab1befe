// vkref resources (see resources.hpp): buffers, images, memory and the frame's upload.
#include "resources.hpp"

#include "errors.hpp"

#include <algorithm>
#include <cstring>
#include <optional>
#include <utility>

namespace vkref::detail {
namespace {

using softraster::Status;

// Where each draw's vertices start: more than any vertex attribute's component needs.
constexpr VkDeviceSize kVertexAlignment = 16;

std::optional<std::uint32_t> findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t allowed,
                                            VkMemoryPropertyFlags wanted) {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  return std::nullopt;
}

// Memory of a type with the `wanted` properties, else of one with the `required` ones.
Status allocate(const Device& device, const VkMemoryRequirements& needs, VkMemoryPropertyFlags wanted,
                VkMemoryPropertyFlags required, VkDeviceMemory* out) {
  std::optional<std::uint32_t> type = findMemoryType(device.memory, needs.memoryTypeBits, wanted);
  if (!type) type = findMemoryType(device.memory, needs.memoryTypeBits, required);
  if (!type) return Status::error("no suitable Vulkan memory type");
  const VkMemoryAllocateInfo info{
      .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = needs.size, .memoryTypeIndex = *type};
  return check(vkAllocateMemory(device.device, &info, nullptr, out), "vkAllocateMemory");
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) { return (value + alignment - 1) / alignment * alignment; }

}  // namespace

// ---- Buffer ------------------------------------------------------------------------------------

softraster::Result<Buffer> Buffer::create(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  b.device_ = device.device;
  const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                .size = size,
                                .usage = usage,
                                .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
  if (Status s = check(vkCreateBuffer(device.device, &info, nullptr, &b.buffer_), "vkCreateBuffer"); !s) return s;
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(device.device, b.buffer_, &needs);
  constexpr VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  if (Status s = allocate(device, needs, host, host, &b.memory_); !s) return s;
  if (Status s = check(vkBindBufferMemory(device.device, b.buffer_, b.memory_, 0), "vkBindBufferMemory"); !s) return s;
  if (Status s = check(vkMapMemory(device.device, b.memory_, 0, VK_WHOLE_SIZE, 0, &b.mapped_), "vkMapMemory"); !s)
    return s;
  return b;
}

Buffer::Buffer(Buffer&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      mapped_(std::exchange(other.mapped_, nullptr)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    destroy();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

Buffer::~Buffer() { destroy(); }

void Buffer::destroy() {
  if (!device_) return;
  vkDestroyBuffer(device_, buffer_, nullptr);  // destroying a null handle is a no-op
  vkFreeMemory(device_, memory_, nullptr);     // also unmaps
  device_ = VK_NULL_HANDLE;
}

// ---- Image -------------------------------------------------------------------------------------

softraster::Result<Image> Image::create(const Device& device, VkFormat format, VkImageUsageFlags usage,
                                        VkImageAspectFlags aspect, std::uint32_t width, std::uint32_t height,
                                        VkSampleCountFlagBits samples, std::uint32_t levels, VkFormat bitsFormat) {
  Image i;
  i.device_ = device.device;
  const bool twoViews = bitsFormat != VK_FORMAT_UNDEFINED && bitsFormat != format;
  const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                               .flags = twoViews ? VkImageCreateFlags{VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT} : 0u,
                               .imageType = VK_IMAGE_TYPE_2D,
                               .format = format,
                               .extent = {width, height, 1},
                               .mipLevels = levels,
                               .arrayLayers = 1,
                               .samples = samples,
                               .tiling = VK_IMAGE_TILING_OPTIMAL,
                               .usage = usage,
                               .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                               .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
  if (Status s = check(vkCreateImage(device.device, &info, nullptr, &i.image_), "vkCreateImage"); !s) return s;
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(device.device, i.image_, &needs);
  if (Status s = allocate(device, needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &i.memory_); !s) return s;
  if (Status s = check(vkBindImageMemory(device.device, i.image_, i.memory_, 0), "vkBindImageMemory"); !s) return s;
  const VkImageViewCreateInfo viewInfo{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                       .image = i.image_,
                                       .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                       .format = format,
                                       .subresourceRange = {aspect, 0, levels, 0, 1}};
  if (Status s = check(vkCreateImageView(device.device, &viewInfo, nullptr, &i.view_), "vkCreateImageView"); !s)
    return s;
  if (twoViews) {
    VkImageViewCreateInfo bitsInfo = viewInfo;
    bitsInfo.format = bitsFormat;
    if (Status s = check(vkCreateImageView(device.device, &bitsInfo, nullptr, &i.bitsView_), "vkCreateImageView"); !s)
      return s;
  }
  return i;
}

Image::Image(Image&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      image_(std::exchange(other.image_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      view_(std::exchange(other.view_, VK_NULL_HANDLE)),
      bitsView_(std::exchange(other.bitsView_, VK_NULL_HANDLE)) {}

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    destroy();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
    bitsView_ = std::exchange(other.bitsView_, VK_NULL_HANDLE);
  }
  return *this;
}

Image::~Image() { destroy(); }

void Image::destroy() {
  if (!device_) return;
  vkDestroyImageView(device_, view_, nullptr);
  if (bitsView_) vkDestroyImageView(device_, bitsView_, nullptr);
  vkDestroyImage(device_, image_, nullptr);
  vkFreeMemory(device_, memory_, nullptr);
  device_ = VK_NULL_HANDLE;
}

// ---- A frame's images and geometry -------------------------------------------------------------

softraster::Result<Targets> createTargets(const Device& device, std::uint32_t width, std::uint32_t height,
                                          VkFormat colourFormat, std::span<const VkFormat> moreColourFormats,
                                          VkFormat depthFormat, VkSampleCountFlagBits samples) {
  Targets t;
  t.width = width;
  t.height = height;
  t.colourFormat = colourFormat;
  t.depthFormat = depthFormat;
  t.samples = samples;
  constexpr VkImageUsageFlags colourUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  constexpr VkImageUsageFlags depthUsage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
  // A colour attachment's single-sample image (rendered to or resolved into, then copied out) and,
  // with MSAA, its multisampled one, sampled too: the per-sample read-back (samples.hpp) fetches
  // every sample in a compute shader. Every colour format is read through an unsigned integer
  // view of its texel's size: its stored bits, not their decoded values.
  const auto colourImages = [&](VkFormat format, Image& single, Image& multi) -> Status {
    auto image = Image::create(device, format, colourUsage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT,
                               width, height, VK_SAMPLE_COUNT_1_BIT);
    if (!image) return image.status();
    single = std::move(*image);
    if (!t.multisampled()) return {};
    auto ms = Image::create(device, format, colourUsage | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_COLOR_BIT, width,
                            height, samples, 1, colourBitsFormat(format));
    if (!ms) return ms.status();
    multi = std::move(*ms);
    return {};
  };
  if (Status s = colourImages(colourFormat, t.colour, t.msColour); !s) return s;
  t.moreColour.resize(moreColourFormats.size());
  for (std::size_t i = 0; i < moreColourFormats.size(); ++i) {
    t.moreColour[i].format = moreColourFormats[i];
    if (Status s = colourImages(moreColourFormats[i], t.moreColour[i].image, t.moreColour[i].msImage); !s) return s;
  }
  auto depth = Image::create(device, depthFormat, depthUsage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             depthAspects(depthFormat), width, height, VK_SAMPLE_COUNT_1_BIT);
  if (!depth) return depth.status();
  t.depth = std::move(*depth);
  if (t.multisampled()) {
    // Sampled too, for the per-sample read-back.
    auto msDepth = Image::create(device, depthFormat, depthUsage | VK_IMAGE_USAGE_SAMPLED_BIT, depthAspects(depthFormat),
                                 width, height, samples);
    if (!msDepth) return msDepth.status();
    t.msDepth = std::move(*msDepth);
  }
  return t;
}

softraster::Result<Geometry> uploadGeometry(const Device& device, std::span<const DrawCall* const> draws) {
  Geometry g;
  g.ranges.resize(draws.size());
  // Lay the draws out first, so each buffer is allocated once.
  VkDeviceSize vertexBytes = 0, uniformBytes = 0, lastUniformOffset = 0;
  std::size_t indexCount = 0;
  for (const DrawCall* d : draws) g.uniformRange = std::max<VkDeviceSize>(g.uniformRange, d->uniformData.size());
  const VkDeviceSize uniformAlignment = std::max<VkDeviceSize>(device.limits.minUniformBufferOffsetAlignment, 16);
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const DrawCall& d = *draws[i];
    if (!d.uniformData.empty()) {
      uniformBytes = alignUp(uniformBytes, uniformAlignment);
      g.ranges[i].uniformOffset = static_cast<std::uint32_t>(uniformBytes);
      lastUniformOffset = uniformBytes;
      uniformBytes += d.uniformData.size();
    }
    if (!d.program->attributes.empty()) {
      vertexBytes = alignUp(vertexBytes, kVertexAlignment);
      g.ranges[i].vertexOffset = vertexBytes;
      vertexBytes += d.vertexData.size();
    }
    if (d.indexed) {
      g.ranges[i].firstIndex = static_cast<std::uint32_t>(indexCount);
      indexCount += d.indices.size();
    }
  }
  if (vertexBytes > 0) {
    auto vertices = Buffer::create(device, vertexBytes, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    if (!vertices) return vertices.status();
    g.vertices = std::move(*vertices);
  }
  if (indexCount > 0) {
    auto indices = Buffer::create(device, indexCount * sizeof(std::uint32_t), VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    if (!indices) return indices.status();
    g.indices = std::move(*indices);
  }
  if (g.uniformRange > 0) {
    // Every block is bound with the same range, so the last one is followed by padding up to it.
    auto uniforms = Buffer::create(device, lastUniformOffset + g.uniformRange,
                                   VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    if (!uniforms) return uniforms.status();
    g.uniforms = std::move(*uniforms);
  }
  auto* uniformBase = static_cast<std::byte*>(g.uniforms.mapped());
  auto* vertexBase = static_cast<std::byte*>(g.vertices.mapped());
  auto* indexBase = static_cast<std::uint32_t*>(g.indices.mapped());
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const DrawCall& d = *draws[i];
    if (!d.program->attributes.empty() && !d.vertexData.empty())
      std::memcpy(vertexBase + g.ranges[i].vertexOffset, d.vertexData.data(), d.vertexData.size());
    if (d.indexed && !d.indices.empty())
      std::memcpy(indexBase + g.ranges[i].firstIndex, d.indices.data(), d.indices.size() * sizeof(std::uint32_t));
    if (!d.uniformData.empty())
      std::memcpy(uniformBase + g.ranges[i].uniformOffset, d.uniformData.data(), d.uniformData.size());
  }
  return g;
}

// ---- UniformSet --------------------------------------------------------------------------------

softraster::Result<UniformSet> UniformSet::create(const Device& device, VkDescriptorSetLayout layout,
                                                  const Geometry& geometry) {
  UniformSet u;
  if (geometry.uniformRange == 0) return u;
  u.device_ = device.device;
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1};
  const VkDescriptorPoolCreateInfo poolInfo{
      .sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, .maxSets = 1, .poolSizeCount = 1, .pPoolSizes = &size};
  if (Status s = check(vkCreateDescriptorPool(device.device, &poolInfo, nullptr, &u.pool_), "vkCreateDescriptorPool");
      !s)
    return s;
  const VkDescriptorSetAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                              .descriptorPool = u.pool_,
                                              .descriptorSetCount = 1,
                                              .pSetLayouts = &layout};
  if (Status s = check(vkAllocateDescriptorSets(device.device, &allocInfo, &u.set_), "vkAllocateDescriptorSets"); !s)
    return s;
  const VkDescriptorBufferInfo buffer{geometry.uniforms.handle(), 0, geometry.uniformRange};
  const VkWriteDescriptorSet write{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                                   .dstSet = u.set_,
                                   .dstBinding = 0,
                                   .descriptorCount = 1,
                                   .descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC,
                                   .pBufferInfo = &buffer};
  vkUpdateDescriptorSets(device.device, 1, &write, 0, nullptr);
  return u;
}

UniformSet::UniformSet(UniformSet&& other) noexcept
    : device_(std::exchange(other.device_, VK_NULL_HANDLE)),
      pool_(std::exchange(other.pool_, VK_NULL_HANDLE)),
      set_(std::exchange(other.set_, VK_NULL_HANDLE)) {}

UniformSet& UniformSet::operator=(UniformSet&& other) noexcept {
  if (this != &other) {
    if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    set_ = std::exchange(other.set_, VK_NULL_HANDLE);
  }
  return *this;
}

UniformSet::~UniformSet() {
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);  // frees the set
}

}  // namespace vkref::detail
