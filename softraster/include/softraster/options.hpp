// How a Context draws: the options that are not Vulkan pipeline state (that is state.hpp) but
// choices of this library: the method (lavapipe's exact rules, or one of the course's
// rasterization methods), how lavapipe's fmuladd rounds on the machine being matched, what the
// depth buffer holds and, for the course's methods, affine instead of perspective varyings.
// Deliberately absent: per-vertex versus per-pixel lighting (a choice of shading model, not of
// the rasterizer: shaders/ has both kinds).
#pragma once

#include <softraster/detail/fused_multiply_add.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace softraster {

// What the depth buffer holds.
//   Vulkan:   window z (z/w mapped to the viewport's depth range), as Vulkan and lavapipe do.
//   InverseZ: the course's 1/z buffer: 1/w (w = camera-space depth for perspective cameras),
//             interpolated linearly in screen space; NOT a Vulkan mode, so it is never
//             cross-checked bit for bit, only charted. Clear the depth buffer to 0 (infinitely
//             far); compare ops keep their meaning in distance (LESS passes the nearer fragment,
//             i.e. the larger 1/z). Needs D32_SFLOAT; the viewport depth range does not apply.
enum class DepthMode : std::uint8_t { Vulkan, InverseZ };

// How pixels are found and shaded. Exact and ExactScalar give the same bits (lavapipe's);
// ExactScalar is the reference the fast one is tested against. The course's three methods are
// other algorithms, charted against Vulkan, never bit-identical to it; each replaces only setup,
// coverage and interpolation of filled triangles (detail/course/: each header says what it does
// and does not do; none has a fill rule), sharing everything before (vertex shading, clipping,
// culling, polygon modes) and after (depth test, shading, blending) with the exact method; lines
// and points are drawn by the exact method's code; they draw on the calling thread, and with 4x
// MSAA each pixel's one result goes to all four samples.
//   Exact:       lavapipe's rules; triangles, and single-sample lines and points, take the SIMD
//                fast path (4x2 pixel batches, AVX2) where the CPU has AVX2 and FMA, fmuladd is
//                fused, the shader's fragment function is written over its float type (shader.hpp)
//                and the target is not sRGB; everything else takes the scalar path.
//   ExactScalar: lavapipe's rules, one pixel at a time.
//   Scanline:    the course's row method: each edge walked into per-row left/right arrays, each
//                row drawn between them (detail/course/scanline.hpp).
//   Trapezoid:   split at the middle vertex into two trapezoids, positions in fixed point and
//                values stepped incrementally down edges and across spans (course/trapezoid.hpp).
//   Barycentric: the bounding box, float barycentrics at each pixel centre, inside when
//                u >= 0, v >= 0, u + v <= 1 (course/barycentric.hpp).
enum class Method : std::uint8_t { Exact, ExactScalar, Scanline, Trapezoid, Barycentric };

// Every method, in the order the CLI, the bench and the chart list them.
inline constexpr std::array kMethods{Method::Exact, Method::ExactScalar, Method::Scanline, Method::Trapezoid,
                                     Method::Barycentric};

// A method's name on the command line and in results ("exact", "exact-scalar", "scanline",
// "trapezoid", "barycentric").
constexpr std::string_view methodName(Method method) {
  switch (method) {
    case Method::Exact: return "exact";
    case Method::ExactScalar: return "exact-scalar";
    case Method::Scanline: return "scanline";
    case Method::Trapezoid: return "trapezoid";
    case Method::Barycentric: return "barycentric";
  }
  return "unknown";
}

// Whether a method is one of the course's (not lavapipe's rules).
constexpr bool isCourseMethod(Method method) {
  return method == Method::Scanline || method == Method::Trapezoid || method == Method::Barycentric;
}

// The method a name stands for, or nothing for an unknown name.
constexpr std::optional<Method> methodFromName(std::string_view name) {
  for (Method m : kMethods) {
    if (methodName(m) == name) return m;
  }
  return std::nullopt;
}

// Where lavapipe provably deviates from the Vulkan specification (docs/lavapipe-rules.md,
// "Deviations"), whose behaviour softraster follows:
//   Driver: lavapipe's, so cross-checks agree bit for bit (the default);
//   Spec:   the specification's words. The known deviations: with 4x MSAA lavapipe's scissor
//           planes let samples through in the column left of and the row above the scissor
//           rectangle, where the spec's scissor test discards every sample of those fragments;
//           lavapipe gives the lines and points of a back-facing polygon drawn in polygon
//           mode line or point the front stencil state, where the spec gives them the back one;
//           with one sample lavapipe ignores the sample mask's bit 0 (it discards a draw
//           only for a mask of 0), where the spec keeps a fragment iff bit 0 is set; and with
//           4x MSAA lavapipe evaluates a line's attributes half a pixel off, drops covered
//           samples its binning does not walk, and draws Bresenham lines with multisampling
//           off (depth and stencil at sample 0 only), where the spec evaluates at the centre,
//           covers every sample inside the line and tests each sample; with alpha to coverage
//           and per-sample invocations lavapipe narrows each sample by every other
//           invocation's alpha (uncovered samples' too) and never by its own, where the spec
//           narrows each invocation's sample by its own alpha.
enum class Deviations : std::uint8_t { Driver, Spec };

// A Deviations value's name on the command line and in results ("driver", "spec").
constexpr std::string_view deviationsName(Deviations d) { return d == Deviations::Spec ? "spec" : "driver"; }

struct ContextOptions {
  Method method = Method::Exact;
  // Threads that draw, the caller's included: 0 = one per core, 1 = the calling thread only.
  // The Context owns them; the output is the same bits for every count.
  unsigned threads = 0;
  // How lavapipe's fmuladd rounds on the machine being matched: fused where the CPU has FMA.
  bool fusedMultiplyAdd = detail::cpuHasFma();
  DepthMode depthMode = DepthMode::Vulkan;
  // The course's methods only: perspective-correct varyings (smooth, the default in GLSL) are
  // interpolated linearly in screen space, without the division by the interpolated 1/w
  // (the course's affine interpolation; noperspective and flat varyings are unchanged). With
  // Exact or ExactScalar it is an error of every draw (Context::validate()), never a silent
  // change of an exact draw.
  bool affineVaryings = false;
  // Whose behaviour where lavapipe deviates from the spec (above).
  Deviations deviations = Deviations::Driver;
  // Whether the fast path may use AVX-512 where the CPU has it (F, VL, BW and DQ): a long
  // shader's blocks (shader.hpp, kBlockPairs) shaded four at a time in 16-lane registers, and
  // other shaders' runs of whole blocks drawn two at a time. Off, everything is AVX2's 8 lanes,
  // as on a CPU without AVX-512. The bits are the same either way; the switch lets one machine
  // test and time both.
  bool allowAvx512 = true;
};

}  // namespace softraster
