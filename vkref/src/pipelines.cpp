// vkref pipelines (see pipelines.hpp): checks, state translation and the pipeline cache.
#include "pipelines.hpp"

#include "errors.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <span>
#include <string_view>

namespace vkref::detail {
namespace {

using softraster::Status;

// Indexed by the softraster enumerators.
constexpr VkCullModeFlags kCullModes[] = {VK_CULL_MODE_NONE, VK_CULL_MODE_FRONT_BIT, VK_CULL_MODE_BACK_BIT,
                                          VK_CULL_MODE_FRONT_AND_BACK};
constexpr VkFrontFace kFrontFaces[] = {VK_FRONT_FACE_COUNTER_CLOCKWISE, VK_FRONT_FACE_CLOCKWISE};
constexpr VkFormat kAttributeFormats[] = {VK_FORMAT_R32_SFLOAT, VK_FORMAT_R32G32_SFLOAT, VK_FORMAT_R32G32B32_SFLOAT,
                                          VK_FORMAT_R32G32B32A32_SFLOAT};
static_assert(static_cast<int>(softraster::CompareOp::Always) == VK_COMPARE_OP_ALWAYS,
              "softraster::CompareOp lists Vulkan's compare ops in Vulkan's order");
static_assert(static_cast<int>(softraster::StencilOp::IncrementAndClamp) == VK_STENCIL_OP_INCREMENT_AND_CLAMP &&
                  static_cast<int>(softraster::StencilOp::DecrementAndWrap) == VK_STENCIL_OP_DECREMENT_AND_WRAP,
              "softraster::StencilOp lists Vulkan's stencil ops in Vulkan's order");
static_assert(static_cast<int>(softraster::BlendFactor::SrcAlphaSaturate) == VK_BLEND_FACTOR_SRC_ALPHA_SATURATE &&
                  static_cast<int>(softraster::BlendOp::Max) == VK_BLEND_OP_MAX &&
                  static_cast<int>(softraster::kColourA) == static_cast<int>(VK_COLOR_COMPONENT_A_BIT) &&
                  static_cast<int>(softraster::LogicOp::Set) == VK_LOGIC_OP_SET &&
                  static_cast<int>(softraster::LogicOp::Xor) == VK_LOGIC_OP_XOR,
              "softraster's blend enums are Vulkan's values");
// A tripwire: a field added to PipelineState must also join PipelineCache::Key (and compile()),
// or draws differing only in it would share a pipeline.
static_assert(sizeof(softraster::PipelineState) == 216, "PipelineState changed: update PipelineCache::Key");

// Whether two attachments' blend states are the same VkPipelineColorBlendAttachmentState.
bool sameBlend(const softraster::AttachmentBlend& a, const softraster::AttachmentBlend& b) {
  return a.enable == b.enable && a.srcColorBlendFactor == b.srcColorBlendFactor &&
         a.dstColorBlendFactor == b.dstColorBlendFactor && a.colorBlendOp == b.colorBlendOp &&
         a.srcAlphaBlendFactor == b.srcAlphaBlendFactor && a.dstAlphaBlendFactor == b.dstAlphaBlendFactor &&
         a.alphaBlendOp == b.alphaBlendOp && a.colorWriteMask == b.colorWriteMask;
}

// The viewport a draw uses: a zero width or height means the whole framebuffer.
VkViewport viewportFor(const softraster::Viewport& v, std::uint32_t width, std::uint32_t height) {
  if (v.width == 0 || v.height == 0)
    return {0, 0, static_cast<float>(width), static_cast<float>(height), v.minDepth, v.maxDepth};
  return {v.x, v.y, v.width, v.height, v.minDepth, v.maxDepth};
}

// The scissor a draw uses: a zero width or height means the whole framebuffer.
VkRect2D scissorFor(const softraster::Scissor& s, std::uint32_t width, std::uint32_t height) {
  if (s.width == 0 || s.height == 0) return {{0, 0}, {width, height}};
  return {{s.x, s.y}, {s.width, s.height}};
}

template <class T>
std::string_view bytesOf(const std::vector<T>& v) {
  return {reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T)};
}
template <class T>
std::string_view bytesOf(std::span<const T> v) {
  return {reinterpret_cast<const char*>(v.data()), v.size_bytes()};
}

}  // namespace

std::uint32_t vertexCount(const DrawCall& d) {
  const std::uint32_t stride = d.program && d.program->vertexStride ? d.program->vertexStride : 1;
  return static_cast<std::uint32_t>(d.vertexData.size() / stride);
}

