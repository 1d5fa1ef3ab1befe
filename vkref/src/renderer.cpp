// vkref::Renderer on the plain Vulkan C API (1.3: dynamic rendering, synchronization2).
// create() makes an instance (optionally with VK_LAYER_KHRONOS_validation and a debug messenger
// that collects every warning and error), picks lavapipe or the named device, and makes a device
// with one graphics queue. render() draws a frame into an R8G8B8A8_UNORM colour image and a
// D32_SFLOAT depth image, copies both to host-visible buffers, waits, and returns them.
// Deliberately simple: every render() call creates and destroys all of its own objects (draws of
// one frame with the same program and state share a pipeline; nothing lives across frames), it
// waits for the device before returning, and failures come back as one line of text. Nothing is
// printed and nothing is global; the debug messenger's user data is the Impl. With validation on,
// an error the layer reports also aborts the offending call (see collectMessage).
#include <vkref/renderer.hpp>

#include <vulkan/vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <deque>
#include <iterator>
#include <mutex>
#include <optional>
#include <tuple>
#include <utility>

// Vulkan structs are filled with C++20 designated initializers, which zero the members they do not
// name; GCC's -Wextra would otherwise warn about every omitted pNext and flags.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace vkref {
namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
// Indexed by softraster::DepthFormat.
constexpr VkFormat kDepthFormats[] = {VK_FORMAT_D16_UNORM, VK_FORMAT_X8_D24_UNORM_PACK32, VK_FORMAT_D32_SFLOAT};
constexpr std::uint32_t kDepthTexelBytes[] = {2, 4, 4};
constexpr std::uint32_t kPushConstantBytes = 128;
constexpr VkShaderStageFlags kPushConstantStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// Indexed by the softraster enumerators.
constexpr VkCullModeFlags kCullModes[] = {VK_CULL_MODE_NONE, VK_CULL_MODE_FRONT_BIT, VK_CULL_MODE_BACK_BIT,
                                          VK_CULL_MODE_FRONT_AND_BACK};
constexpr VkFrontFace kFrontFaces[] = {VK_FRONT_FACE_COUNTER_CLOCKWISE, VK_FRONT_FACE_CLOCKWISE};
constexpr VkFormat kAttributeFormats[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT,
                                          VK_FORMAT_R32G32B32A32_SFLOAT};
static_assert(static_cast<int>(softraster::CompareOp::Always) == VK_COMPARE_OP_ALWAYS,
              "softraster::CompareOp lists Vulkan's compare ops in Vulkan's order");

std::string resultName(VkResult r) {
  switch (r) {
#define VKREF_RESULT(name) \
  case name:               \
    return #name;
    VKREF_RESULT(VK_SUCCESS)
    VKREF_RESULT(VK_NOT_READY)
    VKREF_RESULT(VK_TIMEOUT)
    VKREF_RESULT(VK_INCOMPLETE)
    VKREF_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    VKREF_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    VKREF_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    VKREF_RESULT(VK_ERROR_DEVICE_LOST)
    VKREF_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    VKREF_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    VKREF_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    VKREF_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    VKREF_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    VKREF_RESULT(VK_ERROR_FRAGMENTED_POOL)
    VKREF_RESULT(VK_ERROR_UNKNOWN)
    VKREF_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
    VKREF_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    VKREF_RESULT(VK_ERROR_FRAGMENTATION)
    VKREF_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    VKREF_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
    VKREF_RESULT(VK_ERROR_VALIDATION_FAILED_EXT)
    VKREF_RESULT(VK_ERROR_INVALID_SHADER_NV)
#undef VKREF_RESULT
    default:
      return "VkResult(" + std::to_string(static_cast<int>(r)) + ")";
  }
}

// Stores the message and returns false, so failures read `return fail(error, "...")`.
bool fail(std::string* error, std::string message) {
  *error = std::move(message);
  return false;
}

bool check(VkResult r, const char* call, std::string* error) {
  return r == VK_SUCCESS || fail(error, std::string(call) + " failed: " + resultName(r));
}

std::optional<std::uint32_t> findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t allowed,
                                            VkMemoryPropertyFlags wanted) {
  for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
    if ((allowed & (1u << i)) != 0 && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  return std::nullopt;
}

}  // namespace

struct Renderer::Impl {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkPhysicalDeviceMemoryProperties memory{};
  VkPhysicalDeviceLimits limits{};
  VkPhysicalDeviceFeatures features{};  // the core features enabled on `device`
  bool bresenhamLines = false;          // VK_EXT_line_rasterization with bresenhamLines enabled
  std::array<bool, std::size(kDepthFormats)> depthFormatUsable{};
  std::string name;
  mutable std::mutex messagesMutex;
  std::vector<std::string> messages;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl();

  bool createInstance(bool validation, std::string* error);
  bool pickDevice(const std::string& wanted, std::string* error);
  bool createDevice(std::string* error);

  void addMessage(const char* text) {
    const std::lock_guard lock(messagesMutex);
    messages.emplace_back(text ? text : "");
  }
};

namespace {

// Returning VK_TRUE for an error makes the layer abort the offending call with
// VK_ERROR_VALIDATION_FAILED_EXT instead of passing it on: invalid input (malformed SPIR-V, say)
// then fails cleanly rather than crashing the layer or the driver further down.
VKAPI_ATTR VkBool32 VKAPI_CALL collectMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  static_cast<Renderer::Impl*>(user)->addMessage(data ? data->pMessage : nullptr);
  return severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? VK_TRUE : VK_FALSE;
}

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
};

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

