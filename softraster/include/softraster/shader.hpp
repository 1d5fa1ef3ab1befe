// The shader interface softraster's pipeline is a template over (the concept ShaderInterface,
// checked where Context::draw is called), and the vertex-layout description a renderer that
// feeds a GLSL twin reads (vkref).
//
// A shader type S provides:
//   struct S::Vertex;                        the vertex as stored in the vertex buffer
//   struct S::Uniforms;                      per-draw constants (a push-constant block in GLSL)
//   static constexpr int S::kVaryings;       number of float varyings (0..kMaxVaryings)
//   static Vec4 S::vertex(const Uniforms&, const Vertex&, float* varyingsOut);   clip position
//   template <class F>
//   static Vec4T<F> S::fragment(const Uniforms&, const F* varyingsIn);           RGBA colour
//     or, for several colour attachments, ColourOutputs<F, K> (one RGBA colour per output
//     location 0..K-1, K <= kMaxColourAttachments): output i goes to the framebuffer's colour
//     attachment i (its outputs past the framebuffer's attachments are dropped); such a shader is
//     shaded on the scalar path
// The clip position is in Vulkan's clip space (x right, y down, z in [0, w]; docs/library.md).
// The fragment function is written once over its float type F (float, or FloatBatch from
// simd.hpp: one value per lane of a 4x2 pixel block), so the fast path shades whole batches with
// the same source the scalar path runs per pixel; IEEE operations round the same per lane, so
// both give the same bits. A shader whose fragment function takes only `const float*` (not a
// template) still draws, on the scalar path.
// and optionally
//   static constexpr bool S::kQuads = true;   the fragment function samples textures (texture.hpp):
//                                             written for FloatBatch only, shaded in 2x2 quads
//   static constexpr std::array<Interpolation, kVaryings> S::kInterpolation;    default: all perspective
//   static float S::pointSize(const Uniforms&, const Vertex&);                  gl_PointSize; default 1
//   static constexpr bool S::kBlockPairs = true;  the fragment function also takes FloatBatchPair
//                                             (simd.hpp): where the state allows (depth tested and
//                                             written; no stencil, blending, discards or textures),
//                                             the fast path shades two blocks in one call, their
//                                             chains of arithmetic interleaved. For a long shader
//                                             (Phong per pixel); a short one gains nothing. With
//                                             GCC on x86-64 it must also compile for FloatBatch16
//                                             and FloatBatch16Pair: where the CPU has AVX-512 a
//                                             pair is one 16-lane batch, and two pairs go together
//   a fragment function with a third parameter, FragmentBuiltins<F>& (fragment_builtins.hpp):
//   gl_FragCoord, gl_FrontFacing and discard; such a shader runs before the depth and stencil
//   tests, on both exact paths (the course's methods draw it with the exact method)
// Anything else a shader declares (the project's twins declare kAttributes, VertexAttribute
// below, for vkref) softraster does not read.
// A type that breaks the interface fails to compile at the draw call with one static_assert
// naming the member and the fix (checkShaderInterface below), not with errors from the pipeline.
// Deliberately no virtual functions: the pipeline is instantiated per shader, so a varying a
// shader does not declare costs nothing.
#pragma once

#include <softraster/fragment_builtins.hpp>
#include <softraster/math.hpp>
#include <softraster/simd.hpp>
#include <softraster/state.hpp>

#include <array>
#include <concepts>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>

