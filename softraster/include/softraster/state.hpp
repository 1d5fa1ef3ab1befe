// Fixed-function pipeline state shared by softraster and vkref.
// The fields mirror Vulkan's pipeline create-info structures one to one, so vkref can build a
// VkPipeline from the same value softraster draws with. A field here that one renderer cannot
// honour is an error in that renderer, never a silent default.
// Deliberately absent until a scene needs it: blending, stencil, MSAA, polygon modes, depth bias.
#pragma once

#include <cstdint>

namespace softraster {

enum class CullMode : std::uint8_t { None, Front, Back, FrontAndBack };
enum class FrontFace : std::uint8_t { CounterClockwise, Clockwise };
enum class CompareOp : std::uint8_t { Never, Less, Equal, LessOrEqual, Greater, NotEqual, GreaterOrEqual, Always };
enum class Topology : std::uint8_t { TriangleList };

// VkViewport: window rectangle in pixels and the depth range.
struct Viewport {
  float x = 0, y = 0, width = 0, height = 0;
  float minDepth = 0, maxDepth = 1;
};

struct RasterizationState {
  CullMode cullMode = CullMode::Back;
  FrontFace frontFace = FrontFace::CounterClockwise;
};

struct DepthState {
  bool testEnable = true;
  bool writeEnable = true;
  CompareOp compareOp = CompareOp::Less;
};

struct PipelineState {
  Topology topology = Topology::TriangleList;
  Viewport viewport;  // width/height 0 means "the whole framebuffer"
  RasterizationState rasterization;
  DepthState depth;
};

}  // namespace softraster