bool isEmpty(const DrawCall& d) { return d.indexed ? d.indices.empty() : vertexCount(d) == 0; }

// ---- Checks ------------------------------------------------------------------------------------

Status checkFrame(const FrameRequest& request, const Device& device) {
  const VkPhysicalDeviceLimits& limits = device.limits;
  const std::uint32_t width = request.width, height = request.height;
  if (width == 0 || height == 0 || width > limits.maxFramebufferWidth || height > limits.maxFramebufferHeight)
    return Status::error("frame size " + std::to_string(width) + "x" + std::to_string(height) + " out of range (1.." +
                         std::to_string(limits.maxFramebufferWidth) + "x" +
                         std::to_string(limits.maxFramebufferHeight) + ")");
  if (!(request.clearDepth >= 0 && request.clearDepth <= 1)) return Status::error("clearDepth outside [0, 1]");
  const auto depthIndex = static_cast<std::size_t>(request.depthFormat);
  if (depthIndex >= std::size(kDepthFormats) || !device.depthFormatUsable[depthIndex])
    return Status::error("depth format " + std::to_string(depthIndex) +
                         " cannot be rendered to and copied on this device");
  const auto colourUsable = [&](softraster::ColourFormat format, const std::string& what) -> Status {
    const auto index = static_cast<std::size_t>(format);
    if (index >= std::size(kColourFormats) || !device.colourFormatUsable[index])
      return Status::error(what + "colour format " + std::to_string(index) +
                           " cannot be rendered to, blended, sampled and copied on this device");
    return {};
  };
  if (Status s = colourUsable(request.colourFormat, ""); !s) return s;
  const std::size_t attachments = 1 + request.moreColour.size();
  if (attachments > softraster::kMaxColourAttachments || attachments > limits.maxColorAttachments)
    return Status::error(std::to_string(attachments) + " colour attachments (at most " +
                         std::to_string(std::min<std::uint32_t>(softraster::kMaxColourAttachments,
                                                                limits.maxColorAttachments)) +
                         ")");
  for (std::size_t i = 0; i < request.moreColour.size(); ++i)
    if (Status s = colourUsable(request.moreColour[i].format, "colour attachment " + std::to_string(i + 1) + ": "); !s)
      return s;
  if (request.samples != 1 && request.samples != 4) return Status::error("sample count must be 1 or 4");
  if (request.samples == 4 && (!(limits.framebufferColorSampleCounts & VK_SAMPLE_COUNT_4_BIT) ||
                               !(limits.framebufferDepthSampleCounts & VK_SAMPLE_COUNT_4_BIT)))
    return Status::error("the device cannot render 4x multisampled colour and depth");
  return {};
}