namespace softraster {

inline constexpr int kMaxVaryings = 64;  // Vulkan's minimum maxVertexOutputComponents

// A fragment function's colours for several colour attachments: one per output location.
template <class F, std::size_t K>
using ColourOutputs = std::array<Vec4T<F>, K>;

namespace detail {
template <class T>
struct ColourOutputCount {
  static constexpr std::size_t value = 0;  // not a fragment's colour
};
template <>
struct ColourOutputCount<Vec4> {
  static constexpr std::size_t value = 1;
};
template <std::size_t K>
struct ColourOutputCount<std::array<Vec4, K>> {
  static constexpr std::size_t value = K;
};
}  // namespace detail

// What a fragment function may return for one pixel: a Vec4 (one colour output), or
// ColourOutputs<float, K> with 1 <= K <= kMaxColourAttachments.
template <class T>
concept FragmentColour =
    detail::ColourOutputCount<T>::value >= 1 && detail::ColourOutputCount<T>::value <= kMaxColourAttachments;

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

// The shader interface, piece by piece (each a concept, so a failed one names itself).
template <class S>
concept HasShaderVertexType = requires { typename S::Vertex; };
template <class S>
concept HasShaderUniformsType = requires { typename S::Uniforms; };
template <class S>
concept HasShaderVaryingCount = requires {
  { S::kVaryings } -> std::convertible_to<int>;
} && (S::kVaryings >= 0 && S::kVaryings <= kMaxVaryings);
// A member named `vertex` / `fragment` exists (as a function, a template, static or not).
template <class S>
concept HasShaderVertexMember = requires { &S::vertex; };
template <class S>
concept HasShaderFragmentMember = requires { &S::fragment; } || requires { &S::template fragment<float>; } ||
                                  requires { &S::template fragment<FloatBatch>; };
// The member is a non-static member function (the commonest slip: a shader is never an object).
template <class S>
concept HasNonStaticShaderVertex = requires { requires std::is_member_function_pointer_v<decltype(&S::vertex)>; };
template <class S>
concept HasNonStaticShaderFragment =
    requires { requires std::is_member_function_pointer_v<decltype(&S::fragment)>; } ||
    requires { requires std::is_member_function_pointer_v<decltype(&S::template fragment<float>)>; };
template <class S>
concept HasStaticShaderVertex = requires(const typename S::Uniforms& u, const typename S::Vertex& v, float* out) {
  S::vertex(u, v, out);
};
// A shader that samples textures (texture.hpp) declares kQuads: its fragment function is written
// for FloatBatch only (a batch of two 2x2 quads, the derivatives' source) and every path shades
// it in quads.
template <class S>
concept ShadesQuads = requires {
  { S::kQuads } -> std::convertible_to<bool>;
} && S::kQuads && requires(const typename S::Uniforms& u, const FloatBatch* in) {
  { S::template fragment<FloatBatch>(u, in) } -> std::same_as<Vec4T<FloatBatch>>;
};
// A shader the fast path shades two blocks at a time (FloatBatchPair, simd.hpp): it sets
// kBlockPairs and its fragment function takes the pair.
template <class S>
concept ShadesBlockPairs = requires {
  { S::kBlockPairs } -> std::convertible_to<bool>;
} && S::kBlockPairs && requires(const typename S::Uniforms& u, const FloatBatchPair* in) {
  { S::template fragment<FloatBatchPair>(u, in) } -> std::same_as<Vec4T<FloatBatchPair>>;
};
// A fragment function that reads or writes the fragment built-ins (fragment_builtins.hpp).
template <class S>
concept UsesFragmentBuiltins = requires(const typename S::Uniforms& u, const float* in, FragmentBuiltins<float>& b) {
  { S::template fragment<float>(u, in, b) } -> FragmentColour;
};
// A shader with the built-ins that writes gl_FragDepth (fragment_builtins.hpp).
template <class S>
concept WritesFragDepth = UsesFragmentBuiltins<S> && requires {
  { S::kWritesFragDepth } -> std::convertible_to<bool>;
} && S::kWritesFragDepth;
// A shader with the built-ins that writes gl_SampleMask (fragment_builtins.hpp).
template <class S>
concept WritesSampleMask = UsesFragmentBuiltins<S> && requires {
  { S::kWritesSampleMask } -> std::convertible_to<bool>;
} && S::kWritesSampleMask;
// A shader with the built-ins whose fragment function reads gl_FrontFacing declares
// `static constexpr bool kReadsFrontFacing = true`: the lines and points of its unfilled
// polygons (polygon modes line and point) then take the polygon's facing, for gl_FrontFacing and
// for the stencil state, as lavapipe's unfilled stage gives it only to a shader that reads it.
template <class S>
concept ReadsFrontFacing = UsesFragmentBuiltins<S> && requires {
  { S::kReadsFrontFacing } -> std::convertible_to<bool>;
} && S::kReadsFrontFacing;
// A shader with the built-ins whose fragment function reads gl_SampleID or gl_SamplePosition
// declares `static constexpr bool kShadesPerSample = true`: with 4x MSAA it runs once per
// covered sample (GLSL: reading gl_SampleID turns sample shading on at the full rate).
template <class S>
concept ShadesPerSample = UsesFragmentBuiltins<S> && requires {
  { S::kShadesPerSample } -> std::convertible_to<bool>;
} && S::kShadesPerSample;
// A fragment function in one of the two special forms (quads, built-ins): a plain bool, not a
// concept, so a shader that has neither gets one line about it in a failed check, not two chains.
template <class S>
inline constexpr bool kSpecialFragmentForm = ShadesQuads<S> || UsesFragmentBuiltins<S>;
template <class S>
concept HasStaticShaderFragment = kSpecialFragmentForm<S> || requires(const typename S::Uniforms& u, const float* in) {
  S::fragment(u, in);
} || requires(const typename S::Uniforms& u, const float* in) { S::template fragment<float>(u, in); };
template <class S>
concept HasShaderVertexSignature = requires(const typename S::Uniforms& u, const typename S::Vertex& v, float* out) {
  { S::vertex(u, v, out) } -> std::same_as<Vec4>;
};
template <class S>
concept HasShaderFragmentSignature = kSpecialFragmentForm<S> || requires(const typename S::Uniforms& u, const float* in) {
  { S::fragment(u, in) } -> FragmentColour;
} || requires(const typename S::Uniforms& u, const float* in) {
  { S::template fragment<float>(u, in) } -> FragmentColour;
};
template <class S>
concept HasShaderInterpolation = !requires { S::kInterpolation; } || requires {
  { S::kInterpolation } -> std::convertible_to<InterpolationSet<S::kVaryings>>;
};

// The whole interface the top of this file describes.
template <class S>
concept ShaderInterface = HasShaderVertexType<S> && HasShaderUniformsType<S> && HasShaderVaryingCount<S> &&
                 HasShaderVertexSignature<S> && HasShaderFragmentSignature<S> && HasShaderInterpolation<S>;

// Whether S meets ShaderInterface; when it is not, one static_assert says which member is wrong and how
// to write it. Context::draw calls this first and instantiates nothing more for a non-shader, so
// that message is the error a user sees (with the call site in the "required from" note).
template <class S>
constexpr bool checkShaderInterface() {
  if constexpr (!HasShaderVertexType<S>) {
    static_assert(HasShaderVertexType<S>, "softraster: the shader has no `Vertex` type (struct Vertex { ... }; the vertex as stored in the vertex buffer)");
    return false;
  } else if constexpr (!HasShaderUniformsType<S>) {
    static_assert(HasShaderUniformsType<S>, "softraster: the shader has no `Uniforms` type (struct Uniforms { ... }; may be empty)");
    return false;
  } else if constexpr (!HasShaderVaryingCount<S>) {
    static_assert(HasShaderVaryingCount<S>, "softraster: the shader needs `static constexpr int kVaryings` between 0 and softraster::kMaxVaryings (64)");
    return false;
  } else if constexpr (!HasShaderVertexMember<S>) {
    static_assert(HasShaderVertexMember<S>, "softraster: the shader has no `vertex` function (or it is overloaded); write static softraster::Vec4 vertex(const Uniforms&, const Vertex&, float* varyingsOut)");
    return false;
  } else if constexpr (HasNonStaticShaderVertex<S>) {
    static_assert(!HasNonStaticShaderVertex<S>, "softraster: the shader's `vertex` is a non-static member function; make it static");
    return false;
  } else if constexpr (!HasStaticShaderVertex<S>) {
    static_assert(HasStaticShaderVertex<S>, "softraster: the shader's `vertex` takes other parameters; write static softraster::Vec4 vertex(const Uniforms&, const Vertex&, float* varyingsOut)");
    return false;
  } else if constexpr (!HasShaderVertexSignature<S>) {
    static_assert(HasShaderVertexSignature<S>, "softraster: the shader's `vertex` must return softraster::Vec4 (the clip-space position)");
    return false;
  } else if constexpr (!HasShaderFragmentMember<S>) {
    static_assert(HasShaderFragmentMember<S>, "softraster: the shader has no `fragment` function (or it is overloaded); write template <class F> static softraster::Vec4T<F> fragment(const Uniforms&, const F* varyingsIn)");
    return false;
  } else if constexpr (HasNonStaticShaderFragment<S>) {
    static_assert(!HasNonStaticShaderFragment<S>, "softraster: the shader's `fragment` is a non-static member function; make it static");
    return false;
  } else if constexpr (!HasStaticShaderFragment<S>) {
    static_assert(HasStaticShaderFragment<S>, "softraster: the shader's `fragment` takes other parameters; write template <class F> static softraster::Vec4T<F> fragment(const Uniforms&, const F* varyingsIn)");
    return false;
  } else if constexpr (!HasShaderFragmentSignature<S>) {
    static_assert(HasShaderFragmentSignature<S>, "softraster: the shader's `fragment` must return softraster::Vec4T<F> (softraster::Vec4 for F = float: the RGBA colour), or softraster::ColourOutputs<F, K> with K from 1 to kMaxColourAttachments (8)");
    return false;
  } else if constexpr (!HasShaderInterpolation<S>) {
    static_assert(HasShaderInterpolation<S>, "softraster: the shader's `kInterpolation` must be a softraster::InterpolationSet<kVaryings> (one Interpolation per varying)");
    return false;
  } else {
    return true;
  }
}

namespace detail {

// Stands in for a draw parameter whose type a non-shader lacks (its Uniforms, its Vertex), so the
// call to Context::draw still resolves and checkShaderInterface is what reports the mistake.
struct NotAShaderArgument {
  template <class T>
  NotAShaderArgument(const T&) {}  // NOLINT(google-explicit-constructor): accepts what the caller passed
};
template <class S>
struct ShaderParameters {
  using Uniforms = NotAShaderArgument;
  using Vertices = NotAShaderArgument;
};
template <class S>
  requires HasShaderVertexType<S> && HasShaderUniformsType<S>
struct ShaderParameters<S> {
  using Uniforms = typename S::Uniforms;
  using Vertices = std::span<const typename S::Vertex>;
};

}  // namespace detail

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
} || requires(const typename Shader::Uniforms& u, const FloatBatch* v, FragmentBuiltins<FloatBatch>& b) {
  { Shader::template fragment<FloatBatch>(u, v, b) } -> std::same_as<Vec4T<FloatBatch>>;
};

