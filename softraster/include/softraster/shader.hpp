// The shader interface softraster's pipeline is a template over, and the vertex-layout
// description both renderers read from a shader's C++ twin.
//
// A shader type S provides:
//   struct S::Vertex;                        the vertex as stored in the vertex buffer
//   struct S::Uniforms;                      per-draw constants (a push-constant block in GLSL)
//   static constexpr int S::kVaryings;       number of float varyings (0..kMaxVaryings)
//   static Vec4 S::vertex(const Uniforms&, const Vertex&, float* varyingsOut);   clip position
//   template <class F>
//   static Vec4T<F> S::fragment(const Uniforms&, const F* varyingsIn);           RGBA colour
// The fragment function is written once over its float type F (float, or FloatBatch from
// simd.hpp: one value per lane of a 4x2 pixel block), so the fast path shades whole batches with
// the same source the scalar path runs per pixel; IEEE operations round the same per lane, so
// both give the same bits. A shader whose fragment function takes only `const float*` (not a
// template) still draws, on the scalar path.
// and optionally
//   static constexpr std::array<Interpolation, kVaryings> S::kInterpolation;    default: all perspective
//   static float S::pointSize(const Uniforms&, const Vertex&);                  gl_PointSize; default 1
//   static constexpr std::array<VertexAttribute, N> S::kAttributes;             locations of Vertex's
//       fields, for a renderer that feeds the GLSL twin (vkref); softraster itself does not read it
// Deliberately no virtual functions: the pipeline is instantiated per shader, so a varying a
// shader does not declare costs nothing.
#pragma once

#include <softraster/math.hpp>
#include <softraster/simd.hpp>

#include <array>
#include <concepts>
#include <cstdint>

namespace softraster {

inline constexpr int kMaxVaryings = 16;

// How a varying is interpolated across a primitive (GLSL: smooth, noperspective, flat).
enum class Interpolation : std::uint8_t { Perspective, NoPerspective, Flat };

template <int N>
using InterpolationSet = std::array<Interpolation, static_cast<std::size_t>(N)>;

// The shader's kInterpolation, or all-perspective when it declares none.
template <class Shader>
constexpr InterpolationSet<Shader::kVaryings> interpolationOf() {
  if constexpr (requires { Shader::kInterpolation; }) {
    return Shader::kInterpolation;
  } else {
    InterpolationSet<Shader::kVaryings> all{};
    all.fill(Interpolation::Perspective);
    return all;
  }
}

// One vertex input: `components` consecutive 32-bit floats at byte `offset` of the vertex.
struct VertexAttribute {
  std::uint32_t location = 0;
  std::uint32_t components = 0;
  std::uint32_t offset = 0;
};

// The shader's gl_PointSize for a vertex, or 1 when it writes none.
template <class Shader>
float pointSizeOf(const typename Shader::Uniforms& uniforms, const typename Shader::Vertex& vertex) {
  if constexpr (requires { Shader::pointSize(uniforms, vertex); }) {
    return Shader::pointSize(uniforms, vertex);
  } else {
    return 1.0f;
  }
}

// Whether the shader's fragment function is written over its float type (so it can shade batches).
template <class Shader>
concept ShadesBatches = requires(const typename Shader::Uniforms& u, const FloatBatch* v) {
  { Shader::template fragment<FloatBatch>(u, v) } -> std::same_as<Vec4T<FloatBatch>>;
};

// One pixel's colour from the shader, whichever form its fragment function takes.
template <class Shader>
Vec4 shadeFragment(const typename Shader::Uniforms& uniforms, const float* varyings) {
  if constexpr (requires { Shader::template fragment<float>(uniforms, varyings); }) {
    return Shader::template fragment<float>(uniforms, varyings);
  } else {
    return Shader::fragment(uniforms, varyings);
  }
}

}  // namespace softraster
