// Fixed-function pipeline state shared by softraster and vkref.
// The fields mirror Vulkan's pipeline create-info structures one to one, so vkref can build a
// VkPipeline from the same value softraster draws with. A field here that one renderer cannot
// honour is an error in that renderer, never a silent default.
// 4x MSAA is supported; its sample count is the framebuffer's (framebuffer.hpp), not state here.
// Deliberately absent until a scene needs it: dual-source blending (the SRC1 blend factors, which
// need a second fragment output), smooth lines,
// geometry and tessellation shaders (so adjacency vertices are only ever skipped). The depth
// bounds test is absent for good: lavapipe reports depthBounds = false, so no Vulkan pipeline on
// it may enable it.
#pragma once

#include <array>
#include <cstdint>

namespace softraster {

enum class CullMode : std::uint8_t { None, Front, Back, FrontAndBack };
enum class FrontFace : std::uint8_t { CounterClockwise, Clockwise };
enum class CompareOp : std::uint8_t { Never, Less, Equal, LessOrEqual, Greater, NotEqual, GreaterOrEqual, Always };
// In Vulkan's order (VkPrimitiveTopology 0..9; no patch lists). Without a geometry shader the
// adjacency topologies draw their lines and triangles and ignore the adjacent vertices.
enum class Topology : std::uint8_t {
  PointList,
  LineList,
  LineStrip,
  TriangleList,
  TriangleStrip,
  TriangleFan,
  LineListWithAdjacency,
  LineStripWithAdjacency,
  TriangleListWithAdjacency,
  TriangleStripWithAdjacency,
};

// VkPipelineInputAssemblyStateCreateInfo::primitiveRestartEnable's index for 32-bit indices.
inline constexpr std::uint32_t kPrimitiveRestartIndex = 0xFFFFFFFFu;

// VkViewport: window rectangle in pixels and the depth range. A negative height flips y (Vulkan
// 1.1, VK_KHR_maintenance1): the viewport then spans y + height .. y.
struct Viewport {
  float x = 0, y = 0, width = 0, height = 0;
  float minDepth = 0, maxDepth = 1;
};

// VkRect2D; a width or height of 0 means "the whole framebuffer".
struct Scissor {
  std::int32_t x = 0, y = 0;
  std::uint32_t width = 0, height = 0;
};

// Vulkan depth bias (VkPipelineRasterizationStateCreateInfo depthBias*): triangles, filled or in
// polygon modes line and point (not line or point topologies).
struct DepthBias {
  bool enable = false;
  float constantFactor = 0, clamp = 0, slopeFactor = 0;
};

// VkPolygonMode: filled triangles, their edges as lines (wireframe) or their vertices as points.
enum class PolygonMode : std::uint8_t { Fill, Line, Point };

// VK_EXT_line_rasterization modes lavapipe supports without smoothing.
enum class LineRasterization : std::uint8_t { Rectangular, Bresenham };

// VK_EXT_line_rasterization's stipple (VkPipelineRasterizationLineStateCreateInfoEXT):
// stippledLineEnable, lineStippleFactor in [1, 256], lineStipplePattern (bit 0 first).
struct LineStipple {
  bool enable = false;
  std::uint16_t pattern = 0xFFFF;
  std::uint32_t factor = 1;
};

// VK_EXT_provoking_vertex (VkPipelineRasterizationProvokingVertexStateCreateInfoEXT): which
// vertex of a primitive gives its flat varyings. First is Vulkan's default.
enum class ProvokingVertex : std::uint8_t { First, Last };

struct RasterizationState {
  PolygonMode polygonMode = PolygonMode::Fill;
  CullMode cullMode = CullMode::Back;
  FrontFace frontFace = FrontFace::CounterClockwise;
  // Vulkan depthClampEnable: no clipping against z = 0 and z = w; fragment depth is clamped to
  // the viewport's depth range instead.
  bool depthClampEnable = false;
  DepthBias depthBias;
  float lineWidth = 1.0f;
  LineRasterization lineRasterization = LineRasterization::Rectangular;
  LineStipple lineStipple;
  ProvokingVertex provokingVertex = ProvokingVertex::First;
};

// VkStencilOp, in Vulkan's order (0..7).
enum class StencilOp : std::uint8_t {
  Keep,
  Zero,
  Replace,
  IncrementAndClamp,
  DecrementAndClamp,
  Invert,
  IncrementAndWrap,
  DecrementAndWrap,
};

// VkStencilOpState: one face's stencil test and update. Only the low 8 bits of the masks and the
// reference count (the stencil aspect has 8 bits).
struct StencilOpState {
  StencilOp failOp = StencilOp::Keep;       // the stencil test fails
  StencilOp passOp = StencilOp::Keep;       // both the stencil and the depth test pass
  StencilOp depthFailOp = StencilOp::Keep;  // the stencil test passes, the depth test fails
  CompareOp compareOp = CompareOp::Always;  // (reference & compareMask) OP (stored & compareMask)
  std::uint32_t compareMask = 0xff;
  std::uint32_t writeMask = 0xff;
  std::uint32_t reference = 0;
};

// VkPipelineDepthStencilStateCreateInfo without the depth bounds (see the top of this file).
// The stencil test needs a framebuffer with a stencil aspect (formats.hpp); without one it is
// skipped, as Vulkan skips it without a stencil attachment. `front` applies to fragments of
// front-facing triangles, `back` to those of back-facing ones; lines and points use `front`, and
// so do the lines and points of polygon modes line and point, unless the shader reads
// gl_FrontFacing (kReadsFrontFacing, shader.hpp): then they take the polygon's facing (lavapipe:
// docs/lavapipe-rules.md).
struct DepthState {
  bool testEnable = true;
  bool writeEnable = true;
  CompareOp compareOp = CompareOp::Less;
  bool stencilTestEnable = false;
  StencilOpState front;
  StencilOpState back;
};

// VkBlendFactor 0..14, in Vulkan's order (the SRC1 factors, 15..18, are absent: no dual-source
// blending).
enum class BlendFactor : std::uint8_t {
  Zero,
  One,
  SrcColor,
  OneMinusSrcColor,
  DstColor,
  OneMinusDstColor,
  SrcAlpha,
  OneMinusSrcAlpha,
  DstAlpha,
  OneMinusDstAlpha,
  ConstantColor,
  OneMinusConstantColor,
  ConstantAlpha,
  OneMinusConstantAlpha,
  SrcAlphaSaturate,
};

// VkBlendOp's core set, 0..4 in Vulkan's order (MIN and MAX ignore the factors).
enum class BlendOp : std::uint8_t { Add, Subtract, ReverseSubtract, Min, Max };

// VkLogicOp, in Vulkan's order (s: the fragment's colour converted to the attachment's format,
// d: the stored value; bitwise).
enum class LogicOp : std::uint8_t {
  Clear,         // 0
  And,           // s & d
  AndReverse,    // s & ~d
  Copy,          // s
  AndInverted,   // ~s & d
  NoOp,          // d
  Xor,           // s ^ d
  Or,            // s | d
  Nor,           // ~(s | d)
  Equivalent,    // ~(s ^ d)
  Invert,        // ~d
  OrReverse,     // s | ~d
  CopyInverted,  // ~s
  OrInverted,    // ~s | d
  Nand,          // ~(s & d)
  Set,           // all ones
};

// VkColorComponentFlagBits.
enum ColourComponent : std::uint8_t { kColourR = 1, kColourG = 2, kColourB = 4, kColourA = 8, kColourRGBA = 15 };

// The colour attachments a pipeline may write at once: lavapipe's maxColorAttachments
// (Vulkan's minimum is 4). Fragment output location i goes to colour attachment i.
inline constexpr std::uint32_t kMaxColourAttachments = 8;

// VkPipelineColorBlendAttachmentState: how one colour attachment blends. The default is blending
// off with every component written. The write mask applies with blending off too; its bits name
// R, G, B, A whatever the target's byte order.
struct AttachmentBlend {
  bool enable = false;
  BlendFactor srcColorBlendFactor = BlendFactor::One;
  BlendFactor dstColorBlendFactor = BlendFactor::Zero;
  BlendOp colorBlendOp = BlendOp::Add;
  BlendFactor srcAlphaBlendFactor = BlendFactor::One;
  BlendFactor dstAlphaBlendFactor = BlendFactor::Zero;
  BlendOp alphaBlendOp = BlendOp::Add;
  std::uint8_t colorWriteMask = kColourRGBA;  // ColourComponent bits
};

// Colour attachment 0's AttachmentBlend plus what VkPipelineColorBlendStateCreateInfo holds once
// for every attachment: blendConstants (R, G, B, A whatever the target's byte order),
// logicOpEnable and logicOp (static pipeline state). On R8G8B8A8_UNORM and B8G8R8A8_UNORM targets
// both renderers blend in 8-bit integers (fragment/colour.hpp). With logicOpEnable the logic op
// replaces blending (Vulkan: blending is then treated as disabled) and works on the stored bytes.
struct BlendState : AttachmentBlend {
  bool logicOpEnable = false;
  LogicOp logicOp = LogicOp::Copy;
  float blendConstants[4] = {0, 0, 0, 0};
};

// VkPipelineMultisampleStateCreateInfo without the sample count (the framebuffer's). sampleMask
// is pSampleMask[0]: bit s keeps sample s of every fragment (with one sample,
// bit 0; lavapipe then draws unless the whole mask is 0, a deviation: options.hpp). Alpha to
// coverage keeps the samples the shader's alpha covers (lavapipe: with 4x MSAA sample s where
// alpha > s / 4, with one sample alpha > 0.5; fragment/coverage.hpp); alpha to one then sets the
// alpha to 1 before blending. Sample shading with
// ceil(4 * minSampleShading) > 1 (4x MSAA) runs the fragment shader once per covered sample
// (lavapipe: on every sample, whatever the fraction; the varyings stay at the pixel centre, the
// fragment built-ins move to the sample: fragment/coverage.hpp).
struct MultisampleState {
  std::uint32_t sampleMask = 0xFFFFFFFFu;
  bool alphaToCoverageEnable = false;
  bool alphaToOneEnable = false;
  bool sampleShadingEnable = false;
  float minSampleShading = 0.0f;  // in [0, 1]
};

struct PipelineState {
  Topology topology = Topology::TriangleList;
  // VkPipelineInputAssemblyStateCreateInfo::primitiveRestartEnable: in an indexed draw the index
  // kPrimitiveRestartIndex ends the strip or fan and starts a new one (strip and fan topologies
  // only: lists need the primitiveTopologyListRestart feature, which vkref does not enable).
  bool primitiveRestartEnable = false;
  Viewport viewport;  // width/height 0 means "the whole framebuffer"
  Scissor scissor;
  RasterizationState rasterization;
  DepthState depth;
  BlendState blend;  // colour attachment 0's, and the constants and logic op of every attachment
  // Colour attachments 1.. of a framebuffer with several (moreBlend[i] for attachment i + 1);
  // entries past the framebuffer's attachments are not read.
  std::array<AttachmentBlend, kMaxColourAttachments - 1> moreBlend{};
  MultisampleState multisample;
};

// Colour attachment `attachment`'s whole blend state: its AttachmentBlend with the pipeline's
// constants and logic op (blend's).
inline BlendState attachmentBlend(const PipelineState& state, std::uint32_t attachment) {
  BlendState b = state.blend;
  if (attachment > 0) static_cast<AttachmentBlend&>(b) = state.moreBlend[attachment - 1];
  return b;
}

}  // namespace softraster