// Everything one render() call creates. The destructor waits for submitted work that was not
// seen to finish, then destroys it all (destroying a null handle is a no-op in Vulkan).
struct Frame {
  VkDevice device;
  VkQueue queue;
  const VkPhysicalDeviceMemoryProperties& memory;
  std::deque<Buffer> buffers;  // deque: pointers to elements stay valid
  std::deque<Image> images;
  std::vector<VkPipeline> pipelines;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  bool pending = false;

  Frame(VkDevice d, VkQueue q, const VkPhysicalDeviceMemoryProperties& m) : device(d), queue(q), memory(m) {}
  Frame(const Frame&) = delete;
  Frame& operator=(const Frame&) = delete;

  ~Frame() {
    if (pending) vkQueueWaitIdle(queue);
    vkDestroyCommandPool(device, pool, nullptr);
    vkDestroyFence(device, fence, nullptr);
    for (VkPipeline pipeline : pipelines) vkDestroyPipeline(device, pipeline, nullptr);
    vkDestroyPipelineLayout(device, layout, nullptr);
    for (const Image& i : images) {
      vkDestroyImageView(device, i.view, nullptr);
      vkDestroyImage(device, i.image, nullptr);
      vkFreeMemory(device, i.memory, nullptr);
    }
    for (const Buffer& b : buffers) {
      vkDestroyBuffer(device, b.buffer, nullptr);
      vkFreeMemory(device, b.memory, nullptr);  // also unmaps
    }
  }

  bool allocate(const VkMemoryRequirements& needs, VkMemoryPropertyFlags wanted, VkMemoryPropertyFlags required,
                VkDeviceMemory* out, std::string* error) {
    std::optional<std::uint32_t> type = findMemoryType(memory, needs.memoryTypeBits, wanted);
    if (!type) type = findMemoryType(memory, needs.memoryTypeBits, required);
    if (!type) return fail(error, "no suitable Vulkan memory type");
    const VkMemoryAllocateInfo info{
        .sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, .allocationSize = needs.size, .memoryTypeIndex = *type};
    return check(vkAllocateMemory(device, &info, nullptr, out), "vkAllocateMemory", error);
  }

