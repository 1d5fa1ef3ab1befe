// softraster's entry point: a Context draws indexed triangle lists with a shader type into a
// Framebuffer, following lavapipe's rules to the bit (the "exact" method):
//   vertex processing -> primitive assembly -> clipping -> snapping and setup -> rasterization
//   -> interpolation -> fragment shading -> depth test and writes.
// A Context holds no global state and reports errors through Status; it never prints.
// Deliberately absent from this slice: other topologies, blending, MSAA, alternative
// rasterization methods.
#pragma once

#include <softraster/detail/clipping.hpp>
#include <softraster/detail/fused_multiply_add.hpp>
#include <softraster/detail/interpolation.hpp>
#include <softraster/detail/output_merger.hpp>
#include <softraster/detail/primitive_assembly.hpp>
#include <softraster/detail/rasterizer.hpp>
#include <softraster/detail/triangle_setup.hpp>
#include <softraster/detail/vertex_processing.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>
#include <softraster/status.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace softraster {

struct ContextOptions {
  // How lavapipe's fmuladd rounds on the machine being matched: fused where the CPU has FMA.
  bool fusedMultiplyAdd = detail::cpuHasFma();
};

class Context {
 public:
  explicit Context(ContextOptions options = {}) : options_(options) {}

  const ContextOptions& options() const { return options_; }

  // Draws an indexed triangle list. Trailing indices that do not form a triangle are ignored,
  // as Vulkan does; an index past the end of `vertices` is an error and nothing is drawn.
  template <class Shader>
  Status draw(const PipelineState& state, const typename Shader::Uniforms& uniforms,
              std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
              Framebuffer& framebuffer) const {
    static_assert(Shader::kVaryings >= 0 && Shader::kVaryings <= kMaxVaryings, "too many varyings");
    if (framebuffer.width() == 0 || framebuffer.height() == 0) return Status::error("framebuffer has no pixels");
    if (state.topology != Topology::TriangleList) return Status::error("only triangle lists are supported");
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= vertices.size()) {
        return Status::error("index " + std::to_string(i) + " (" + std::to_string(indices[i]) +
                             ") is past the last vertex (" + std::to_string(vertices.size()) + " vertices)");
      }
    }
    if (options_.fusedMultiplyAdd) {
      drawTriangles<Shader, true>(state, uniforms, vertices, indices, framebuffer);
    } else {
      drawTriangles<Shader, false>(state, uniforms, vertices, indices, framebuffer);
    }
    return {};
  }

 private:
  template <class Shader, bool Fused>
  static void drawTriangles(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                            std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                            Framebuffer& framebuffer);

  template <class Shader, bool Fused>
  static void rasterize(const detail::ShadedVertex<Shader::kVaryings>& a, const detail::ShadedVertex<Shader::kVaryings>& b,
                        const detail::ShadedVertex<Shader::kVaryings>& c, const PipelineState& state,
                        const detail::WindingFilter& winding, const detail::PixelRect& region,
                        const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer);

  ContextOptions options_;
};

// The viewport the state names, or the whole framebuffer when its size is 0.
inline Viewport resolveViewport(const Viewport& vp, const Framebuffer& fb) {
  if (vp.width != 0 && vp.height != 0) return vp;
  Viewport full = vp;
  full.x = 0;
  full.y = 0;
  full.width = static_cast<float>(fb.width());
  full.height = static_cast<float>(fb.height());
  return full;
}

// Pixels a draw may touch: framebuffer and viewport rectangle, as lavapipe rounds the latter.
inline detail::PixelRect drawRegion(const Viewport& vp, const Framebuffer& fb) {
  const detail::PixelRect viewportRect{static_cast<int>(vp.x + 0.499f), static_cast<int>(vp.y + 0.499f),
                                       static_cast<int>(vp.x + vp.width - 0.501f),
                                       static_cast<int>(vp.y + vp.height - 0.501f)};
  const detail::PixelRect framebufferRect{0, 0, static_cast<int>(fb.width()) - 1, static_cast<int>(fb.height()) - 1};
  return detail::intersect(viewportRect, framebufferRect);
}