Status checkDraw(const DrawCall& d, std::uint32_t width, std::uint32_t height, std::uint32_t colourAttachments,
                 const Device& device) {
  const VkPhysicalDeviceLimits& limits = device.limits;
  const VkPhysicalDeviceFeatures& features = device.features;
  const ShaderProgram* p = d.program;
  if (!p) return Status::error("no shader program");
  constexpr std::uint32_t kSpirvMagic = 0x07230203;
  for (std::span<const std::uint32_t> code : {p->vertexSpirv, p->fragmentSpirv})
    if (code.size() < 5 || code[0] != kSpirvMagic) return Status::error("program '" + p->name + "' lacks valid SPIR-V");
  if (d.pushConstants.size() > kPushConstantBytes || d.pushConstants.size() % 4 != 0)
    return Status::error(std::to_string(d.pushConstants.size()) +
                         " bytes of push constants (need a multiple of 4, at most 128)");
  if (d.uniformData.size() > limits.maxUniformBufferRange || d.uniformData.size() % 4 != 0)
    return Status::error(std::to_string(d.uniformData.size()) + " bytes of uniform block (need a multiple of 4, at most " +
                         std::to_string(limits.maxUniformBufferRange) + ")");

  if (d.textures.size() > kMaxTextures)
    return Status::error(std::to_string(d.textures.size()) + " textures (at most " + std::to_string(kMaxTextures) + ")");
  for (std::size_t i = 0; i < d.textures.size(); ++i) {
    const softraster::Texture* t = d.textures[i].texture;
    if (t == nullptr && d.textures[i].depthPass >= 0) {  // the pass's index is checked by checkFrame
      if (d.textures[i].sampler.compareOp > softraster::CompareOp::Always)
        return Status::error("texture " + std::to_string(i) + ": unknown compare op");
      continue;
    }
    if (t == nullptr || t->levels() == 0) return Status::error("texture " + std::to_string(i) + " has no texels");
    if (t->width() > limits.maxImageDimension2D || t->height() > limits.maxImageDimension2D)
      return Status::error("texture " + std::to_string(i) + " is larger than maxImageDimension2D");
    if (d.textures[i].depthPass >= 0) return Status::error("texture " + std::to_string(i) + " names a depth pass and a texture");
    if (d.textures[i].sampler.compareEnable) return Status::error("texture " + std::to_string(i) + ": a comparison sampler needs a depth pass's image");
    if (std::fabs(d.textures[i].sampler.mipLodBias) > limits.maxSamplerLodBias)
      return Status::error("texture " + std::to_string(i) + ": mipLodBias beyond maxSamplerLodBias");
  }

  const softraster::PipelineState& s = d.state;
  if (s.topology > softraster::Topology::TriangleStripWithAdjacency) return Status::error("unsupported topology");
  if (s.primitiveRestartEnable && s.topology != softraster::Topology::LineStrip &&
      s.topology != softraster::Topology::TriangleStrip && s.topology != softraster::Topology::TriangleFan &&
      s.topology != softraster::Topology::LineStripWithAdjacency &&
      s.topology != softraster::Topology::TriangleStripWithAdjacency)
    return Status::error("primitive restart with a list topology needs primitiveTopologyListRestart (not enabled)");
  if (s.topology >= softraster::Topology::LineListWithAdjacency && !features.geometryShader)
    return Status::error("adjacency topologies need the geometryShader feature, which the device lacks "
                         "(VUID-VkPipelineInputAssemblyStateCreateInfo-topology-00429)");
  if (s.rasterization.provokingVertex == softraster::ProvokingVertex::Last && !device.provokingVertexLast)
    return Status::error("provoking vertex last (VK_EXT_provoking_vertex) is not supported by the device");
  if (s.rasterization.lineStipple.enable) {
    const bool bresenham = s.rasterization.lineRasterization == softraster::LineRasterization::Bresenham;
    if (!(bresenham ? device.stippledBresenhamLines : device.stippledRectangularLines && device.rectangularLines))
      return Status::error("stippled lines of this mode (VK_EXT_line_rasterization) are not supported by the device");
    if (s.rasterization.lineStipple.factor < 1 || s.rasterization.lineStipple.factor > 256)
      return Status::error("line stipple factor outside [1, 256]");
  }
  if (s.rasterization.depthClampEnable && !features.depthClamp)
    return Status::error("depth clamp is not supported by the device");
  if (s.rasterization.depthBias.enable && s.rasterization.depthBias.clamp != 0 && !features.depthBiasClamp)
    return Status::error("depth bias clamp is not supported by the device");
  if (s.rasterization.lineWidth != 1.0f && !features.wideLines)
    return Status::error("wide lines are not supported by the device");
  if (s.blend.logicOpEnable && !features.logicOp)
    return Status::error("logic ops are not supported by the device (the logicOp feature)");
  if (s.blend.logicOp > softraster::LogicOp::Set) return Status::error("unknown logic op");
  for (std::uint32_t a = 0; a < colourAttachments; ++a) {
    const softraster::AttachmentBlend b = softraster::attachmentBlend(s, a);
    for (softraster::BlendFactor f :
         {b.srcColorBlendFactor, b.dstColorBlendFactor, b.srcAlphaBlendFactor, b.dstAlphaBlendFactor})
      if (f > softraster::BlendFactor::SrcAlphaSaturate)
        return Status::error("colour attachment " + std::to_string(a) + ": unknown blend factor");
    if (b.colorBlendOp > softraster::BlendOp::Max || b.alphaBlendOp > softraster::BlendOp::Max)
      return Status::error("colour attachment " + std::to_string(a) + ": unknown blend op");
    if (a > 0 && !features.independentBlend && !sameBlend(b, s.blend))
      return Status::error("colour attachment " + std::to_string(a) +
                           " blends unlike attachment 0, which needs the independentBlend feature the device lacks "
                           "(VUID-VkPipelineColorBlendStateCreateInfo-pAttachments-00605)");
  }
  if (s.multisample.sampleShadingEnable && !features.sampleRateShading)
    return Status::error("sample shading is not supported by the device (the sampleRateShading feature)");
  if (s.multisample.sampleShadingEnable && !(s.multisample.minSampleShading >= 0.0f && s.multisample.minSampleShading <= 1.0f))
    return Status::error("minSampleShading outside [0, 1]");
  if (s.multisample.alphaToOneEnable && !features.alphaToOne)
    return Status::error("alpha to one is not supported by the device (the alphaToOne feature)");
  if ((s.multisample.alphaToCoverageEnable || s.multisample.alphaToOneEnable) &&
      s.rasterization.lineRasterization == softraster::LineRasterization::Bresenham)
    return Status::error("alpha to coverage and alpha to one need rectangular lines (VUID-VkGraphicsPipelineCreateInfo-"
                         "lineRasterizationMode-02766)");
  if (s.rasterization.polygonMode > softraster::PolygonMode::Point) return Status::error("unsupported polygon mode");
  if (s.rasterization.polygonMode != softraster::PolygonMode::Fill && !features.fillModeNonSolid)
    return Status::error("polygon modes line and point are not supported by the device");
  if (s.rasterization.lineWidth < limits.lineWidthRange[0] || s.rasterization.lineWidth > limits.lineWidthRange[1])
    return Status::error("line width outside the device's range");
  if (s.rasterization.lineRasterization == softraster::LineRasterization::Bresenham && !device.bresenhamLines)
    return Status::error("Bresenham lines (VK_EXT_line_rasterization) are not supported by the device");
  if (s.scissor.x < 0 || s.scissor.y < 0) return Status::error("scissor offset is negative");
  if (static_cast<std::size_t>(s.rasterization.cullMode) >= std::size(kCullModes))
    return Status::error("unsupported cull mode");
  if (static_cast<std::size_t>(s.rasterization.frontFace) >= std::size(kFrontFaces))
    return Status::error("unsupported front face");
  if (s.depth.compareOp > softraster::CompareOp::Always) return Status::error("unsupported depth compare op");
  for (const softraster::StencilOpState* face : {&s.depth.front, &s.depth.back}) {
    if (face->compareOp > softraster::CompareOp::Always) return Status::error("unsupported stencil compare op");
    for (softraster::StencilOp op : {face->failOp, face->passOp, face->depthFailOp})
      if (op > softraster::StencilOp::DecrementAndWrap) return Status::error("unsupported stencil op");
  }

  const VkViewport v = viewportFor(s.viewport, width, height);
  const float* bounds = limits.viewportBoundsRange;
  if (!(v.width > 0 && v.width <= static_cast<float>(limits.maxViewportDimensions[0]) && v.height != 0 &&
        std::fabs(v.height) <= static_cast<float>(limits.maxViewportDimensions[1])))
    return Status::error("viewport size out of range");
  if (!(v.x >= bounds[0] && v.x + v.width <= bounds[1] && std::fmin(v.y, v.y + v.height) >= bounds[0] &&
        std::fmax(v.y, v.y + v.height) <= bounds[1]))
    return Status::error("viewport outside the device's viewport bounds");
  if (!(v.minDepth >= 0 && v.minDepth <= 1 && v.maxDepth >= 0 && v.maxDepth <= 1))
    return Status::error("viewport depth range outside [0, 1]");

  if (p->attributes.empty()) return {};  // the vertex shader reads no vertex buffer
  if (p->vertexStride == 0 || p->vertexStride > limits.maxVertexInputBindingStride)
    return Status::error("vertex stride " + std::to_string(p->vertexStride) + " out of range");
  for (const softraster::VertexAttribute& a : p->attributes)
    if (a.components < 1 || a.components > 4 || a.location >= limits.maxVertexInputAttributes ||
        a.offset > limits.maxVertexInputAttributeOffset || a.offset + 4 * a.components > p->vertexStride)
      return Status::error("vertex attribute at location " + std::to_string(a.location) + " does not fit the vertex");
  const std::size_t vertices = d.vertexData.size() / p->vertexStride;
  for (std::uint32_t index : d.indices)
    if (index >= vertices && !(s.primitiveRestartEnable && index == softraster::kPrimitiveRestartIndex))
      return Status::error("index " + std::to_string(index) + " out of range (" + std::to_string(vertices) +
                           " vertices)");
  return {};
}

