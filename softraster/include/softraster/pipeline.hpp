// softraster's entry point: a Context draws points, lines and triangles (lists, strips, fans),
// indexed or not, with a shader type into a Framebuffer, following lavapipe's rules to the bit
// (the "exact" method):
//   vertex processing -> primitive assembly -> clipping -> snapping and setup -> rasterization
//   -> interpolation -> fragment shading -> depth test and writes.
// A Context holds no global state and reports errors through Status; it never prints.
// Polygon modes line and point go through the draw-pipeline path for every triangle (clip,
// float cull, then Mesa's "unfilled" stage: each original edge as a line, each original vertex as
// a point), as lavapipe does; in point mode x and y are clipped at 2w (measured).
// 4x MSAA: filled triangles only (coverage and depth per sample, one shading per pixel);
// Framebuffer::resolve() resolves as lavapipe does.
// Deliberately absent from this slice: MSAA lines, points and polygon modes, depth bias in
// polygon modes, blend factors beyond ZERO/ONE, alternative rasterization methods.
#pragma once

#include <softraster/detail/clipping.hpp>
#include <softraster/detail/fused_multiply_add.hpp>
#include <softraster/detail/interpolation.hpp>
#include <softraster/detail/line_point_setup.hpp>
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
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace softraster {

// What the depth buffer holds.
//   Vulkan:   window z (z/w mapped to the viewport's depth range), as Vulkan and lavapipe do.
//   InverseZ: the course's 1/z buffer: 1/w (w = camera-space depth for perspective cameras),
//             interpolated linearly in screen space; NOT a Vulkan mode, so it is never
//             cross-checked bit for bit, only charted. Clear the depth buffer to 0 (infinitely
//             far); compare ops keep their meaning in distance (LESS passes the nearer fragment,
//             i.e. the larger 1/z). Needs D32_SFLOAT; the viewport depth range does not apply.
enum class DepthMode : std::uint8_t { Vulkan, InverseZ };

struct ContextOptions {
  // How lavapipe's fmuladd rounds on the machine being matched: fused where the CPU has FMA.
  bool fusedMultiplyAdd = detail::cpuHasFma();
  DepthMode depthMode = DepthMode::Vulkan;
};

class Context {
 public:
  explicit Context(ContextOptions options = {}) : options_(options) {}

  const ContextOptions& options() const { return options_; }

  // vkCmdDraw: vertices 0..n-1 in order, assembled by state.topology.
  template <class Shader>
  Status draw(const PipelineState& state, const typename Shader::Uniforms& uniforms,
              std::span<const typename Shader::Vertex> vertices, Framebuffer& framebuffer) const {
    std::vector<std::uint32_t> sequence(vertices.size());
    for (std::size_t i = 0; i < sequence.size(); ++i) sequence[i] = static_cast<std::uint32_t>(i);
    return drawPrimitives<Shader>(state, uniforms, vertices, sequence, framebuffer);
  }

  // vkCmdDrawIndexed. An index past the end of `vertices` is an error and nothing is drawn.
  // Indices that do not complete a primitive are ignored, as Vulkan does.
  template <class Shader>
  Status drawIndexed(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                     std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                     Framebuffer& framebuffer) const {
    for (std::size_t i = 0; i < indices.size(); ++i) {
      if (indices[i] >= vertices.size()) {
        return Status::error("index " + std::to_string(i) + " (" + std::to_string(indices[i]) +
                             ") is past the last vertex (" + std::to_string(vertices.size()) + " vertices)");
      }
    }
    return drawPrimitives<Shader>(state, uniforms, vertices, indices, framebuffer);
  }

 private:
  template <class Shader>
  Status drawPrimitives(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                        std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                        Framebuffer& framebuffer) const;

  template <class Shader, bool Fused, DepthFormat Format>
  void drawWithFormat(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                      std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                      Framebuffer& framebuffer) const;

  // The fused path, compiled for CPUs with FMA so that std::fma is one instruction instead of a
  // library call (it is only taken where the CPU has FMA; results are the same either way).
  template <class Shader, DepthFormat Format>
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("fma"), gnu::flatten]]
#endif
  void drawFused(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                 std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                 Framebuffer& framebuffer) const {
    drawWithFormat<Shader, true, Format>(state, uniforms, vertices, indices, framebuffer);
  }

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

