// vkref pipelines: softraster::PipelineState translated into a Vulkan graphics pipeline, the
// checks of what Vulkan on this device cannot express (each an error, never a silent default),
// and the cache that compiles each pipeline once per Renderer, keyed by (program, state, target
// formats, samples), and keeps it for every later draw and frame. A pipeline writes every colour
// attachment of its frame (fragment output location i to attachment i), each blended by its own
// AttachmentBlend (PipelineState::blend, then moreBlend), or none in a depth pass.
// Deliberately no dynamic state (viewport and scissor are baked, as the state gives them), no
// eviction (a Renderer sees a few dozen distinct pipelines) and no VkPipelineCache (nothing is
// written to disk). Recording the draws is passes' job.
#pragma once

#include "device.hpp"

#include <vkref/frame.hpp>

#include <softraster/status.hpp>

#include <vulkan/vulkan.h>

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace vkref::detail {

inline constexpr std::uint32_t kPushConstantBytes = 128;
inline constexpr VkShaderStageFlags kPushConstantStages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;

// Vertices in a draw's vertexData (whole vertices of its program's stride).
std::uint32_t vertexCount(const DrawCall& draw);
// A draw with nothing to assemble: skipped, and so not checked either.
bool isEmpty(const DrawCall& draw);

// What about the frame (size, clear depth, colour attachments and their formats, depth format,
// samples) the device cannot honour.
softraster::Status checkFrame(const FrameRequest& request, const Device& device);
// What about a draw into a width x height frame with `colourAttachments` colour attachments
// (0 in a depth pass) Vulkan (or this renderer) cannot honour.
softraster::Status checkDraw(const DrawCall& draw, std::uint32_t width, std::uint32_t height,
                             std::uint32_t colourAttachments, const Device& device);

// What a pipeline is compiled for besides its draw: the frame's size (a zero viewport or scissor
// means the whole frame), its colour attachments (colourFormats[0, colourCount); a depth pass has
// none), depth format and sample count.
struct TargetFormat {
  std::uint32_t width = 0, height = 0;
  std::uint32_t colourCount = 1;
  std::array<VkFormat, softraster::kMaxColourAttachments> colourFormats{VK_FORMAT_R8G8B8A8_UNORM};
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

class PipelineCache {
 public:
  static softraster::Result<std::unique_ptr<PipelineCache>> create(const Device& device);
  ~PipelineCache();  // destroys every pipeline and the layout; no frame may still use them
  PipelineCache(const PipelineCache&) = delete;
  PipelineCache& operator=(const PipelineCache&) = delete;

  // Which known program the SPIR-V at an address holds, remembered for one prepare() only: the
  // request cannot change while it is prepared, so the same spans mean the same code, and each
  // program's code is hashed and compared once per frame instead of once per draw. Not kept
  // across frames, where an address may hold other code.
  class FrameMemo {
    friend class PipelineCache;
    struct Entry {
      const std::uint32_t* vertex;
      std::size_t vertexWords;
      const std::uint32_t* fragment;
      std::size_t fragmentWords;
      std::uint32_t program;
    };
    std::vector<Entry> entries_;
  };

  // The one layout of every pipeline: kPushConstantBytes of push constants; set 0, whose
  // binding 0 is a dynamic uniform buffer (a draw's uniform block) for both stages; set 1, whose
  // bindings 0..kMaxTextures-1 are combined image samplers (a draw's textures) for the fragment stage.
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSetLayout uniformSetLayout() const { return setLayout_; }
  VkDescriptorSetLayout textureSetLayout() const { return textureSetLayout_; }
  // The pipeline for a checked draw (see checkDraw), compiled on its first use.
  softraster::Result<VkPipeline> get(const DrawCall& draw, const TargetFormat& target, FrameMemo& memo);
  std::size_t size() const { return pipelines_.size(); }

 private:
  // A program as the cache knows it: a copy of its code and vertex layout, so an entry never
  // depends on memory the caller owns.
  struct Program {
    std::vector<std::uint32_t> vertexSpirv, fragmentSpirv;
    std::vector<softraster::VertexAttribute> attributes;
    std::uint32_t vertexStride = 0;
  };
  // Everything a pipeline is built from, floats by their bits (so NaN keys match themselves),
  // viewport and scissor as resolved against the frame size.
  struct Key {
    std::uint32_t program = 0;  // index into programs_
    VkFormat depthFormat = VK_FORMAT_UNDEFINED;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    std::uint32_t colourCount = 1;
    std::array<VkFormat, softraster::kMaxColourAttachments> colourFormats{};  // UNDEFINED past colourCount
    std::uint8_t topology = 0, polygonMode = 0, cullMode = 0, frontFace = 0, lineRasterization = 0;
    bool primitiveRestart = false, lineStipple = false, provokingLast = false;
    std::uint16_t stipplePattern = 0;
    std::uint32_t stippleFactor = 0;
    bool depthClamp = false, depthBias = false;
    std::uint32_t biasConstant = 0, biasClamp = 0, biasSlope = 0, lineWidth = 0;
    std::array<std::uint32_t, 6> viewport{};  // x, y, width, height, minDepth, maxDepth
    std::int32_t scissorX = 0, scissorY = 0;
    std::uint32_t scissorWidth = 0, scissorHeight = 0;
    bool depthTest = false, depthWrite = false;
    std::uint8_t depthCompare = 0;
    bool stencilTest = false;
    // front then back: failOp, passOp, depthFailOp, compareOp; compareMask, writeMask, reference
    std::array<std::uint8_t, 8> stencilOps{};
    std::array<std::uint32_t, 6> stencilValues{};
    // One colour attachment's AttachmentBlend.
    struct Blend {
      bool enable = false;
      std::uint8_t srcColorFactor = 0, dstColorFactor = 0, colorOp = 0, srcAlphaFactor = 0, dstAlphaFactor = 0,
                   alphaOp = 0, writeMask = 0;
      auto operator<=>(const Blend&) const = default;
    };
    std::array<Blend, softraster::kMaxColourAttachments> blends{};  // default past colourCount
    std::uint8_t logicOp = 0xff;  // VkLogicOp, 0xff: logicOpEnable off
    std::uint32_t sampleMask = 0;  // VkPipelineMultisampleStateCreateInfo
    bool alphaToCoverage = false, alphaToOne = false, sampleShading = false;
    std::uint32_t minSampleShading = 0;  // by its bits
    std::array<std::uint32_t, 4> blendConstants{};  // by their bits
    auto operator<=>(const Key&) const = default;
  };

  explicit PipelineCache(VkDevice device) : device_(device) {}
  std::uint32_t programIndex(const ShaderProgram& program, FrameMemo& memo);
  std::uint32_t internProgram(const ShaderProgram& program);
  softraster::Result<VkPipeline> compile(const Program& program, const softraster::PipelineState& state,
                                         const TargetFormat& target) const;

  VkDevice device_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout textureSetLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  std::vector<Program> programs_;
  std::unordered_multimap<std::size_t, std::uint32_t> programsByHash_;
  std::map<Key, VkPipeline> pipelines_;
};

}  // namespace vkref::detail