// ---- The cache ---------------------------------------------------------------------------------

softraster::Result<std::unique_ptr<PipelineCache>> PipelineCache::create(const Device& device) {
  std::unique_ptr<PipelineCache> cache(new PipelineCache(device.device));
  const VkDescriptorSetLayoutBinding uniformBinding{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER_DYNAMIC, 1,
                                                    kPushConstantStages, nullptr};
  const VkDescriptorSetLayoutCreateInfo setInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                .bindingCount = 1,
                                                .pBindings = &uniformBinding};
  if (Status s = check(vkCreateDescriptorSetLayout(device.device, &setInfo, nullptr, &cache->setLayout_),
                       "vkCreateDescriptorSetLayout");
      !s)
    return s;
  std::array<VkDescriptorSetLayoutBinding, kMaxTextures> textureBindings{};
  for (std::uint32_t i = 0; i < kMaxTextures; ++i) {
    textureBindings[i] = {i, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr};
  }
  const VkDescriptorSetLayoutCreateInfo textureSetInfo{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                                       .bindingCount = kMaxTextures,
                                                       .pBindings = textureBindings.data()};
  if (Status s = check(vkCreateDescriptorSetLayout(device.device, &textureSetInfo, nullptr, &cache->textureSetLayout_),
                       "vkCreateDescriptorSetLayout");
      !s)
    return s;
  const std::array<VkDescriptorSetLayout, 2> setLayouts{cache->setLayout_, cache->textureSetLayout_};
  const VkPushConstantRange pushRange{kPushConstantStages, 0, kPushConstantBytes};
  const VkPipelineLayoutCreateInfo layoutInfo{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                              .setLayoutCount = 2,
                                              .pSetLayouts = setLayouts.data(),
                                              .pushConstantRangeCount = 1,
                                              .pPushConstantRanges = &pushRange};
  if (Status s = check(vkCreatePipelineLayout(device.device, &layoutInfo, nullptr, &cache->layout_),
                       "vkCreatePipelineLayout");
      !s)
    return s;
  return cache;
}