// Pixels a draw may touch (lavapipe's draw region): framebuffer ∩ scissor ∩ the viewport
// rectangle [(int)(x + 0.499), (int)(x + width - 0.501)] (lavapipe sets point_tri_clip, which
// scissors every primitive to the viewport).
inline detail::PixelRect drawRegion(const Scissor& scissor, const Viewport& vp, const Framebuffer& fb) {
  detail::PixelRect region{0, 0, static_cast<int>(fb.width()) - 1, static_cast<int>(fb.height()) - 1};
  if (scissor.width != 0 && scissor.height != 0) {
    region = detail::intersect(region, {scissor.x, scissor.y, scissor.x + static_cast<int>(scissor.width) - 1,
                                        scissor.y + static_cast<int>(scissor.height) - 1});
  }
  const float top = std::fmin(vp.y, vp.y + vp.height), bottom = std::fmax(vp.y, vp.y + vp.height);
  return detail::intersect(region, {static_cast<int>(vp.x + 0.499f), static_cast<int>(top + 0.499f),
                                    static_cast<int>(vp.x + vp.width - 0.501f), static_cast<int>(bottom - 0.501f)});
}

template <class Shader>
Status Context::drawPrimitives(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                               std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                               Framebuffer& framebuffer) const {
  static_assert(Shader::kVaryings >= 0 && Shader::kVaryings <= kMaxVaryings, "too many varyings");
  if (framebuffer.width() == 0 || framebuffer.height() == 0) return Status::error("framebuffer has no pixels");
  if (state.topology > Topology::TriangleFan) return Status::error("unknown topology");
  if (options_.depthMode == DepthMode::InverseZ && framebuffer.depthFormat() != DepthFormat::D32Sfloat) {
    return Status::error("the 1/z depth buffer needs a D32_SFLOAT framebuffer");
  }
  if (framebuffer.samples() != 1 && framebuffer.samples() != 4) return Status::error("framebuffers have 1 or 4 samples");
  if (framebuffer.samples() == 4 &&
      (!detail::isTriangleTopology(state.topology) || state.rasterization.polygonMode != PolygonMode::Fill ||
       options_.depthMode != DepthMode::Vulkan)) {
    return Status::error("softraster draws only filled triangles with 4x MSAA so far");
  }
  if (!(state.rasterization.lineWidth >= 1.0f)) return Status::error("line width must be at least 1");
  if (state.rasterization.polygonMode != PolygonMode::Fill && state.rasterization.depthBias.enable) {
    return Status::error("depth bias with polygon mode line or point is not supported by softraster yet");
  }
  const bool fused = options_.fusedMultiplyAdd;
  switch (framebuffer.depthFormat()) {
    case DepthFormat::D16Unorm:
      fused ? drawFused<Shader, DepthFormat::D16Unorm>(state, uniforms, vertices, indices, framebuffer)
            : drawWithFormat<Shader, false, DepthFormat::D16Unorm>(state, uniforms, vertices, indices, framebuffer);
      break;
    case DepthFormat::X8D24UnormPack32:
      fused ? drawFused<Shader, DepthFormat::X8D24UnormPack32>(state, uniforms, vertices, indices, framebuffer)
            : drawWithFormat<Shader, false, DepthFormat::X8D24UnormPack32>(state, uniforms, vertices, indices, framebuffer);
      break;
    case DepthFormat::D32Sfloat:
      fused ? drawFused<Shader, DepthFormat::D32Sfloat>(state, uniforms, vertices, indices, framebuffer)
            : drawWithFormat<Shader, false, DepthFormat::D32Sfloat>(state, uniforms, vertices, indices, framebuffer);
      break;
  }
  return {};
}

