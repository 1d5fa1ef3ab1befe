// The fragment built-ins a shader twin may read and write (GLSL's gl_FragCoord, gl_FrontFacing
// and discard), the optional third parameter of its fragment function (shader.hpp):
//   template <class F>
//   static Vec4T<F> fragment(const Uniforms&, const F* varyingsIn, FragmentBuiltins<F>& builtins);
// A twin that takes only two parameters is unchanged and pays nothing. FragmentBuiltins<F> holds
//   fragCoord    x, y the pixel centre (px + 0.5, py + 0.5; also with 4x MSAA, where the fragment
//                is shaded once at the centre; with sample shading the sample's position, the
//                shader then running once per sample), z the fragment's depth as lavapipe
//                interpolates it there (the depth bias added, before the depth-range clamp), w the
//                interpolated 1/w (at the pixel centre, as the varyings, also with sample shading);
//   frontFacing  the primitive's facing (one value per primitive, so a plain bool for both F;
//                true for lines and points);
//   discard      output: the lanes the shader discards (MaskOf<F>: bool for float, BatchMask for
//                FloatBatch), set through discardIf();
//   fragDepth    output, gl_FragDepth, taken only from a shader that declares
//                `static constexpr bool kWritesFragDepth = true` (then every fragment must write
//                it): the depth test and write use it, clamped to [0, 1] (and to the viewport's
//                range with depth clamp) and converted as the format does; no depth bias is
//                added (lavapipe: a late depth test with the shader's z);
//   sampleId, samplePosition  gl_SampleID and gl_SamplePosition: the invocation's sample and its
//                offset in the pixel (kSamplePositions4x; 0 and (0.5, 0.5) with one sample). A
//                shader that reads them declares `static constexpr bool kShadesPerSample = true`
//                (shader.hpp): with 4x MSAA it then runs once per covered sample, as GLSL's
//                gl_SampleID makes it do. One value for every lane (an invocation is one sample).
// MaskOf<F> and the comparisons that make one (lessThan, ...) are written for both float types,
// so one twin serves both paths. A discarded fragment writes nothing: no colour, depth or stencil
// (lavapipe tests depth and stencil after the shader's kill, or early with a deferred write).
// Deliberately absent: gl_SampleMask, gl_SampleMaskIn.
#pragma once

#include <softraster/math.hpp>
#include <softraster/simd.hpp>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

namespace softraster {

// One bool per lane of a FloatBatch (-1 or 0 per lane, as a vector comparison gives it).
class BatchMask {
 public:
  using Native = FloatBatch::NativeMask;
  BatchMask() : m_{} {}
  [[gnu::always_inline]] explicit BatchMask(Native m) : m_(m) {}
  BatchMask(const BatchMask& other) : m_(other.m_) {}  // user-provided: through memory, as FloatBatch
  BatchMask& operator=(const BatchMask& other) = default;
  [[gnu::always_inline]] Native native() const { return m_; }
  bool operator[](int lane) const { return m_[lane] != 0; }
  friend BatchMask operator&(BatchMask a, BatchMask b) { return BatchMask(a.m_ & b.m_); }
  friend BatchMask operator|(BatchMask a, BatchMask b) { return BatchMask(a.m_ | b.m_); }
  friend BatchMask operator!(BatchMask a) { return BatchMask(~a.m_); }

 private:
  Native m_;
};

template <class F>
struct MaskType;
template <>
struct MaskType<float> {
  using Type = bool;
};
template <>
struct MaskType<FloatBatch> {
  using Type = BatchMask;
};
template <class F>
using MaskOf = typename MaskType<F>::Type;

// GLSL's ordered comparisons (false where either side is NaN), lane by lane.
inline bool lessThan(float a, float b) { return a < b; }
inline bool greaterThan(float a, float b) { return a > b; }
inline BatchMask lessThan(FloatBatch a, FloatBatch b) { return BatchMask(a.native() < b.native()); }
inline BatchMask greaterThan(FloatBatch a, FloatBatch b) { return BatchMask(a.native() > b.native()); }

// GLSL's `cond ? a : b` per lane (mix with a bool vector).
inline float select(bool m, float a, float b) { return m ? a : b; }
inline FloatBatch select(BatchMask m, FloatBatch a, FloatBatch b) {
  return FloatBatch(m.native() != 0 ? a.native() : b.native());
}

template <class F>
struct FragmentBuiltins {
  Vec4T<F> fragCoord{};          // gl_FragCoord
  bool frontFacing = true;       // gl_FrontFacing
  MaskOf<F> discard{};           // set where the shader executes `discard`
  F fragDepth{};                 // gl_FragDepth: read only from a shader with kWritesFragDepth = true
  int sampleId = 0;              // gl_SampleID
  Vec2 samplePosition{0.5f, 0.5f};  // gl_SamplePosition
};

// `if (cond) discard;`
template <class F>
inline void discardIf(FragmentBuiltins<F>& builtins, MaskOf<F> cond) {
  builtins.discard = builtins.discard | cond;
}

}  // namespace softraster

#pragma GCC diagnostic pop