PipelineCache::~PipelineCache() {
  for (const auto& [key, pipeline] : pipelines_) vkDestroyPipeline(device_, pipeline, nullptr);
  vkDestroyPipelineLayout(device_, layout_, nullptr);
  vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
  vkDestroyDescriptorSetLayout(device_, textureSetLayout_, nullptr);
}

std::uint32_t PipelineCache::programIndex(const ShaderProgram& p, FrameMemo& memo) {
  for (const FrameMemo::Entry& e : memo.entries_) {
    const Program& known = programs_[e.program];
    if (e.vertex == p.vertexSpirv.data() && e.vertexWords == p.vertexSpirv.size() &&
        e.fragment == p.fragmentSpirv.data() && e.fragmentWords == p.fragmentSpirv.size() &&
        known.vertexStride == p.vertexStride && bytesOf(known.attributes) == bytesOf(p.attributes))
      return e.program;
  }
  const std::uint32_t index = internProgram(p);
  memo.entries_.push_back(
      {p.vertexSpirv.data(), p.vertexSpirv.size(), p.fragmentSpirv.data(), p.fragmentSpirv.size(), index});
  return index;
}

// Programs are told apart by content, not by address or name: callers make a ShaderProgram per
// draw or per frame, and an address may hold another program later.
std::uint32_t PipelineCache::internProgram(const ShaderProgram& p) {
  const std::hash<std::string_view> hash;
  std::size_t h = hash(bytesOf(p.vertexSpirv));
  h = h * 31 + hash(bytesOf(p.fragmentSpirv));
  h = h * 31 + hash(bytesOf(p.attributes));
  h = h * 31 + p.vertexStride;
  const auto same = [&](const Program& known) {
    return known.vertexStride == p.vertexStride && bytesOf(known.vertexSpirv) == bytesOf(p.vertexSpirv) &&
           bytesOf(known.fragmentSpirv) == bytesOf(p.fragmentSpirv) &&
           bytesOf(known.attributes) == bytesOf(p.attributes);
  };
  for (auto [it, end] = programsByHash_.equal_range(h); it != end; ++it)
    if (same(programs_[it->second])) return it->second;
  const auto index = static_cast<std::uint32_t>(programs_.size());
  programs_.push_back({{p.vertexSpirv.begin(), p.vertexSpirv.end()},
                       {p.fragmentSpirv.begin(), p.fragmentSpirv.end()},
                       p.attributes,
                       p.vertexStride});
  programsByHash_.emplace(h, index);
  return index;
}

