// CourseTriangles: where a course method (Method::Scanline, Trapezoid, Barycentric) plugs into the
// draw loop (exact/draw.hpp). The loop's front end is shared with the exact method: vertex
// shading, primitive assembly, clipping (frustum, guard band), the draw pipeline's float cull and
// polygon modes. For a filled triangle the loop calls drawTriangle() here instead of the exact
// method's snapping, fixed-point setup, coverage and plane interpolation: this culls by winding
// (the float signed area, front faces as RasterizationState says), makes each vertex's Pixel
// (course/pixel.hpp), adds the triangle's depth bias (the exact method's formula) and its facing
// (for the stencil test's face), and hands the
// three Pixels to the chosen method's two calls, setup() and draw(), whose pixels go to the
// shared per-pixel end (CourseFragments: stencil and depth tests and writes, shading, blending,
// write mask).
// Lines and points (topologies and polygon modes line and point) are not the course's: the
// Context draws them by Method::ExactScalar's path (pipeline.hpp), so they are its pixels, and a
// course draw compiles no line or point code.
// Deliberately absent: threads (a course method draws on the calling thread), SIMD, any fill rule
// or snapping (each method's header says what it does and does not do).
#pragma once

#include <softraster/detail/course/barycentric.hpp>
#include <softraster/detail/course/pixel.hpp>
#include <softraster/detail/course/scanline.hpp>
#include <softraster/detail/course/trapezoid.hpp>
#include <softraster/detail/exact/scratch.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/geometry/culling.hpp>
#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/options.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <vector>

namespace softraster::detail::course {

template <class Shader, bool Fused, DepthFormat Format>
class CourseTriangles {
 public:
  static constexpr int N = Shader::kVaryings;
  static constexpr int K = N + 2;
  using Vertex = ShadedVertex<N>;

  CourseTriangles(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                  const Viewport& viewport, const PixelRect& region, bool inverseZ, const ContextOptions& options,
                  DrawScratch& scratch)
      : bias_(state.rasterization.depthBias),
        ccwIsFront_(state.rasterization.frontFace == FrontFace::CounterClockwise),
        method_(options.method),
        fragments_(state, uniforms, framebuffer, viewport, region, inverseZ, options.affineVaryings, options.deviations),
        scanline_(scratch.vector<Pixel<K>>(ScratchSlot::CourseRows)) {}

  // One filled triangle past the front end; a is the provoking vertex.
  void drawTriangle(const Vertex& a, const Vertex& b, const Vertex& c, const WindingFilter& winding) {
    const float area = (a.window.x - b.window.x) * (c.window.y - a.window.y) -
                       (c.window.x - a.window.x) * (a.window.y - b.window.y);
    if (!(area != 0.0f)) return;  // zero area or NaN
    if (area > 0 ? !winding.drawCounterClockwise : !winding.drawClockwise) return;
    const Pixel<K> pa = pixelOf<K>(a, a, kInterpolation, fragments_.affine());
    const Pixel<K> pb = pixelOf<K>(b, a, kInterpolation, fragments_.affine());
    const Pixel<K> pc = pixelOf<K>(c, a, kInterpolation, fragments_.affine());
    float offset = 0.0f;
    if (bias_.enable) {
      const PlaneSetup setup(a.window, b.window, c.window);
      offset = setup.depthBias(a.window.z, b.window.z, c.window.z, bias_, Format);
    }
    fragments_.setDepthOffset(offset);
    fragments_.setFrontFacing((area > 0) == ccwIsFront_);
    const auto shade = [this](int px, int py, const float* values) { fragments_.shade(px, py, values); };
    const PixelRect& region = fragments_.region();
    switch (method_) {
      case Method::Scanline:
        if (scanline_.setup(pa, pb, pc, region)) scanline_.draw(shade);
        break;
      case Method::Trapezoid:
        if (trapezoid_.setup(pa, pb, pc, region)) trapezoid_.draw(shade);
        break;
      case Method::Barycentric:
        if (barycentric_.setup(pa, pb, pc, region)) barycentric_.draw(shade);
        break;
      default: break;  // not a course method: the Context never makes one of these for it
    }
  }

 private:
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  DepthBias bias_;
  bool ccwIsFront_;  // a counter-clockwise triangle (positive float area) is front-facing
  Method method_;
  CourseFragments<Shader, Fused, Format> fragments_;
  ScanlineTriangle<K> scanline_;
  TrapezoidTriangle<K> trapezoid_;
  BarycentricTriangle<K> barycentric_;
};

}  // namespace softraster::detail::course
