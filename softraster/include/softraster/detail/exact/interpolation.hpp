// Interpolation: per-triangle plane equations for depth, 1/w and every varying, and their
// evaluation at a pixel centre as lavapipe's fragment JIT code does it:
//   a = fmuladd(dady, py, fmuladd(dadx, px, a0));
//   perspective-correct varyings are set up pre-multiplied by 1/w at the vertices and divided
//   per pixel by a real division: v = a * (1.0f / w_interp);
//   noperspective varyings use the plane of the plain values; flat ones the provoking vertex's.
// Deliberately absent until scenes need them: centroid and sample locations, derivatives.
#pragma once

#include <softraster/detail/fused_multiply_add.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/shader.hpp>

#include <array>

namespace softraster::detail {

template <bool Fused>
inline float evaluatePlane(const PlaneEquation& p, float px, float py) {
  return fmuladd<Fused>(p.dady, py, fmuladd<Fused>(p.dadx, px, p.a0));
}

template <int N>
struct TriangleInterpolants {
  PlaneEquation depth;
  float depthOffset = 0.0f;  // depth bias, added to every fragment's depth
  PlaneEquation oneOverW;
  std::array<PlaneEquation, N> varyings;
  // Not an interpolant, but the primitive's one other per-primitive value the fragment stage
  // reads: which stencil face applies (set by the draw loop; lines and points are front, but
  // an unfilled back-facing polygon's with Deviations::Spec).
  bool frontFacing = true;
};

// v0 is the provoking vertex, or v2 with provokingLast (lp_state_setup.c: attribs[2]).
template <int N>
inline TriangleInterpolants<N> setupInterpolants(const ShadedVertex<N>& v0, const ShadedVertex<N>& v1,
                                                 const ShadedVertex<N>& v2, const InterpolationSet<N>& interpolation,
                                                 const DepthBias& bias, DepthFormat depthFormat,
                                                 float pixelOffset = kPixelCentreOffset, bool provokingLast = false) {
  const PlaneSetup setup(v0.window, v1.window, v2.window, pixelOffset);
  TriangleInterpolants<N> t;
  t.depth = setup.plane(v0.window.z, v1.window.z, v2.window.z);
  t.depthOffset = setup.depthBias(v0.window.z, v1.window.z, v2.window.z, bias, depthFormat);
  t.oneOverW = setup.plane(v0.window.w, v1.window.w, v2.window.w);
  // Unrolled, so that the switch on the shader's constant interpolation folds away (GCC 12 at -O2
  // keeps the loop and the switch; unrolled, a triangle costs about 57 instructions fewer).
#pragma GCC unroll 16
  for (int i = 0; i < N; ++i) {
    switch (interpolation[static_cast<std::size_t>(i)]) {
      case Interpolation::Perspective:
        t.varyings[i] = setup.plane(v0.varyings[i] * v0.window.w, v1.varyings[i] * v1.window.w,
                                    v2.varyings[i] * v2.window.w);
        break;
      case Interpolation::NoPerspective:
        t.varyings[i] = setup.plane(v0.varyings[i], v1.varyings[i], v2.varyings[i]);
        break;
      case Interpolation::Flat:
        t.varyings[i] = {(provokingLast ? v2 : v0).varyings[i], 0.0f, 0.0f};
        break;
    }
  }
  return t;
}

// Depth at the pixel centre, before the depth range clamp, with the depth bias added (lavapipe
// always adds it; a zero offset still turns -0 into +0).
template <bool Fused, int N>
inline float interpolateDepth(const TriangleInterpolants<N>& t, float px, float py) {
  return evaluatePlane<Fused>(t.depth, px, py) + t.depthOffset;
}

template <bool Fused, int N>
inline void interpolateVaryings(const TriangleInterpolants<N>& t, const InterpolationSet<N>& interpolation, float px,
                                float py, float* out) {
  if constexpr (N > 0) {
    const float w = 1.0f / evaluatePlane<Fused>(t.oneOverW, px, py);
    for (int i = 0; i < N; ++i) {
      switch (interpolation[static_cast<std::size_t>(i)]) {
        case Interpolation::Perspective: out[i] = evaluatePlane<Fused>(t.varyings[i], px, py) * w; break;
        case Interpolation::NoPerspective: out[i] = evaluatePlane<Fused>(t.varyings[i], px, py); break;
        case Interpolation::Flat: out[i] = t.varyings[i].a0; break;
      }
    }
  }
}

}  // namespace softraster::detail