softraster::Result<VkPipeline> PipelineCache::get(const DrawCall& d, const TargetFormat& target, FrameMemo& memo) {
  const softraster::PipelineState& s = d.state;
  const softraster::RasterizationState& r = s.rasterization;
  const VkViewport v = viewportFor(s.viewport, target.width, target.height);
  const VkRect2D sc = scissorFor(s.scissor, target.width, target.height);
  const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
  const auto byte = [](auto e) { return static_cast<std::uint8_t>(e); };
  Key key;
  key.program = programIndex(*d.program, memo);
  key.depthFormat = target.depthFormat;
  key.samples = target.samples;
  key.colourCount = target.colourCount;
  for (std::uint32_t a = 0; a < target.colourCount; ++a) {
    key.colourFormats[a] = target.colourFormats[a];
    const softraster::AttachmentBlend b = softraster::attachmentBlend(s, a);
    key.blends[a] = {.enable = b.enable,
                     .srcColorFactor = byte(b.srcColorBlendFactor),
                     .dstColorFactor = byte(b.dstColorBlendFactor),
                     .colorOp = byte(b.colorBlendOp),
                     .srcAlphaFactor = byte(b.srcAlphaBlendFactor),
                     .dstAlphaFactor = byte(b.dstAlphaBlendFactor),
                     .alphaOp = byte(b.alphaBlendOp),
                     .writeMask = b.colorWriteMask};
  }
  key.topology = byte(s.topology);
  key.polygonMode = byte(r.polygonMode);
  key.cullMode = byte(r.cullMode);
  key.frontFace = byte(r.frontFace);
  key.lineRasterization = byte(r.lineRasterization);
  key.primitiveRestart = s.primitiveRestartEnable;
  key.lineStipple = r.lineStipple.enable;
  key.stipplePattern = r.lineStipple.enable ? r.lineStipple.pattern : 0;
  key.stippleFactor = r.lineStipple.enable ? r.lineStipple.factor : 0;
  key.provokingLast = r.provokingVertex == softraster::ProvokingVertex::Last;
  key.depthClamp = r.depthClampEnable;
  key.depthBias = r.depthBias.enable;
  key.biasConstant = bits(r.depthBias.constantFactor);
  key.biasClamp = bits(r.depthBias.clamp);
  key.biasSlope = bits(r.depthBias.slopeFactor);
  key.lineWidth = bits(r.lineWidth);
  key.viewport = {bits(v.x), bits(v.y), bits(v.width), bits(v.height), bits(v.minDepth), bits(v.maxDepth)};
  key.scissorX = sc.offset.x;
  key.scissorY = sc.offset.y;
  key.scissorWidth = sc.extent.width;
  key.scissorHeight = sc.extent.height;
  key.depthTest = s.depth.testEnable;
  key.depthWrite = s.depth.writeEnable;
  key.depthCompare = byte(s.depth.compareOp);
  key.stencilTest = s.depth.stencilTestEnable;
  if (key.stencilTest) {  // a disabled test's faces change nothing, so they share one pipeline
    const softraster::StencilOpState* faces[2] = {&s.depth.front, &s.depth.back};
    for (std::size_t f = 0; f < 2; ++f) {
      key.stencilOps[4 * f] = byte(faces[f]->failOp);
      key.stencilOps[4 * f + 1] = byte(faces[f]->passOp);
      key.stencilOps[4 * f + 2] = byte(faces[f]->depthFailOp);
      key.stencilOps[4 * f + 3] = byte(faces[f]->compareOp);
      key.stencilValues[3 * f] = faces[f]->compareMask;
      key.stencilValues[3 * f + 1] = faces[f]->writeMask;
      key.stencilValues[3 * f + 2] = faces[f]->reference;
    }
  }
  const softraster::BlendState& b = s.blend;  // the logic op and constants every attachment shares
  key.logicOp = b.logicOpEnable ? byte(b.logicOp) : 0xff;
  key.sampleMask = s.multisample.sampleMask;
  key.alphaToCoverage = s.multisample.alphaToCoverageEnable;
  key.alphaToOne = s.multisample.alphaToOneEnable;
  key.sampleShading = s.multisample.sampleShadingEnable;
  key.minSampleShading = s.multisample.sampleShadingEnable ? bits(s.multisample.minSampleShading) : 0;
  for (int i = 0; i < 4; ++i) key.blendConstants[static_cast<std::size_t>(i)] = bits(b.blendConstants[i]);

  if (const auto found = pipelines_.find(key); found != pipelines_.end()) return found->second;
  softraster::Result<VkPipeline> pipeline = compile(programs_[key.program], s, target);
  if (pipeline) pipelines_.emplace(key, *pipeline);
  return pipeline;
}