  // A host-visible, coherent, mapped buffer.
  Buffer* createBuffer(VkDeviceSize size, VkBufferUsageFlags usage, std::string* error) {
    Buffer& b = buffers.emplace_back();
    const VkBufferCreateInfo info{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                                  .size = size,
                                  .usage = usage,
                                  .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    if (!check(vkCreateBuffer(device, &info, nullptr, &b.buffer), "vkCreateBuffer", error)) return nullptr;
    VkMemoryRequirements needs;
    vkGetBufferMemoryRequirements(device, b.buffer, &needs);
    constexpr VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    if (!allocate(needs, host, host, &b.memory, error) ||
        !check(vkBindBufferMemory(device, b.buffer, b.memory, 0), "vkBindBufferMemory", error) ||
        !check(vkMapMemory(device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory", error))
      return nullptr;
    return &b;
  }

  Buffer* upload(const void* data, std::size_t size, VkBufferUsageFlags usage, std::string* error) {
    Buffer* b = createBuffer(size, usage, error);
    if (b) std::memcpy(b->mapped, data, size);
    return b;
  }

  // A single-sample, optimally tiled 2D image (device-local where possible) and a view of it.
  Image* createImage(VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect, std::uint32_t width,
                     std::uint32_t height, std::string* error,
                     VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
    Image& i = images.emplace_back();
    const VkImageCreateInfo info{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                                 .imageType = VK_IMAGE_TYPE_2D,
                                 .format = format,
                                 .extent = {width, height, 1},
                                 .mipLevels = 1,
                                 .arrayLayers = 1,
                                 .samples = samples,
                                 .tiling = VK_IMAGE_TILING_OPTIMAL,
                                 .usage = usage,
                                 .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                 .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    if (!check(vkCreateImage(device, &info, nullptr, &i.image), "vkCreateImage", error)) return nullptr;
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(device, i.image, &needs);
    if (!allocate(needs, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0, &i.memory, error) ||
        !check(vkBindImageMemory(device, i.image, i.memory, 0), "vkBindImageMemory", error))
      return nullptr;
    const VkImageViewCreateInfo viewInfo{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                         .image = i.image,
                                         .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                         .format = format,
                                         .subresourceRange = {aspect, 0, 1, 0, 1}};
    if (!check(vkCreateImageView(device, &viewInfo, nullptr, &i.view), "vkCreateImageView", error)) return nullptr;
    return &i;
  }
};

// The viewport a draw uses: a zero width or height means the whole framebuffer.
VkViewport viewportFor(const softraster::Viewport& v, std::uint32_t width, std::uint32_t height) {
  if (v.width == 0 || v.height == 0)
    return {0, 0, static_cast<float>(width), static_cast<float>(height), v.minDepth, v.maxDepth};
  return {v.x, v.y, v.width, v.height, v.minDepth, v.maxDepth};
}

// Draws with equal programs and equal states can share a pipeline.
auto pipelineKey(const DrawCall& d) {
  const softraster::PipelineState& s = d.state;
  const softraster::Viewport& v = s.viewport;
  const softraster::Scissor& sc = s.scissor;
  const softraster::DepthBias& b = s.rasterization.depthBias;
  return std::tuple(s.blend.enable, s.blend.source, s.blend.destination, s.rasterization.polygonMode, s.rasterization.lineWidth, s.rasterization.lineRasterization, d.program, s.topology, v.x, v.y, v.width, v.height, v.minDepth, v.maxDepth, sc.x, sc.y, sc.width,
                    sc.height, s.rasterization.cullMode, s.rasterization.frontFace, s.rasterization.depthClampEnable,
                    b.enable, b.constantFactor, b.clamp, b.slopeFactor, s.depth.testEnable, s.depth.writeEnable,
                    s.depth.compareOp);
}

std::uint32_t vertexCount(const DrawCall& d) {
  const std::uint32_t stride = d.program && d.program->vertexStride ? d.program->vertexStride : 1;
  return static_cast<std::uint32_t>(d.vertexData.size() / stride);
}

// A draw with nothing to assemble is skipped.
bool isEmpty(const DrawCall& d) { return d.indexed ? d.indices.empty() : vertexCount(d) == 0; }

// What about a draw Vulkan (or this renderer) cannot honour; empty when the draw is fine.
std::string checkDraw(const DrawCall& d, std::uint32_t width, std::uint32_t height,
                      const VkPhysicalDeviceLimits& limits, const VkPhysicalDeviceFeatures& features,
                      bool bresenhamLines) {
  const ShaderProgram* p = d.program;
  if (!p) return "no shader program";
  constexpr std::uint32_t kSpirvMagic = 0x07230203;
  for (std::span<const std::uint32_t> code : {p->vertexSpirv, p->fragmentSpirv})
    if (code.size() < 5 || code[0] != kSpirvMagic) return "program '" + p->name + "' lacks valid SPIR-V";
  if (d.pushConstants.size() > kPushConstantBytes || d.pushConstants.size() % 4 != 0)
    return std::to_string(d.pushConstants.size()) + " bytes of push constants (need a multiple of 4, at most 128)";

  const softraster::PipelineState& s = d.state;
  if (s.topology > softraster::Topology::TriangleFan) return "unsupported topology";
  if (s.rasterization.depthClampEnable && !features.depthClamp) return "depth clamp is not supported by the device";
  if (s.rasterization.depthBias.enable && s.rasterization.depthBias.clamp != 0 && !features.depthBiasClamp)
    return "depth bias clamp is not supported by the device";
  if (s.rasterization.lineWidth != 1.0f && !features.wideLines) return "wide lines are not supported by the device";
  if (s.rasterization.polygonMode > softraster::PolygonMode::Point) return "unsupported polygon mode";
  if (s.rasterization.polygonMode != softraster::PolygonMode::Fill && !features.fillModeNonSolid)
    return "polygon modes line and point are not supported by the device";
  if (s.rasterization.lineWidth < limits.lineWidthRange[0] || s.rasterization.lineWidth > limits.lineWidthRange[1])
    return "line width outside the device's range";
  if (s.rasterization.lineRasterization == softraster::LineRasterization::Bresenham && !bresenhamLines)
    return "Bresenham lines (VK_EXT_line_rasterization) are not supported by the device";
  if (s.scissor.x < 0 || s.scissor.y < 0) return "scissor offset is negative";
  if (static_cast<std::size_t>(s.rasterization.cullMode) >= std::size(kCullModes)) return "unsupported cull mode";
  if (static_cast<std::size_t>(s.rasterization.frontFace) >= std::size(kFrontFaces)) return "unsupported front face";
  if (s.depth.compareOp > softraster::CompareOp::Always) return "unsupported depth compare op";

  const VkViewport v = viewportFor(s.viewport, width, height);
  const float* bounds = limits.viewportBoundsRange;
  if (!(v.width > 0 && v.width <= static_cast<float>(limits.maxViewportDimensions[0]) && v.height != 0 &&
        std::fabs(v.height) <= static_cast<float>(limits.maxViewportDimensions[1])))
    return "viewport size out of range";
  if (!(v.x >= bounds[0] && v.x + v.width <= bounds[1] && std::fmin(v.y, v.y + v.height) >= bounds[0] &&
        std::fmax(v.y, v.y + v.height) <= bounds[1]))
    return "viewport outside the device's viewport bounds";
  if (!(v.minDepth >= 0 && v.minDepth <= 1 && v.maxDepth >= 0 && v.maxDepth <= 1))
    return "viewport depth range outside [0, 1]";

  if (p->attributes.empty()) return {};  // the vertex shader reads no vertex buffer
  if (p->vertexStride == 0 || p->vertexStride > limits.maxVertexInputBindingStride)
    return "vertex stride " + std::to_string(p->vertexStride) + " out of range";
  for (const softraster::VertexAttribute& a : p->attributes)
    if (a.components < 1 || a.components > 4 || a.location >= limits.maxVertexInputAttributes ||
        a.offset > limits.maxVertexInputAttributeOffset || a.offset + 4 * a.components > p->vertexStride)
      return "vertex attribute at location " + std::to_string(a.location) + " does not fit the vertex";
  const std::size_t vertices = d.vertexData.size() / p->vertexStride;
  for (std::uint32_t index : d.indices)
    if (index >= vertices)
      return "index " + std::to_string(index) + " out of range (" + std::to_string(vertices) + " vertices)";
  return {};
}

bool createPipeline(VkDevice device, VkPipelineLayout layout, const DrawCall& d, std::uint32_t width,
                    std::uint32_t height, VkFormat depthFormat, VkSampleCountFlagBits samples, VkPipeline* out,
                    std::string* error) {
  const ShaderProgram& p = *d.program;
  const std::span<const std::uint32_t> code[2] = {p.vertexSpirv, p.fragmentSpirv};
  VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  bool ok = true;
  for (int i = 0; i < 2 && ok; ++i) {
    const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                        .codeSize = code[i].size_bytes(),
                                        .pCode = code[i].data()};
    ok = check(vkCreateShaderModule(device, &info, nullptr, &modules[i]), "vkCreateShaderModule", error);
  }
  if (ok) {
    const VkPipelineShaderStageCreateInfo stages[2] = {
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_VERTEX_BIT,
         .module = modules[0],
         .pName = "main"},
        {.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
         .stage = VK_SHADER_STAGE_FRAGMENT_BIT,
         .module = modules[1],
         .pName = "main"}};
    const VkVertexInputBindingDescription binding{0, p.vertexStride, VK_VERTEX_INPUT_RATE_VERTEX};
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const softraster::VertexAttribute& a : p.attributes)
      attributes.push_back({a.location, 0, kAttributeFormats[a.components - 1], a.offset});
    const VkPipelineVertexInputStateCreateInfo vertexInput{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
        .vertexBindingDescriptionCount = attributes.empty() ? 0u : 1u,
        .pVertexBindingDescriptions = &binding,
        .vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes.size()),
        .pVertexAttributeDescriptions = attributes.data()};
    const VkPipelineInputAssemblyStateCreateInfo inputAssembly{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
        .topology = static_cast<VkPrimitiveTopology>(d.state.topology)};  // same order as Vulkan's
    const VkViewport viewport = viewportFor(d.state.viewport, width, height);
    const softraster::Scissor& sc = d.state.scissor;
    const VkRect2D scissor = sc.width == 0 || sc.height == 0 ? VkRect2D{{0, 0}, {width, height}}
                                                             : VkRect2D{{sc.x, sc.y}, {sc.width, sc.height}};
    const VkPipelineViewportStateCreateInfo viewportState{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                          .viewportCount = 1,
                                                          .pViewports = &viewport,
                                                          .scissorCount = 1,
                                                          .pScissors = &scissor};
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .depthClampEnable = d.state.rasterization.depthClampEnable ? VK_TRUE : VK_FALSE,
        .rasterizerDiscardEnable = VK_FALSE,
        .polygonMode = static_cast<VkPolygonMode>(d.state.rasterization.polygonMode),  // same order as Vulkan's
        .cullMode = kCullModes[static_cast<std::size_t>(d.state.rasterization.cullMode)],
        .frontFace = kFrontFaces[static_cast<std::size_t>(d.state.rasterization.frontFace)],
        .depthBiasEnable = d.state.rasterization.depthBias.enable ? VK_TRUE : VK_FALSE,
        .depthBiasConstantFactor = d.state.rasterization.depthBias.constantFactor,
        .depthBiasClamp = d.state.rasterization.depthBias.clamp,
        .depthBiasSlopeFactor = d.state.rasterization.depthBias.slopeFactor,
        .lineWidth = d.state.rasterization.lineWidth};
    // Bresenham lines need VK_EXT_line_rasterization; rectangular ones are Vulkan's default.
    const VkPipelineRasterizationLineStateCreateInfoEXT lineState{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_LINE_STATE_CREATE_INFO_EXT,
        .lineRasterizationMode = VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT};
    if (d.state.rasterization.lineRasterization == softraster::LineRasterization::Bresenham)
      rasterization.pNext = &lineState;
    const VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = samples};
    const VkPipelineDepthStencilStateCreateInfo depth{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = d.state.depth.testEnable ? VK_TRUE : VK_FALSE,
        .depthWriteEnable = d.state.depth.writeEnable ? VK_TRUE : VK_FALSE,
        .depthCompareOp = static_cast<VkCompareOp>(d.state.depth.compareOp)};
    const softraster::BlendState& b = d.state.blend;
    const auto factor = [](softraster::BlendFactor f) {
      return f == softraster::BlendFactor::One ? VK_BLEND_FACTOR_ONE : VK_BLEND_FACTOR_ZERO;
    };
    const VkPipelineColorBlendAttachmentState blendAttachment{
        .blendEnable = b.enable ? VK_TRUE : VK_FALSE,
        .srcColorBlendFactor = factor(b.source),
        .dstColorBlendFactor = factor(b.destination),
        .colorBlendOp = VK_BLEND_OP_ADD,
        .srcAlphaBlendFactor = factor(b.source),
        .dstAlphaBlendFactor = factor(b.destination),
        .alphaBlendOp = VK_BLEND_OP_ADD,
        .colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                          VK_COLOR_COMPONENT_A_BIT};
    const VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                                    .attachmentCount = 1,
                                                    .pAttachments = &blendAttachment};
    const VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                  .colorAttachmentCount = 1,
                                                  .pColorAttachmentFormats = &kColourFormat,
                                                  .depthAttachmentFormat = depthFormat};
    const VkGraphicsPipelineCreateInfo info{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                            .pNext = &rendering,
                                            .stageCount = 2,
                                            .pStages = stages,
                                            .pVertexInputState = &vertexInput,
                                            .pInputAssemblyState = &inputAssembly,
                                            .pViewportState = &viewportState,
                                            .pRasterizationState = &rasterization,
                                            .pMultisampleState = &multisample,
                                            .pDepthStencilState = &depth,
                                            .pColorBlendState = &blend,
                                            .layout = layout};
    ok = check(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, out), "vkCreateGraphicsPipelines",
               error);
  }
  for (VkShaderModule m : modules) vkDestroyShaderModule(device, m, nullptr);
  return ok;
}