template <class Shader, bool Fused, DepthFormat Format>
void Context::drawWithFormat(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                             std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                             Framebuffer& framebuffer) const {
  constexpr int N = Shader::kVaryings;
  constexpr InterpolationSet<N> interpolation = interpolationOf<Shader>();
  using Vertex = detail::ShadedVertex<N>;
  const RasterizationState& rs = state.rasterization;
  const Viewport viewport = resolveViewport(state.viewport, framebuffer);
  const detail::ViewportTransform transform = detail::makeViewportTransform(viewport);
  const detail::PixelRect region = drawRegion(state.scissor, viewport, framebuffer);
  if (region.empty()) return;
  const detail::DepthRange depthRange = detail::fragmentDepthRange(viewport, rs.depthClampEnable);
  const bool inverseZ = options_.depthMode == DepthMode::InverseZ;
  const DepthState& ds = state.depth;
  const std::uint32_t width = framebuffer.width();
  std::uint8_t* colour = framebuffer.colour().data();
  std::uint32_t* depth = framebuffer.depthStorage().data();
  std::array<float, (N == 0 ? 1 : N)> varyings{};  // one fragment's inputs (GCC 12 rejects this inside the lambda)
  const bool multisample = framebuffer.samples() == 4;
  const float pixelOffset = multisample ? 0.0f : detail::kPixelCentreOffset;

  // Fragment work of one primitive: depth, depth test, shading, writes, for every covered pixel.
  auto shadeFragments = [&](const auto& edges, const detail::PixelRect& bounds,
                            const detail::TriangleInterpolants<N>& interpolants) {
    detail::rasterizeEdges(edges, bounds, region, [&](int px, int py) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px);
      std::uint32_t stored = 0;  // Vulkan tests and writes depth only with the depth test on
      if (ds.testEnable) {
        bool passes;
        if (inverseZ) {  // the course's 1/z buffer: larger is nearer, so compare the other way round
          stored = std::bit_cast<std::uint32_t>(detail::evaluatePlane<Fused>(interpolants.oneOverW, fx, fy));
          passes = detail::depthTestPasses<Format>(ds.compareOp, depth[pixel], stored);
        } else {
          const float z = detail::clampDepth(detail::interpolateDepth<Fused>(interpolants, fx, fy), depthRange);
          stored = detail::depthToStorage<Format>(z);
          passes = detail::depthTestPasses<Format>(ds.compareOp, stored, depth[pixel]);
        }
        if (!passes) return;
      }
      detail::interpolateVaryings<Fused>(interpolants, interpolation, fx, fy, varyings.data());
      detail::blendColour(colour + 4 * pixel, Shader::fragment(uniforms, varyings.data()), state.blend);
      if (ds.testEnable && ds.writeEnable) depth[pixel] = stored;
    });
  };

  // 4x MSAA (filled triangles): coverage and depth per sample, the fragment shaded once at the
  // pixel centre, its colour written to the samples that are covered and pass the depth test.
  auto shadeSamples = [&](const auto& edges, const detail::PixelRect& bounds,
                          const detail::TriangleInterpolants<N>& interpolants) {
    detail::rasterizeEdgesSampled(edges, bounds, region, [&](int px, int py, unsigned mask) {
      const float fx = static_cast<float>(px), fy = static_cast<float>(py);
      const std::size_t pixel = static_cast<std::size_t>(py) * width + static_cast<std::size_t>(px);
      std::uint32_t stored[4];
      unsigned passed = ds.testEnable ? 0u : mask;  // without the depth test every covered sample passes
      for (int s = 0; s < 4 && ds.testEnable; ++s) {
        if (!(mask & (1u << s))) continue;
        const float z = detail::clampDepth(
            detail::interpolateDepth<Fused>(interpolants, fx + detail::kSamplePositions4x[s][0],
                                            fy + detail::kSamplePositions4x[s][1]),
            depthRange);
        stored[s] = detail::depthToStorage<Format>(z);
        if (detail::depthTestPasses<Format>(ds.compareOp, stored[s], depth[pixel * 4 + static_cast<std::size_t>(s)])) {
          passed |= 1u << s;
        }
      }
      if (passed == 0) return;
      detail::interpolateVaryings<Fused>(interpolants, interpolation, fx + 0.5f, fy + 0.5f, varyings.data());
      const Vec4 c = Shader::fragment(uniforms, varyings.data());
      for (int s = 0; s < 4; ++s) {
        if (!(passed & (1u << s))) continue;
        const std::size_t sample = pixel * 4 + static_cast<std::size_t>(s);
        detail::blendColour(colour + 4 * sample, c, state.blend);
        if (ds.testEnable && ds.writeEnable) depth[sample] = stored[s];
      }
    });
  };

  std::vector<Vertex> shaded(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    shaded[i] = detail::shadeVertex<Shader, Fused>(uniforms, vertices[i], transform, !rs.depthClampEnable);
  }

  auto drawLine = [&](const Vertex& a, const Vertex& b) {
    const auto line = rs.lineRasterization == LineRasterization::Bresenham
                          ? detail::setupBresenhamLine(a.window, b.window, rs.lineWidth)
                          : detail::setupRectangularLine(a.window, b.window, rs.lineWidth);
    if (!line) return;
    shadeFragments(line->quad.edges, line->quad.bounds, detail::setupLineInterpolants(a, b, *line, interpolation));
  };
  auto drawPoint = [&](const Vertex& v) {
    const detail::QuadEdges quad = detail::setupPoint(v.window, v.pointSize);
    shadeFragments(quad.edges, quad.bounds, detail::setupPointInterpolants(v, interpolation));
  };

  if (state.topology == Topology::PointList) {
    for (const std::uint32_t index : indices) {
      const Vertex& v = shaded[index];
      if (detail::pointSurvivesClipping(v)) drawPoint(v);
    }
    return;
  }

  if (detail::isLineTopology(state.topology)) {
    Vertex clippedA, clippedB;
    for (const detail::LineIndices& l : detail::assembleLines(state.topology, indices)) {
      const Vertex& a = shaded[l[0]];
      const Vertex& b = shaded[l[1]];
      const std::uint32_t outside = a.clipMask | b.clipMask;
      if (outside == 0) {
        drawLine(a, b);
      } else if ((a.clipMask & b.clipMask) == 0 &&
                 detail::clipLine(a, b, outside, transform, interpolation, clippedA, clippedB)) {
        drawLine(clippedA, clippedB);
      }
    }
    return;
  }

  const detail::WindingFilter winding = detail::windingFilter(rs);
  if (!winding.drawClockwise && !winding.drawCounterClockwise) return;
  const bool unfilled = rs.polygonMode != PolygonMode::Fill;
  // Mesa's unfilled stage for one (clipped, culled) triangle: `edges` holds its header's edge
  // flags (bit i: the edge from vertex i to vertex i+1); an edge or vertex is drawn when its flag
  // and its first vertex's edge flag are set. Flat varyings are the triangle's provoking vertex's.
  auto drawUnfilled = [&](const Vertex& a, const Vertex& b, const Vertex& c, unsigned edges) {
    Vertex v[3] = {a, b, c};
    for (int i = 0; i < N; ++i) {
      if (interpolation[static_cast<std::size_t>(i)] == Interpolation::Flat) v[1].varyings[i] = v[2].varyings[i] = a.varyings[i];
    }
    if (rs.polygonMode == PolygonMode::Line) {
      if ((edges & 4u) && v[2].edgeFlag) drawLine(v[2], v[0]);
      if ((edges & 1u) && v[0].edgeFlag) drawLine(v[0], v[1]);
      if ((edges & 2u) && v[1].edgeFlag) drawLine(v[1], v[2]);
    } else {
      for (int i = 0; i < 3; ++i) {
        if ((edges & (1u << i)) && v[i].edgeFlag) drawPoint(v[i]);
      }
    }
  };
  // Setup and fragments of one triangle (after clipping and culling).
  auto drawTriangle = [&](const Vertex& a, const Vertex& b, const Vertex& c) {
    detail::FixedTriangle fixed = detail::snapTriangle(a.window, b.window, c.window, pixelOffset);
    const int area = detail::fixedAreaSign(fixed);
    if (area == 0 || (area > 0 ? !winding.drawCounterClockwise : !winding.drawClockwise)) return;
    // From here on the triangle is counter-clockwise: a negative one continues as (a, c, b),
    // keeping the provoking vertex first.
    const Vertex& v1 = area > 0 ? b : c;
    const Vertex& v2 = area > 0 ? c : b;
    if (area < 0) {
      std::swap(fixed.x[1], fixed.x[2]);
      std::swap(fixed.y[1], fixed.y[2]);
    }
    const detail::TriangleEdges edges = detail::setupEdges(fixed);
    const detail::TriangleInterpolants<N> interpolants =
        detail::setupInterpolants(a, v1, v2, interpolation, rs.depthBias, Format, pixelOffset);
    if (multisample) {
      shadeSamples(edges.edges, edges.bounds, interpolants);
    } else {
      shadeFragments(edges.edges, edges.bounds, interpolants);
    }
  };

  const std::vector<detail::TriangleIndices> triangles = detail::assembleTriangles(state.topology, indices);
  const std::size_t batchSize = detail::trianglesPerBatch(state.topology);
  detail::ClippedPolygon<N> polygon;
  for (std::size_t start = 0; start < triangles.size(); start += batchSize) {
    const auto batch = std::span(triangles).subspan(start, std::min(batchSize, triangles.size() - start));
    const bool throughDrawPipeline = unfilled || detail::batchNeedsClipping(batch, shaded);
    for (const detail::TriangleIndices& t : batch) {
      const Vertex& v0 = shaded[t[0]];
      const Vertex& v1 = shaded[t[1]];
      const Vertex& v2 = shaded[t[2]];
      if (!throughDrawPipeline) {
        drawTriangle(v0, v1, v2);
        continue;
      }
      const std::uint32_t outside = v0.clipMask | v1.clipMask | v2.clipMask;
      if (outside == 0) {
        if (!detail::survivesPipelineCull(v0.window, v1.window, v2.window, rs)) continue;
        unfilled ? drawUnfilled(v0, v1, v2, 7u) : drawTriangle(v0, v1, v2);
        continue;
      }
      if ((v0.clipMask & v1.clipMask & v2.clipMask) != 0) continue;  // entirely outside one plane
      if (!detail::clipTriangle(v0, v1, v2, outside, transform, interpolation, polygon,
                                rs.polygonMode == PolygonMode::Point)) {
        continue;
      }
      // Emitted as a fan from vertex 0, with emit_poly's edge flags for each triangle.
      const unsigned first = polygon.edges[0] ? 1u : 0u;
      for (int i = 2; i < polygon.count; ++i) {
        const Vertex& p0 = polygon.vertices[0];
        const Vertex& p1 = polygon.vertices[i - 1];
        const Vertex& p2 = polygon.vertices[i];
        if (!detail::survivesPipelineCull(p0.window, p1.window, p2.window, rs)) continue;
        if (!unfilled) {
          drawTriangle(p0, p1, p2);
          continue;
        }
        unsigned edges = (i == 2 ? first : 0u) | (polygon.edges[static_cast<std::size_t>(i - 1)] ? 2u : 0u);
        if (i == polygon.count - 1 && polygon.edges[static_cast<std::size_t>(i)]) edges |= 4u;
        drawUnfilled(p0, p1, p2, edges);
      }
    }
  }
}

}  // namespace softraster