// ---- State translation -------------------------------------------------------------------------

softraster::Result<VkPipeline> PipelineCache::compile(const Program& p, const softraster::PipelineState& state,
                                                      const TargetFormat& target) const {
  const std::vector<std::uint32_t>* code[2] = {&p.vertexSpirv, &p.fragmentSpirv};
  VkShaderModule modules[2] = {VK_NULL_HANDLE, VK_NULL_HANDLE};
  Status status;
  for (int i = 0; i < 2 && status; ++i) {
    const VkShaderModuleCreateInfo info{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                        .codeSize = code[i]->size() * sizeof(std::uint32_t),
                                        .pCode = code[i]->data()};
    status = check(vkCreateShaderModule(device_, &info, nullptr, &modules[i]), "vkCreateShaderModule");
  }
  VkPipeline pipeline = VK_NULL_HANDLE;
  if (status) {
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
        .topology = static_cast<VkPrimitiveTopology>(state.topology),  // same order as Vulkan's
        .primitiveRestartEnable = state.primitiveRestartEnable ? VK_TRUE : VK_FALSE};
    const VkViewport viewport = viewportFor(state.viewport, target.width, target.height);
    const VkRect2D scissor = scissorFor(state.scissor, target.width, target.height);
    const VkPipelineViewportStateCreateInfo viewportState{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                                          .viewportCount = 1,
                                                          .pViewports = &viewport,
                                                          .scissorCount = 1,
                                                          .pScissors = &scissor};
    const softraster::RasterizationState& r = state.rasterization;
    VkPipelineRasterizationStateCreateInfo rasterization{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .depthClampEnable = r.depthClampEnable ? VK_TRUE : VK_FALSE,
        .rasterizerDiscardEnable = VK_FALSE,
        .polygonMode = static_cast<VkPolygonMode>(r.polygonMode),  // same order as Vulkan's
        .cullMode = kCullModes[static_cast<std::size_t>(r.cullMode)],
        .frontFace = kFrontFaces[static_cast<std::size_t>(r.frontFace)],
        .depthBiasEnable = r.depthBias.enable ? VK_TRUE : VK_FALSE,
        .depthBiasConstantFactor = r.depthBias.constantFactor,
        .depthBiasClamp = r.depthBias.clamp,
        .depthBiasSlopeFactor = r.depthBias.slopeFactor,
        .lineWidth = r.lineWidth};
    // Bresenham and stippled lines need VK_EXT_line_rasterization (rectangular lines are Vulkan's
    // default, named here when stippled: strictLines is true on lavapipe); provoking vertex last
    // needs VK_EXT_provoking_vertex. Each structure is chained only when the state needs it.
    const bool bresenham = r.lineRasterization == softraster::LineRasterization::Bresenham;
    const VkPipelineRasterizationProvokingVertexStateCreateInfoEXT provoking{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_PROVOKING_VERTEX_STATE_CREATE_INFO_EXT,
        .provokingVertexMode = VK_PROVOKING_VERTEX_MODE_LAST_VERTEX_EXT};
    const bool provokingLast = r.provokingVertex == softraster::ProvokingVertex::Last;
    const VkPipelineRasterizationLineStateCreateInfoEXT lineState{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_LINE_STATE_CREATE_INFO_EXT,
        .pNext = provokingLast ? &provoking : nullptr,
        .lineRasterizationMode =
            bresenham ? VK_LINE_RASTERIZATION_MODE_BRESENHAM_EXT : VK_LINE_RASTERIZATION_MODE_RECTANGULAR_EXT,
        .stippledLineEnable = r.lineStipple.enable ? VK_TRUE : VK_FALSE,
        .lineStippleFactor = r.lineStipple.enable ? r.lineStipple.factor : 1u,
        .lineStipplePattern = r.lineStipple.enable ? r.lineStipple.pattern : std::uint16_t{0xFFFF}};
    if (bresenham || r.lineStipple.enable) {
      rasterization.pNext = &lineState;
    } else if (provokingLast) {
      rasterization.pNext = &provoking;
    }
    const VkSampleMask sampleMask = state.multisample.sampleMask;  // pSampleMask[0]: up to 32 samples
    const VkPipelineMultisampleStateCreateInfo multisample{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
        .rasterizationSamples = target.samples,
        .sampleShadingEnable = state.multisample.sampleShadingEnable ? VK_TRUE : VK_FALSE,
        .minSampleShading = state.multisample.minSampleShading,
        .pSampleMask = &sampleMask,
        .alphaToCoverageEnable = state.multisample.alphaToCoverageEnable ? VK_TRUE : VK_FALSE,
        .alphaToOneEnable = state.multisample.alphaToOneEnable ? VK_TRUE : VK_FALSE};
    // softraster's StencilOp and CompareOp are VkStencilOp and VkCompareOp values.
    const auto stencilFace = [](const softraster::StencilOpState& f) {
      return VkStencilOpState{.failOp = static_cast<VkStencilOp>(f.failOp),
                              .passOp = static_cast<VkStencilOp>(f.passOp),
                              .depthFailOp = static_cast<VkStencilOp>(f.depthFailOp),
                              .compareOp = static_cast<VkCompareOp>(f.compareOp),
                              .compareMask = f.compareMask,
                              .writeMask = f.writeMask,
                              .reference = f.reference};
    };
    const VkPipelineDepthStencilStateCreateInfo depth{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO,
        .depthTestEnable = state.depth.testEnable ? VK_TRUE : VK_FALSE,
        .depthWriteEnable = state.depth.writeEnable ? VK_TRUE : VK_FALSE,
        .depthCompareOp = static_cast<VkCompareOp>(state.depth.compareOp),
        .depthBoundsTestEnable = VK_FALSE,  // lavapipe has no depthBounds feature
        .stencilTestEnable = state.depth.stencilTestEnable ? VK_TRUE : VK_FALSE,
        .front = stencilFace(state.depth.front),
        .back = stencilFace(state.depth.back)};
    // softraster's blend enums are VkBlendFactor / VkBlendOp values, its mask VkColorComponentFlags.
    // One state per colour attachment (blend, then moreBlend); the constants and logic op are shared.
    const softraster::BlendState& b = state.blend;
    const auto factor = [](softraster::BlendFactor f) { return static_cast<VkBlendFactor>(f); };
    const auto op = [](softraster::BlendOp o) { return static_cast<VkBlendOp>(o); };
    std::array<VkPipelineColorBlendAttachmentState, softraster::kMaxColourAttachments> blendAttachments{};
    for (std::uint32_t a = 0; a < target.colourCount; ++a) {
      const softraster::AttachmentBlend ab = softraster::attachmentBlend(state, a);
      blendAttachments[a] = {.blendEnable = ab.enable ? VK_TRUE : VK_FALSE,
                             .srcColorBlendFactor = factor(ab.srcColorBlendFactor),
                             .dstColorBlendFactor = factor(ab.dstColorBlendFactor),
                             .colorBlendOp = op(ab.colorBlendOp),
                             .srcAlphaBlendFactor = factor(ab.srcAlphaBlendFactor),
                             .dstAlphaBlendFactor = factor(ab.dstAlphaBlendFactor),
                             .alphaBlendOp = op(ab.alphaBlendOp),
                             .colorWriteMask = static_cast<VkColorComponentFlags>(ab.colorWriteMask)};
    }
    VkPipelineColorBlendStateCreateInfo blend{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                              .attachmentCount = target.colourCount,
                                              .pAttachments = blendAttachments.data()};
    for (int i = 0; i < 4; ++i) blend.blendConstants[i] = b.blendConstants[i];
    // softraster's LogicOp is VkLogicOp's values.
    blend.logicOpEnable = b.logicOpEnable ? VK_TRUE : VK_FALSE;
    blend.logicOp = static_cast<VkLogicOp>(b.logicOp);
    const VkPipelineRenderingCreateInfo rendering{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                                  .colorAttachmentCount = target.colourCount,
                                                  .pColorAttachmentFormats = target.colourFormats.data(),
                                                  .depthAttachmentFormat = target.depthFormat,
                                                  .stencilAttachmentFormat =
                                                      (depthAspects(target.depthFormat) & VK_IMAGE_ASPECT_STENCIL_BIT)
                                                          ? target.depthFormat
                                                          : VK_FORMAT_UNDEFINED};
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
                                            .layout = layout_};
    status = check(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
                   "vkCreateGraphicsPipelines");
  }
  for (VkShaderModule m : modules) vkDestroyShaderModule(device_, m, nullptr);
  if (!status) return status;
  return pipeline;
}

}  // namespace vkref::detail
