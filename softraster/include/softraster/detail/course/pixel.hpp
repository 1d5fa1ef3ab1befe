// What the course's three methods (scanline.hpp, trapezoid.hpp, barycentric.hpp) share: the
// course's Pixel (a projected vertex: x, y and the values interpolated linearly in screen space),
// the Pixel of each of a triangle's vertices, the safe float-to-pixel conversions their loops are
// clamped with, and CourseFragments, the per-pixel end of the pipeline they all hand pixels to:
// the stencil test (fragment/stencil.hpp, as the exact method does it, per sample), the depth
// test (every compare op, depth write, Vulkan z or the course's 1/z buffer), the
// shader's fragment function, blending and the write mask (each colour output to its attachment),
// through detail/fragment/ as the exact method's scalar stage does.
// The interpolated values of a Pixel, in order: window z (Vulkan depth, z/w mapped by the
// viewport, linear in screen space), 1/w (the course's 1/z: linear in screen space), then the
// shader's varyings. A perspective-correct varying travels as v/w and is divided by the
// interpolated 1/w at the pixel; with affine varyings (ContextOptions::affineVaryings) it travels
// as v itself and is not divided (the course's cheaper, wrong-under-perspective form).
// noperspective varyings are always plain v; flat ones carry the provoking vertex's value at all
// three vertices, so every interpolation gives it back exactly.
// Deliberately absent: coverage (each method's own), fill rules, MSAA coverage (with 4x MSAA a
// pixel's one result goes to its four samples), threads (the calling thread draws), texture
// derivatives (a sampling shader samples the base level: no quads here).
#pragma once

#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fragment/colour.hpp>
#include <softraster/detail/fragment/depth.hpp>
#include <softraster/detail/fragment/shade.hpp>
#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/detail/instruction_set.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace softraster::detail::course {

// Window coordinates past this magnitude are not drawn by a course method (the triangle is
// dropped): the shared front end clips to the guard band (|x|, |y| <= 2w), so a finite vertex
// lands within a few viewport sizes of it; this bound keeps every method's integer and float
// position arithmetic (16.16 fixed point in 64 bits, row counts) far from overflow.
inline constexpr float kMaxWindowCoordinate = 16777216.0f;  // 2^24

// The course's Pixel: a projected vertex (or a point on an edge or a row) with its values.
// K = 2 + the shader's varyings: [0] window z, [1] 1/w, [2..] the varyings (see the top).
template <int K>
struct Pixel {
  float x = 0, y = 0;
  std::array<float, K> values{};
};

// a + t * (b - a) for every value (and x, y): the linear interpolation the methods walk with.
template <int K>
inline Pixel<K> lerp(const Pixel<K>& a, const Pixel<K>& b, float t) {
  Pixel<K> p;
  p.x = a.x + t * (b.x - a.x);
  p.y = a.y + t * (b.y - a.y);
  for (int i = 0; i < K; ++i) p.values[i] = a.values[i] + t * (b.values[i] - a.values[i]);
  return p;
}

// Whether a vertex can be drawn by a course method at all: finite and within kMaxWindowCoordinate.
template <int K>
inline bool drawable(const Pixel<K>& p) {
  return std::fabs(p.x) <= kMaxWindowCoordinate && std::fabs(p.y) <= kMaxWindowCoordinate;  // false for NaN
}

// The first pixel whose centre (i + 0.5) is at or after v, clamped to [lo, hi + 1] (an empty range
// when v is past hi); v must not be NaN (drawable() vertices only give finite values).
inline int firstCentreAtOrAfter(float v, int lo, int hi) {
  const float first = std::ceil(v - 0.5f);
  if (!(first > static_cast<float>(lo))) return lo;
  if (first > static_cast<float>(hi)) return hi + 1;
  return static_cast<int>(first);
}

// The last pixel whose centre is at or before v, clamped to [lo - 1, hi].
inline int lastCentreAtOrBefore(float v, int lo, int hi) {
  const float last = std::floor(v - 0.5f);
  if (!(last < static_cast<float>(hi))) return hi;
  if (last < static_cast<float>(lo)) return lo - 1;
  return static_cast<int>(last);
}

// The Pixel of a shaded vertex: its window x, y and the values the methods interpolate. The
// provoking vertex (flat varyings) is passed as `provoking`.
template <int K, int N>
inline Pixel<K> pixelOf(const ShadedVertex<N>& v, const ShadedVertex<N>& provoking, const InterpolationSet<N>& interpolation,
                        bool affine) {
  static_assert(K == N + 2);
  Pixel<K> p;
  p.x = v.window.x;
  p.y = v.window.y;
  p.values[0] = v.window.z;
  p.values[1] = v.window.w;
  for (int i = 0; i < N; ++i) {
    const auto k = static_cast<std::size_t>(i);
    switch (interpolation[k]) {
      case Interpolation::Perspective: p.values[k + 2] = affine ? v.varyings[k] : v.varyings[k] * v.window.w; break;
      case Interpolation::NoPerspective: p.values[k + 2] = v.varyings[k]; break;
      case Interpolation::Flat: p.values[k + 2] = provoking.varyings[k]; break;
    }
  }
  return p;
}

// The per-pixel end of a course method's draw, the same for the three: takes a pixel and its
// interpolated values, tests depth, shades, blends and writes. Pixels outside the draw region are
// ignored, so a method whose arithmetic goes wrong gives wrong pixels, never a stray write.
template <class Shader, bool Fused, DepthFormat Format>
class CourseFragments {
 public:
  static constexpr int N = Shader::kVaryings;
  static constexpr int K = N + 2;
  static constexpr InstructionSet kInstructionSet = Fused ? InstructionSet::Fma : InstructionSet::Baseline;