template <class Shader, bool Fused>
void Context::drawTriangles(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                            std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                            Framebuffer& framebuffer) {
  constexpr int N = Shader::kVaryings;
  const Viewport viewport = resolveViewport(state.viewport, framebuffer);
  const detail::ViewportTransform transform = detail::makeViewportTransform(viewport);
  const detail::PixelRect region = drawRegion(viewport, framebuffer);
  const detail::WindingFilter winding = detail::windingFilter(state.rasterization);
  if (region.empty() || (!winding.drawClockwise && !winding.drawCounterClockwise)) return;

  std::vector<detail::ShadedVertex<N>> shaded(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    shaded[i] = detail::shadeVertex<Shader, Fused>(uniforms, vertices[i], transform);
  }

  const std::size_t usable = indices.size() - indices.size() % 3;
  detail::ClippedPolygon<N> polygon;
  for (std::size_t start = 0; start < usable; start += detail::kBatchIndices) {
    const auto batch = indices.subspan(start, std::min(detail::kBatchIndices, usable - start));
    const bool throughDrawPipeline = detail::batchNeedsClipping(batch, shaded);
    for (std::size_t t = 0; t + 2 < batch.size(); t += 3) {
      const auto& v0 = shaded[batch[t]];
      const auto& v1 = shaded[batch[t + 1]];
      const auto& v2 = shaded[batch[t + 2]];
      if (!throughDrawPipeline) {
        rasterize<Shader, Fused>(v0, v1, v2, state, winding, region, uniforms, framebuffer);
        continue;
      }
      const std::uint32_t outside = v0.clipMask | v1.clipMask | v2.clipMask;
      if (outside == 0) {
        if (detail::survivesPipelineCull(v0.window, v1.window, v2.window, state.rasterization)) {
          rasterize<Shader, Fused>(v0, v1, v2, state, winding, region, uniforms, framebuffer);
        }
        continue;
      }
      if ((v0.clipMask & v1.clipMask & v2.clipMask) != 0) continue;  // entirely outside one plane
      if (!detail::clipTriangle(v0, v1, v2, outside, transform, polygon)) continue;
      for (int i = 2; i < polygon.count; ++i) {
        const auto& p0 = polygon.vertices[0];
        const auto& p1 = polygon.vertices[i - 1];
        const auto& p2 = polygon.vertices[i];
        if (detail::survivesPipelineCull(p0.window, p1.window, p2.window, state.rasterization)) {
          rasterize<Shader, Fused>(p0, p1, p2, state, winding, region, uniforms, framebuffer);
        }
      }
    }
  }
}

template <class Shader, bool Fused>
void Context::rasterize(const detail::ShadedVertex<Shader::kVaryings>& a, const detail::ShadedVertex<Shader::kVaryings>& b,
                        const detail::ShadedVertex<Shader::kVaryings>& c, const PipelineState& state,
                        const detail::WindingFilter& winding, const detail::PixelRect& region,
                        const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer) {
  constexpr int N = Shader::kVaryings;
  detail::FixedTriangle fixed = detail::snapTriangle(a.window, b.window, c.window);
  const int area = detail::fixedAreaSign(fixed);
  if (area == 0) return;
  if (area > 0 ? !winding.drawCounterClockwise : !winding.drawClockwise) return;

  // From here on the triangle is counter-clockwise: a negative one continues as (a, c, b).
  const detail::ShadedVertex<N>& v0 = a;
  const detail::ShadedVertex<N>& v1 = area > 0 ? b : c;
  const detail::ShadedVertex<N>& v2 = area > 0 ? c : b;
  if (area < 0) {
    std::swap(fixed.x[1], fixed.x[2]);
    std::swap(fixed.y[1], fixed.y[2]);
  }
  const detail::TriangleEdges edges = detail::setupEdges(fixed);
  const detail::TriangleInterpolants<N> interpolants = detail::setupInterpolants(v0, v1, v2);

  const std::uint32_t width = framebuffer.width();
  std::uint8_t* colour = framebuffer.colour().data();
  float* depth = framebuffer.depth().data();
  const DepthState& ds = state.depth;
  std::array<float, (N == 0 ? 1 : N)> varyings{};
  detail::rasterizeTriangle(edges, region, [&](int px, int py) {
    const float fx = static_cast<float>(px), fy = static_cast<float>(py);
    const std::size_t pixel = static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px);
    const float z = detail::clampDepth(detail::interpolateDepth<Fused>(interpolants, fx, fy));
    if (ds.testEnable && !detail::depthTestPasses(ds.compareOp, z, depth[pixel])) return;
    detail::interpolateVaryings<Fused>(interpolants, fx, fy, varyings.data());
    detail::storeColour(colour + 4 * pixel, Shader::fragment(uniforms, varyings.data()));
    if (ds.testEnable && ds.writeEnable) depth[pixel] = z;
  });
}

}  // namespace softraster
