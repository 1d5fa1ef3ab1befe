// The shader interface softraster's pipeline is a template over, and the vertex-layout
// description both renderers read from a shader's C++ twin.
//
// A shader type S provides:
//   struct S::Vertex;                        the vertex as stored in the vertex buffer
//   struct S::Uniforms;                      per-draw constants (a push-constant block in GLSL)
//   static constexpr int S::kVaryings;       number of float varyings (0..kMaxVaryings)
//   static constexpr std::array<VertexAttribute, N> S::kAttributes;   locations of Vertex's fields
//   static Vec4 S::vertex(const Uniforms&, const Vertex&, float* varyingsOut);   clip position
//   static Vec4 S::fragment(const Uniforms&, const float* varyingsIn);           RGBA colour
// and optionally
//   static constexpr std::array<Interpolation, kVaryings> S::kInterpolation;    default: all perspective
//   static float S::pointSize(const Uniforms&, const Vertex&);                  gl_PointSize; default 1
// Deliberately no virtual functions: the pipeline is instantiated per shader, so a varying a
// shader does not declare costs nothing.
#pragma once

#include <array>
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

}  // namespace softraster