// One pixel's colour (or colours: ColourOutputs) from the shader, whichever form its fragment
// function takes.
template <class Shader>
auto shadeFragment(const typename Shader::Uniforms& uniforms, const float* varyings) {
  if constexpr (requires { Shader::template fragment<float>(uniforms, varyings); }) {
    return Shader::template fragment<float>(uniforms, varyings);
  } else {
    return Shader::fragment(uniforms, varyings);
  }
}

// One pixel's colour (or colours) from a shader that takes the fragment built-ins (UsesFragmentBuiltins).
template <class Shader>
auto shadeFragment(const typename Shader::Uniforms& uniforms, const float* varyings, FragmentBuiltins<float>& builtins) {
  return Shader::template fragment<float>(uniforms, varyings, builtins);
}

// How many colour outputs the shader's fragment function writes: K for ColourOutputs<F, K>, else 1.
template <class Shader>
constexpr int colourOutputsOf() {
  using Uniforms = typename Shader::Uniforms;
  if constexpr (UsesFragmentBuiltins<Shader>) {
    return static_cast<int>(detail::ColourOutputCount<decltype(Shader::template fragment<float>(
        std::declval<const Uniforms&>(), std::declval<const float*>(), std::declval<FragmentBuiltins<float>&>()))>::value);
  } else if constexpr (ShadesQuads<Shader>) {
    return 1;
  } else {
    return static_cast<int>(detail::ColourOutputCount<decltype(shadeFragment<Shader>(
        std::declval<const Uniforms&>(), std::declval<const float*>()))>::value);
  }
}

}  // namespace softraster
