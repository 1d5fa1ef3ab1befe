// What depth_tiles_test.cpp and pass_test.cpp share: a shader of interpolated vertex colours, the
// check that every depth tile's bounds hold every stored depth, and random draws over every depth
// compare op, depth writes on and off, bias, clamp, scissors and (with a stencil aspect) stencil.
#pragma once

#include <softraster/detail/fast/depth_tiles.hpp>
#include <softraster/pipeline.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace random_draws {

// The colour of each vertex interpolated, red scaled by the uniforms' alpha (a kept draw must be
// drawn with its own copy of them), shaded in batches.
struct Colour {
  struct Vertex {
    softraster::Vec3 position;
    softraster::Vec4 colour;
  };
  struct Uniforms {
    float alpha = 1;
  };
  static constexpr int kVaryings = 4;
  static softraster::Vec4 vertex(const Uniforms&, const Vertex& v, float* out) {
    out[0] = v.colour.x, out[1] = v.colour.y, out[2] = v.colour.z, out[3] = v.colour.w;
    return {v.position.x, v.position.y, v.position.z, 1.0f};
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* in) {
    return {in[0] * u.alpha, in[1], in[2], in[3]};
  }
};

inline bool fastPathHere() {
#if SOFTRASTER_HAS_FAST_PATH
  return softraster::detail::fast::cpuRunsFastPath();
#else
  return false;
#endif
}

// Every tile's bounds hold every depth stored in it.
inline void expectTilesHold(softraster::Framebuffer& framebuffer, const std::string& where) {
  using softraster::detail::FramebufferAccess;
  using softraster::detail::kDepthTileSize;
  const auto tiles = FramebufferAccess::depthTiles(framebuffer);
  const std::uint32_t* depth = FramebufferAccess::depthWords(framebuffer);
  const std::uint32_t perRow = FramebufferAccess::depthTilesPerRow(framebuffer);
  for (std::uint32_t y = 0; y < framebuffer.height(); ++y) {
    for (std::uint32_t x = 0; x < framebuffer.width(); ++x) {
      const softraster::detail::DepthTileRange& t = tiles[(y / kDepthTileSize) * perRow + x / kDepthTileSize];
      const float key = softraster::detail::depthTileKey(framebuffer.depthFormat(), depth[y * framebuffer.width() + x]);
      if (!(t.lo <= key && key <= t.hi)) {
        ADD_FAILURE() << where << ": pixel (" << x << ", " << y << ") key " << key << " outside its tile's [" << t.lo
                      << ", " << t.hi << "]";
        return;
      }
    }
  }
}

// Two triangles covering the viewport at depth z (a flat quad), in colour c.
inline std::vector<Colour::Vertex> quad(float z, softraster::Vec4 c) {
  return {{{-1, -1, z}, c}, {{1, -1, z}, c}, {{1, 1, z}, c}, {{-1, -1, z}, c}, {{1, 1, z}, c}, {{-1, 1, z}, c}};
}

struct RandomDraw {
  softraster::PipelineState state;
  std::vector<Colour::Vertex> vertices;
  float alpha = 1;
};

// One draw into a width x height framebuffer of `format`: a flat quad at one of a few levels
// (so that depths meet exactly), or one to four triangles anywhere, some vertices at the levels.
inline RandomDraw randomDraw(std::mt19937& random, softraster::DepthFormat format, std::uint32_t width,
                             std::uint32_t height) {
  using softraster::CompareOp;
  const CompareOp ops[] = {CompareOp::Never,   CompareOp::Less,     CompareOp::Equal,          CompareOp::LessOrEqual,
                           CompareOp::Greater, CompareOp::NotEqual, CompareOp::GreaterOrEqual, CompareOp::Always};
  const float levels[] = {0.125f, 0.25f, 0.5f, 0.75f, 1.0f};
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  RandomDraw d;
  softraster::PipelineState& state = d.state;
  state.rasterization.cullMode = softraster::CullMode::None;
  state.depth.compareOp = ops[random() % 8];
  state.depth.writeEnable = random() % 4 != 0;
  state.depth.testEnable = random() % 10 != 0;
  if (random() % 5 == 0) {
    state.rasterization.depthBias = {true, static_cast<float>(random() % 200) - 100.0f, 0.0f, unit(random) * 4 - 2};
  }
  if (random() % 5 == 0) {
    state.rasterization.depthClampEnable = true;
    state.viewport = {0, 0, static_cast<float>(width), static_cast<float>(height), 0.2f + 0.2f * unit(random),
                      0.6f + 0.3f * unit(random)};
  }
  if (random() % 4 == 0) {
    state.scissor = {static_cast<std::int32_t>(random() % 60), static_cast<std::int32_t>(random() % 60),
                     static_cast<std::uint32_t>(40 + random() % 120), static_cast<std::uint32_t>(40 + random() % 100)};
  }
  if (softraster::hasStencil(format) && random() % 2 == 0) {
    state.depth.stencilTestEnable = true;
    state.depth.front.passOp = softraster::StencilOp::IncrementAndClamp;
    state.depth.front.depthFailOp = softraster::StencilOp::Invert;
    state.depth.back = state.depth.front;
  }
  const softraster::Vec4 c{unit(random), unit(random), unit(random), 1};
  if (random() % 3 == 0) {
    d.vertices = quad(levels[random() % 5], c);
  } else {
    for (int v = 0; v < 3 * (1 + static_cast<int>(random() % 4)); ++v) {
      const float z = random() % 3 == 0 ? levels[random() % 5] : -0.1f + 1.2f * unit(random);
      d.vertices.push_back({{-2.0f + 4.0f * unit(random), -2.0f + 4.0f * unit(random), z}, c});
    }
  }
  d.alpha = 0.25f + 0.75f * unit(random);
  return d;
}

}  // namespace random_draws