VkImageMemoryBarrier2 imageBarrier(VkImage image, VkImageAspectFlags aspect, VkPipelineStageFlags2 srcStage,
                                   VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess,
                                   VkImageLayout from, VkImageLayout to) {
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
          .subresourceRange = {aspect, 0, 1, 0, 1}};
}

void barrier(VkCommandBuffer cmd, std::span<const VkImageMemoryBarrier2> images,
             const VkMemoryBarrier2* memory = nullptr) {
  const VkDependencyInfo info{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                              .memoryBarrierCount = memory ? 1u : 0u,
                              .pMemoryBarriers = memory,
                              .imageMemoryBarrierCount = static_cast<std::uint32_t>(images.size()),
                              .pImageMemoryBarriers = images.data()};
  vkCmdPipelineBarrier2(cmd, &info);
}

}  // namespace

// ---- Impl: instance, device --------------------------------------------------------------------

Renderer::Impl::~Impl() {
  if (device) {
    vkDeviceWaitIdle(device);
    vkDestroyDevice(device, nullptr);
  }
  if (messenger) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance, messenger, nullptr);
  }
  if (instance) vkDestroyInstance(instance, nullptr);
}

bool Renderer::Impl::createInstance(bool validation, std::string* error) {
  std::vector<const char*> layers, extensions;
  if (validation) {
    std::uint32_t count = 0;
    if (!check(vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties", error))
      return false;
    std::vector<VkLayerProperties> available(count);
    if (!check(vkEnumerateInstanceLayerProperties(&count, available.data()), "vkEnumerateInstanceLayerProperties",
               error))
      return false;
    bool found = false;
    for (std::uint32_t i = 0; i < count; ++i) found = found || std::strcmp(available[i].layerName, kValidationLayer) == 0;
    if (!found)
      return fail(error, "validation requested but VK_LAYER_KHRONOS_validation is not available "
                         "(is vulkan-validationlayers installed?)");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  const VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                              .pApplicationName = "vkref",
                              .pEngineName = "vkref",
                              .apiVersion = VK_API_VERSION_1_3};
  // Chained into the instance create info too, so instance creation and destruction are covered.
  const VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
      .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
      .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
      .pfnUserCallback = &collectMessage,
      .pUserData = this};
  const VkInstanceCreateInfo info{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                                  .pNext = validation ? &messengerInfo : nullptr,
                                  .pApplicationInfo = &app,
                                  .enabledLayerCount = static_cast<std::uint32_t>(layers.size()),
                                  .ppEnabledLayerNames = layers.data(),
                                  .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
                                  .ppEnabledExtensionNames = extensions.data()};
  const VkResult r = vkCreateInstance(&info, nullptr, &instance);
  if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
    return fail(error, "no Vulkan driver found (vkCreateInstance failed: VK_ERROR_INCOMPATIBLE_DRIVER; "
                       "is mesa-vulkan-drivers installed?)");
  if (!check(r, "vkCreateInstance", error)) return false;
  if (!validation) return true;
  auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
      vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
  if (!create) return fail(error, "vkCreateDebugUtilsMessengerEXT is not available");
  return check(create(instance, &messengerInfo, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT", error);
}

bool Renderer::Impl::pickDevice(const std::string& wanted, std::string* error) {
  std::uint32_t count = 0;
  if (!check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices", error)) return false;
  std::vector<VkPhysicalDevice> devices(count);
  if (!check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices", error))
    return false;
  devices.resize(count);
  if (devices.empty()) return fail(error, "no Vulkan device found (is mesa-vulkan-drivers installed?)");

  std::string available;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    vkGetPhysicalDeviceProperties(candidate, &properties.properties);
    if (properties.properties.apiVersion >= VK_API_VERSION_1_2) {  // driver properties are core from 1.2
      properties.pNext = &driver;
      vkGetPhysicalDeviceProperties2(candidate, &properties);
    }
    const std::string candidateName = properties.properties.deviceName;
    const bool match = wanted.empty() ? driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE
                                      : candidateName.find(wanted) != std::string::npos;
    if (match) {
      physicalDevice = candidate;
      name = candidateName;
      limits = properties.properties.limits;
      if (properties.properties.apiVersion < VK_API_VERSION_1_3)
        return fail(error, "Vulkan device '" + name + "' supports Vulkan " +
                               std::to_string(VK_API_VERSION_MAJOR(properties.properties.apiVersion)) + "." +
                               std::to_string(VK_API_VERSION_MINOR(properties.properties.apiVersion)) +
                               "; vkref needs 1.3");
      return true;
    }
    available += (available.empty() ? "" : ", ") + candidateName;
  }
  const std::string what = wanted.empty() ? "lavapipe (llvmpipe)" : "'" + wanted + "'";
  return fail(error, "no Vulkan device matches " + what + " (available: " + available + ")");
}

bool Renderer::Impl::createDevice(std::string* error) {
  VkPhysicalDeviceVulkan13Features supported{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &supported};
  vkGetPhysicalDeviceFeatures2(physicalDevice, &features2);
  if (!supported.dynamicRendering || !supported.synchronization2)
    return fail(error, "Vulkan device '" + name + "' lacks dynamicRendering or synchronization2");

  const auto supports = [&](VkFormat format, VkFormatFeatureFlags needed) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(physicalDevice, format, &properties);
    return (properties.optimalTilingFeatures & needed) == needed;
  };
  if (!supports(kColourFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT))
    return fail(error, "Vulkan device '" + name + "' cannot render to R8G8B8A8_UNORM and copy it");
  for (std::size_t f = 0; f < std::size(kDepthFormats); ++f)
    depthFormatUsable[f] =
        supports(kDepthFormats[f], VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT);
  // Optional core features scenes may use: enabled when the device has them, else draws needing
  // them are rejected by checkDraw.
  features.depthClamp = features2.features.depthClamp;
  features.depthBiasClamp = features2.features.depthBiasClamp;
  features.wideLines = features2.features.wideLines;
  features.fillModeNonSolid = features2.features.fillModeNonSolid;
  features.largePoints = features2.features.largePoints;

  // VK_EXT_line_rasterization, for Bresenham lines.
  std::uint32_t extensionCount = 0;
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &extensionCount, nullptr);
  std::vector<VkExtensionProperties> extensions(extensionCount);
  vkEnumerateDeviceExtensionProperties(physicalDevice, nullptr, &extensionCount, extensions.data());
  const bool hasLineRasterization = std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME) == 0;
  });
  VkPhysicalDeviceLineRasterizationFeaturesEXT lineFeatures{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT};
  if (hasLineRasterization) {
    VkPhysicalDeviceFeatures2 query{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &lineFeatures};
    vkGetPhysicalDeviceFeatures2(physicalDevice, &query);
    bresenhamLines = lineFeatures.bresenhamLines == VK_TRUE;
  }

  std::uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physicalDevice, &familyCount, families.data());
  queueFamily = familyCount;
  for (std::uint32_t i = 0; i < familyCount && queueFamily == familyCount; ++i)
    if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) queueFamily = i;
  if (queueFamily == familyCount) return fail(error, "Vulkan device '" + name + "' has no graphics queue");

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queueInfo{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                          .queueFamilyIndex = queueFamily,
                                          .queueCount = 1,
                                          .pQueuePriorities = &priority};
  VkPhysicalDeviceLineRasterizationFeaturesEXT enabledLines{
      .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_LINE_RASTERIZATION_FEATURES_EXT,
      .bresenhamLines = bresenhamLines ? VK_TRUE : VK_FALSE};
  VkPhysicalDeviceVulkan13Features enabled{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES,
                                           .pNext = bresenhamLines ? &enabledLines : nullptr,
                                           .synchronization2 = VK_TRUE,
                                           .dynamicRendering = VK_TRUE};
  const char* lineExtension = VK_EXT_LINE_RASTERIZATION_EXTENSION_NAME;
  const VkDeviceCreateInfo info{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                                .pNext = &enabled,
                                .queueCreateInfoCount = 1,
                                .pQueueCreateInfos = &queueInfo,
                                .enabledExtensionCount = bresenhamLines ? 1u : 0u,
                                .ppEnabledExtensionNames = &lineExtension,
                                .pEnabledFeatures = &features};
  if (!check(vkCreateDevice(physicalDevice, &info, nullptr, &device), "vkCreateDevice", error)) return false;
  vkGetDeviceQueue(device, queueFamily, 0, &queue);
  vkGetPhysicalDeviceMemoryProperties(physicalDevice, &memory);
  return true;
}

