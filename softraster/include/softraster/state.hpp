// Fixed-function pipeline state shared by softraster and vkref.
// The fields mirror Vulkan's pipeline create-info structures one to one, so vkref can build a
// VkPipeline from the same value softraster draws with. A field here that one renderer cannot
// honour is an error in that renderer, never a silent default.
// The sample count is the framebuffer's (framebuffer.hpp), not state here.
// Deliberately absent until a scene needs it: blend factors other than ZERO and ONE, stencil,
// multisample state (sample shading, sample mask, alpha to coverage), smooth and stippled lines.
#pragma once

#include <cstdint>

namespace softraster {

enum class CullMode : std::uint8_t { None, Front, Back, FrontAndBack };
enum class FrontFace : std::uint8_t { CounterClockwise, Clockwise };
enum class CompareOp : std::uint8_t { Never, Less, Equal, LessOrEqual, Greater, NotEqual, GreaterOrEqual, Always };
// In Vulkan's order (VkPrimitiveTopology 0..5).
enum class Topology : std::uint8_t { PointList, LineList, LineStrip, TriangleList, TriangleStrip, TriangleFan };

// VkViewport: window rectangle in pixels and the depth range.
struct Viewport {
  float x = 0, y = 0, width = 0, height = 0;
  float minDepth = 0, maxDepth = 1;
};

// VkRect2D; a width or height of 0 means "the whole framebuffer".
struct Scissor {
  std::int32_t x = 0, y = 0;
  std::uint32_t width = 0, height = 0;
};

// Vulkan depth bias (VkPipelineRasterizationStateCreateInfo depthBias*), triangles only.
struct DepthBias {
  bool enable = false;
  float constantFactor = 0, clamp = 0, slopeFactor = 0;
};

// VkPolygonMode: filled triangles, their edges as lines (wireframe) or their vertices as points.
enum class PolygonMode : std::uint8_t { Fill, Line, Point };

// VK_EXT_line_rasterization modes lavapipe supports without smoothing.
enum class LineRasterization : std::uint8_t { Rectangular, Bresenham };

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
};

struct DepthState {
  bool testEnable = true;
  bool writeEnable = true;
  CompareOp compareOp = CompareOp::Less;
};

// Colour blending with op ADD; the same factors for colour and alpha. With ZERO and ONE the UNORM8
// result is exact in both renderers: a saturating 8-bit add (additive blending counts fragments).
enum class BlendFactor : std::uint8_t { Zero, One };

struct BlendState {
  bool enable = false;
  BlendFactor source = BlendFactor::One;
  BlendFactor destination = BlendFactor::Zero;
};

struct PipelineState {
  Topology topology = Topology::TriangleList;
  Viewport viewport;  // width/height 0 means "the whole framebuffer"
  Scissor scissor;
  RasterizationState rasterization;
  DepthState depth;
  BlendState blend;
};

}  // namespace softraster