  CourseFragments(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                  const Viewport& viewport, const PixelRect& region, bool inverseZ, bool affine,
                  Deviations deviations = Deviations::Driver)
      : uniforms_(uniforms),
        target_(fragmentTarget(state, framebuffer, viewport, region, inverseZ, deviations)),
        samples_(framebuffer.samples() == 4 ? 4u : 1u),
        affine_(affine) {}

  const PixelRect& region() const { return target_.region; }
  bool affine() const { return affine_; }

  // The triangle's depth-bias offset, added to every window z (not to 1/z) until the next call.
  void setDepthOffset(float offset) { depthOffset_ = offset; }
  // The triangle's facing, which picks the stencil face, until the next call.
  void setFrontFacing(bool front) { frontFacing_ = front; }

  // One pixel with its interpolated values ([0] z, [1] 1/w, [2..] varyings as pixelOf made them).
  // Compiled once per shader, format and instruction set, whichever method calls it
  // (detail/instruction_set.hpp), rather than copied into each method's loops.
  void shade(int px, int py, const float* values) const {
    callCompiledFor<kInstructionSet, &CourseFragments::shadeHere>(*this, px, py, values);
  }

 private:
  void shadeHere(int px, int py, const float* values) const {
    const PixelRect& r = target_.region;
    if (px < r.x0 || px > r.x1 || py < r.y0 || py > r.y1) return;
    const std::size_t pixel = static_cast<std::size_t>(py) * target_.width + static_cast<std::size_t>(px);
    std::uint32_t stored = 0;
    if (target_.depth.testEnable) {
      if (target_.inverseZ) {
        stored = std::bit_cast<std::uint32_t>(values[1]);
      } else {
        stored = depthToStorage<Format>(clampDepth(values[0] + depthOffset_, target_.depthRange));
      }
    }
    // The sample mask, and with alpha to coverage the colour first: the samples its alpha keeps.
    unsigned kept = target_.coverage.sampleMask;
    std::array<float, (N == 0 ? 1 : N)> varyings{};
    FragmentColours<Shader> c{};
    const bool shadedFirst = target_.coverage.shadesFirst();
    if (shadedFirst) {
      c = shadeValues(values, varyings.data());
      kept &= samples_ == 4 ? alphaToCoverageSamples<4>(c[0].w) : alphaToCoverageSamples<1>(c[0].w);
      if (kept == 0) return;
    }
    unsigned passed = 0;
    for (unsigned s = 0; s < samples_; ++s) {
      if (!(kept & (1u << s))) continue;
      const std::uint32_t old = target_.depthStorage[pixel * samples_ + s];
      const bool passes = !target_.depth.testEnable ||
                          (target_.inverseZ ? depthTestPasses<Format>(target_.depth.compareOp, old, stored)
                                            : depthTestPasses<Format>(target_.depth.compareOp, stored, old));
      if (target_.stencil.enable) {
        const StencilFace& face = target_.stencil.face(frontFacing_);
        std::uint8_t& value = target_.stencilStorage[pixel * samples_ + s];
        const bool stencilPasses = stencilTestPasses(face, value);
        value = stencilUpdate(face, stencilOpFor(face, stencilPasses, passes), value);
        if (!stencilPasses) continue;
      }
      if (passes) passed |= 1u << s;
    }
    if (passed == 0) return;
    if (!shadedFirst) c = shadeValues(values, varyings.data());
    if (target_.coverage.alphaToOne) setAlphaToOne(c);
    for (unsigned s = 0; s < samples_; ++s) {
      if (!(passed & (1u << s))) continue;
      const std::size_t sample = pixel * samples_ + s;
      writeColours(target_, sample, c);
      if (target_.depth.testEnable && target_.depth.writeEnable) target_.depthStorage[sample] = stored;
    }
  }

  // The shader's colours from one pixel's interpolated values (the varyings divided as the top
  // says, into `varyings`).
  FragmentColours<Shader> shadeValues(const float* values, float* varyings) const {
    if constexpr (N > 0) {
      const float w = 1.0f / values[1];
      for (int i = 0; i < N; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const bool divide = kInterpolation[k] == Interpolation::Perspective && !affine_;
        varyings[k] = divide ? values[k + 2] * w : values[k + 2];
      }
    }
    return shade(varyings);
  }

  // The shader's colour from one pixel's varyings. The course's methods shade one pixel at a
  // time, with no neighbours: a shader that samples textures (kQuads) gets a batch whose every
  // lane is this pixel, so its derivatives are 0 and it samples the base level, magnified (the
  // course's texture lookup, without mipmaps: where that aliases is what the chart shows).
  FragmentColours<Shader> shade(const float* varyings) const {
    if constexpr (ShadesQuads<Shader>) {
      std::array<FloatBatch, (N == 0 ? 1 : N)> batch{};
      for (int i = 0; i < N; ++i) batch[static_cast<std::size_t>(i)] = FloatBatch(varyings[i]);
      const Vec4T<FloatBatch> c = Shader::template fragment<FloatBatch>(uniforms_, batch.data());
      return {Vec4{c.x[0], c.y[0], c.z[0], c.w[0]}};
    } else {
      return fragmentColours(shadeFragment<Shader>(uniforms_, varyings));
    }
  }

  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();

  const typename Shader::Uniforms& uniforms_;
  FragmentTarget target_;
  unsigned samples_;
  bool affine_;
  float depthOffset_ = 0.0f;
  bool frontFacing_ = true;
};

}  // namespace softraster::detail::course