// ---- Renderer ----------------------------------------------------------------------------------

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

std::unique_ptr<Renderer> Renderer::create(const DeviceOptions& options, std::string* error) {
  std::string ignored;
  if (!error) error = &ignored;
  auto impl = std::make_unique<Impl>();
  if (!impl->createInstance(options.validation, error) || !impl->pickDevice(options.deviceName, error) ||
      !impl->createDevice(error))
    return nullptr;
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

std::string Renderer::deviceName() const { return impl_->name; }

std::vector<std::string> Renderer::validationMessages() const {
  const std::lock_guard lock(impl_->messagesMutex);
  return impl_->messages;
}

bool Renderer::render(const FrameRequest& request, FrameImages* out, std::string* error) {
  std::string ignored;
  if (!error) error = &ignored;
  if (!out) return fail(error, "render: no FrameImages to write to");
  const Impl& im = *impl_;
  const std::uint32_t width = request.width, height = request.height;
  if (width == 0 || height == 0 || width > im.limits.maxFramebufferWidth || height > im.limits.maxFramebufferHeight)
    return fail(error, "frame size " + std::to_string(width) + "x" + std::to_string(height) + " out of range (1.." +
                           std::to_string(im.limits.maxFramebufferWidth) + "x" +
                           std::to_string(im.limits.maxFramebufferHeight) + ")");
  if (!(request.clearDepth >= 0 && request.clearDepth <= 1)) return fail(error, "clearDepth outside [0, 1]");
  const auto depthIndex = static_cast<std::size_t>(request.depthFormat);
  if (depthIndex >= std::size(kDepthFormats) || !im.depthFormatUsable[depthIndex])
    return fail(error, "depth format " + std::to_string(depthIndex) + " cannot be rendered to and copied on this device");
  const VkFormat depthFormat = kDepthFormats[depthIndex];
  if (request.samples != 1 && request.samples != 4) return fail(error, "sample count must be 1 or 4");
  const bool multisample = request.samples == 4;
  const VkSampleCountFlagBits samples = multisample ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT;
  if (multisample && (!(im.limits.framebufferColorSampleCounts & VK_SAMPLE_COUNT_4_BIT) ||
                      !(im.limits.framebufferDepthSampleCounts & VK_SAMPLE_COUNT_4_BIT)))
    return fail(error, "the device cannot render 4x multisampled colour and depth");
  const std::uint32_t depthTexelBytes = kDepthTexelBytes[depthIndex];
  const std::vector<DrawCall>& draws = request.draws;
  for (std::size_t i = 0; i < draws.size(); ++i) {
    if (isEmpty(draws[i])) continue;  // skipped, so not checked either
    if (std::string problem = checkDraw(draws[i], width, height, im.limits, im.features, im.bresenhamLines); !problem.empty())
      return fail(error, "draw " + std::to_string(i) + ": " + problem);
  }

  Frame frame(im.device, im.queue, im.memory);
  const std::size_t pixels = std::size_t{width} * height;
  Image* colour = frame.createImage(kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                    VK_IMAGE_ASPECT_COLOR_BIT, width, height, error);
  if (!colour) return false;
  Image* depth = frame.createImage(depthFormat,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_ASPECT_DEPTH_BIT, width, height, error);
  if (!depth) return false;
  // With MSAA these two single-sample images receive the resolves of the multisampled ones.
  Image* msColour = nullptr;
  Image* msDepth = nullptr;
  if (multisample) {
    msColour = frame.createImage(kColourFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, VK_IMAGE_ASPECT_COLOR_BIT, width,
                                 height, error, samples);
    if (!msColour) return false;
    msDepth = frame.createImage(depthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
                                width, height, error, samples);
    if (!msDepth) return false;
  }
  Buffer* colourOut = frame.createBuffer(pixels * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, error);
  if (!colourOut) return false;
  Buffer* depthOut = frame.createBuffer(pixels * depthTexelBytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, error);
  if (!depthOut) return false;

  const VkPushConstantRange pushRange{kPushConstantStages, 0, kPushConstantBytes};
  const VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                              .pushConstantRangeCount = 1,
                                              .pPushConstantRanges = &pushRange};
  if (!check(vkCreatePipelineLayout(im.device, &layoutInfo, nullptr, &frame.layout), "vkCreatePipelineLayout", error))
    return false;

  // Per draw: its pipeline (shared with an earlier draw of the same program and state) and buffers.
  struct Prepared {
    VkPipeline pipeline = VK_NULL_HANDLE;
    Buffer* vertices = nullptr;
    Buffer* indices = nullptr;
  };
  std::vector<Prepared> prepared(draws.size());
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const DrawCall& d = draws[i];
    if (isEmpty(d)) continue;
    for (std::size_t j = 0; j < i && !prepared[i].pipeline; ++j)
      if (prepared[j].pipeline && pipelineKey(draws[j]) == pipelineKey(d)) prepared[i].pipeline = prepared[j].pipeline;
    if (!prepared[i].pipeline) {
      VkPipeline& pipeline = frame.pipelines.emplace_back(VK_NULL_HANDLE);
      if (!createPipeline(im.device, frame.layout, d, width, height, depthFormat, samples, &pipeline, error))
        return fail(error, "draw " + std::to_string(i) + " (program '" + d.program->name + "'): " + *error);
      prepared[i].pipeline = pipeline;
    }
    if (!d.program->attributes.empty() &&
        !(prepared[i].vertices = frame.upload(d.vertexData.data(), d.vertexData.size(),
                                              VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, error)))
      return false;
    if (d.indexed && !(prepared[i].indices = frame.upload(d.indices.data(), d.indices.size() * sizeof(std::uint32_t),
                                                          VK_BUFFER_USAGE_INDEX_BUFFER_BIT, error)))
      return false;
  }

  const VkCommandPoolCreateInfo poolInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                         .flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT,
                                         .queueFamilyIndex = im.queueFamily};
  if (!check(vkCreateCommandPool(im.device, &poolInfo, nullptr, &frame.pool), "vkCreateCommandPool", error))
    return false;
  const VkCommandBufferAllocateInfo allocInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                              .commandPool = frame.pool,
                                              .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                              .commandBufferCount = 1};
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  if (!check(vkAllocateCommandBuffers(im.device, &allocInfo, &cmd), "vkAllocateCommandBuffers", error)) return false;
  const VkFenceCreateInfo fenceInfo{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (!check(vkCreateFence(im.device, &fenceInfo, nullptr, &frame.fence), "vkCreateFence", error)) return false;

  const VkCommandBufferBeginInfo beginInfo{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                           .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  if (!check(vkBeginCommandBuffer(cmd, &beginInfo), "vkBeginCommandBuffer", error)) return false;

  constexpr VkPipelineStageFlags2 depthStages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  // A depth resolve writes in the colour-attachment-output stage.
  constexpr VkPipelineStageFlags2 depthWriteStages = depthStages | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
  constexpr VkAccessFlags2 depthWriteAccess =
      VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
  std::vector<VkImageMemoryBarrier2> toAttachments;
  for (Image* image : {colour, msColour}) {
    if (image)
      toAttachments.push_back(imageBarrier(image->image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_NONE,
                                           VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                           VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                                           VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL));
  }
  for (Image* image : {depth, msDepth}) {
    if (image)
      toAttachments.push_back(imageBarrier(
          image->image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, depthWriteStages,
          VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | depthWriteAccess, VK_IMAGE_LAYOUT_UNDEFINED,
          VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL));
  }
  barrier(cmd, toAttachments);

  const auto& c = request.clearColour;
  const VkRenderingAttachmentInfo colourAttachment{
      .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
      .imageView = multisample ? msColour->view : colour->view,
      .imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
      .resolveMode = multisample ? VK_RESOLVE_MODE_AVERAGE_BIT : VK_RESOLVE_MODE_NONE,
      .resolveImageView = multisample ? colour->view : VK_NULL_HANDLE,
      .resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
      .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                   .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                                   .clearValue = {.color = {.float32 = {c[0], c[1], c[2], c[3]}}}};
  const VkRenderingAttachmentInfo depthAttachment{
      .sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
      .imageView = multisample ? msDepth->view : depth->view,
      .imageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
      .resolveMode = multisample ? VK_RESOLVE_MODE_SAMPLE_ZERO_BIT : VK_RESOLVE_MODE_NONE,
      .resolveImageView = multisample ? depth->view : VK_NULL_HANDLE,
      .resolveImageLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
      .loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                  .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                                  .clearValue = {.depthStencil = {request.clearDepth, 0}}};
  const VkRenderingInfo renderingInfo{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                                      .renderArea = {{0, 0}, {width, height}},
                                      .layerCount = 1,
                                      .colorAttachmentCount = 1,
                                      .pColorAttachments = &colourAttachment,
                                      .pDepthAttachment = &depthAttachment};
  vkCmdBeginRendering(cmd, &renderingInfo);
  for (std::size_t i = 0; i < draws.size(); ++i) {
    const DrawCall& d = draws[i];
    if (isEmpty(d)) continue;
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, prepared[i].pipeline);
    if (prepared[i].vertices) {
      const VkDeviceSize offset = 0;
      vkCmdBindVertexBuffers(cmd, 0, 1, &prepared[i].vertices->buffer, &offset);
    }
    if (!d.pushConstants.empty())
      vkCmdPushConstants(cmd, frame.layout, kPushConstantStages, 0, static_cast<std::uint32_t>(d.pushConstants.size()),
                         d.pushConstants.data());
    if (d.indexed) {
      vkCmdBindIndexBuffer(cmd, prepared[i].indices->buffer, 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(cmd, static_cast<std::uint32_t>(d.indices.size()), 1, 0, 0, 0);
    } else {
      vkCmdDraw(cmd, vertexCount(d), 1, 0, 0);
    }
  }
  vkCmdEndRendering(cmd);

  const VkImageMemoryBarrier2 toTransfer[2] = {
      imageBarrier(colour->image, VK_IMAGE_ASPECT_COLOR_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                   VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                   VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL),
      imageBarrier(depth->image, VK_IMAGE_ASPECT_DEPTH_BIT, depthWriteStages, depthWriteAccess,
                   VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)};
  barrier(cmd, toTransfer);
  // Tightly packed rows, row 0 = top. Depth copies out as stored: D16 as 16-bit integers,
  // X8_D24 as 32-bit words with the depth in the low 24 bits, D32_SFLOAT as floats.
  const VkBufferImageCopy colourRegion{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                       .imageExtent = {width, height, 1}};
  const VkBufferImageCopy depthRegion{.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1},
                                      .imageExtent = {width, height, 1}};
  vkCmdCopyImageToBuffer(cmd, colour->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, colourOut->buffer, 1, &colourRegion);
  vkCmdCopyImageToBuffer(cmd, depth->image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, depthOut->buffer, 1, &depthRegion);
  const VkMemoryBarrier2 toHost{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                                .srcStageMask = VK_PIPELINE_STAGE_2_COPY_BIT,
                                .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                                .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
  barrier(cmd, {}, &toHost);
  if (!check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer", error)) return false;

  const VkSubmitInfo submit{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd};
  if (!check(vkQueueSubmit(im.queue, 1, &submit, frame.fence), "vkQueueSubmit", error)) return false;
  frame.pending = true;
  if (!check(vkWaitForFences(im.device, 1, &frame.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences", error)) return false;
  frame.pending = false;

  out->width = width;
  out->height = height;
  out->rgba.resize(pixels * 4);
  std::memcpy(out->rgba.data(), colourOut->mapped, pixels * 4);
  out->depth.resize(pixels);
  out->depthStorage.resize(pixels);
  const auto* texels = static_cast<const std::uint8_t*>(depthOut->mapped);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint32_t stored = 0;
    std::memcpy(&stored, texels + i * depthTexelBytes, depthTexelBytes);
    switch (request.depthFormat) {
      case softraster::DepthFormat::D16Unorm: out->depth[i] = static_cast<float>(stored / 65535.0); break;
      case softraster::DepthFormat::X8D24UnormPack32:
        stored &= 0xffffffu;
        out->depth[i] = static_cast<float>(stored / 16777215.0);
        break;
      case softraster::DepthFormat::D32Sfloat: std::memcpy(&out->depth[i], &stored, 4); break;
    }
    out->depthStorage[i] = stored;
  }
  return true;
}

}  // namespace vkref
