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
//                true for lines and points; the lines and points of an unfilled polygon get
//                the polygon's facing when the shader declares `static constexpr bool
//                kReadsFrontFacing = true` (shader.hpp), as lavapipe gives it only to a shader
//                that reads gl_FrontFacing: declare it whenever the fragment function reads it);
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
//   sampleMaskIn gl_SampleMaskIn[0], per lane (IntOf<F>: int32 for float, IntBatch for
//                FloatBatch): the samples the fragment covers after the sample mask state,
//                bit s for sample s (4x MSAA; with sample shading only the invocation's own
//                sample's bit); 1 with one sample, and for lines drawn with multisampling off
//                (4x MSAA Bresenham lines, as lavapipe draws them). Reading it does not shade
//                per sample;
//   sampleMask   output, gl_SampleMask[0], per lane, taken only from a shader that declares
//                `static constexpr bool kWritesSampleMask = true`: sample s is kept only where
//                bit s is set (with sample shading, bit s of sample s's invocation); with one
//                sample, and on lines drawn with multisampling off, bit 0 keeps or drops the
//                whole fragment. A dropped sample is neither tested nor written. Starts with
//                every bit set.
// MaskOf<F> and the comparisons that make one (lessThan, ...) are written for both float types,
// so one twin serves both paths. A discarded fragment writes nothing: no colour, depth or stencil
// (lavapipe tests depth and stencil after the shader's kill, or early with a deferred write).
// IntOf<F> has GLSL's int operations a mask needs (& | ^ ~ << >> + - *, ==, !=), toInt (GLSL's
// int(x): truncation) and toFloat.
// Deliberately absent: integer division, and ints for anything but these built-ins.
#pragma once

#include <softraster/math.hpp>
#include <softraster/simd.hpp>

#include <cstdint>

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

// GLSL's int per lane of a FloatBatch (the fragment built-ins' sample masks).
class IntBatch {
 public:
  using Native = FloatBatch::NativeMask;
  IntBatch() : v_{} {}
  IntBatch(std::int32_t s) : v_(Native{} + s) {}  // NOLINT(google-explicit-constructor): every lane s
  [[gnu::always_inline]] explicit IntBatch(Native v) : v_(v) {}
  IntBatch(const IntBatch& other) : v_(other.v_) {}  // user-provided: through memory, as FloatBatch
  IntBatch& operator=(const IntBatch& other) = default;
  [[gnu::always_inline]] Native native() const { return v_; }
  std::int32_t operator[](int lane) const { return v_[lane]; }
  friend IntBatch operator&(IntBatch a, IntBatch b) { return IntBatch(a.v_ & b.v_); }
  friend IntBatch operator|(IntBatch a, IntBatch b) { return IntBatch(a.v_ | b.v_); }
  friend IntBatch operator^(IntBatch a, IntBatch b) { return IntBatch(a.v_ ^ b.v_); }
  friend IntBatch operator~(IntBatch a) { return IntBatch(~a.v_); }
  // Wrapping, as GLSL's int arithmetic (done on the unsigned bits: no signed overflow here).
  friend IntBatch operator+(IntBatch a, IntBatch b) { return IntBatch(wrap(a.bits() + b.bits())); }
  friend IntBatch operator-(IntBatch a, IntBatch b) { return IntBatch(wrap(a.bits() - b.bits())); }
  friend IntBatch operator*(IntBatch a, IntBatch b) { return IntBatch(wrap(a.bits() * b.bits())); }
  // Shifts by 0..31 (GLSL leaves others undefined); >> is arithmetic, as GLSL's on int.
  friend IntBatch operator<<(IntBatch a, int n) { return IntBatch(wrap(a.bits() << n)); }
  friend IntBatch operator>>(IntBatch a, int n) { return IntBatch(a.v_ >> n); }

 private:
  using Bits = std::uint32_t __attribute__((vector_size(32)));
  [[gnu::always_inline]] Bits bits() const { return reinterpret_cast<Bits>(v_); }
  [[gnu::always_inline]] static Native wrap(Bits b) { return reinterpret_cast<Native>(b); }
  Native v_;
};

template <class F>
struct IntType;
template <>
struct IntType<float> {
  using Type = std::int32_t;
};
template <>
struct IntType<FloatBatch> {
  using Type = IntBatch;
};
template <class F>
using IntOf = typename IntType<F>::Type;

// GLSL's int(x) (truncation toward zero; out of range or NaN, where GLSL is undefined, gives
// INT32_MIN as x86's cvttss2si does) and float(i).
inline std::int32_t toInt(float x) {
  return x > -2147483904.0f && x < 2147483648.0f ? static_cast<std::int32_t>(x) : INT32_MIN;
}
inline IntBatch toInt(FloatBatch x) {
  const FloatBatch::Native v = x.native();
  const IntBatch::Native inRange = (v > -2147483904.0f) & (v < 2147483648.0f);
  const IntBatch::Native whole = __builtin_convertvector(inRange ? v : FloatBatch::Native{}, IntBatch::Native);
  return IntBatch(inRange ? whole : IntBatch::Native{} + INT32_MIN);
}
inline float toFloat(std::int32_t i) { return static_cast<float>(i); }
inline FloatBatch toFloat(IntBatch i) { return FloatBatch(__builtin_convertvector(i.native(), FloatBatch::Native)); }

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
inline std::int32_t select(bool m, std::int32_t a, std::int32_t b) { return m ? a : b; }
inline IntBatch select(BatchMask m, IntBatch a, IntBatch b) { return IntBatch(m.native() != 0 ? a.native() : b.native()); }

// GLSL's == and != on ints, lane by lane.
inline bool equal(std::int32_t a, std::int32_t b) { return a == b; }
inline bool notEqual(std::int32_t a, std::int32_t b) { return a != b; }
inline BatchMask equal(IntBatch a, IntBatch b) { return BatchMask(a.native() == b.native()); }
inline BatchMask notEqual(IntBatch a, IntBatch b) { return BatchMask(a.native() != b.native()); }

template <class F>
struct FragmentBuiltins {
  Vec4T<F> fragCoord{};          // gl_FragCoord
  bool frontFacing = true;       // gl_FrontFacing
  MaskOf<F> discard{};           // set where the shader executes `discard`
  F fragDepth{};                 // gl_FragDepth: read only from a shader with kWritesFragDepth = true
  int sampleId = 0;              // gl_SampleID
  Vec2 samplePosition{0.5f, 0.5f};  // gl_SamplePosition
  IntOf<F> sampleMaskIn{1};      // gl_SampleMaskIn[0]
  IntOf<F> sampleMask{-1};       // gl_SampleMask[0]: read only from a shader with kWritesSampleMask = true
};

// `if (cond) discard;`
template <class F>
inline void discardIf(FragmentBuiltins<F>& builtins, MaskOf<F> cond) {
  builtins.discard = builtins.discard | cond;
}

}  // namespace softraster

#pragma GCC diagnostic pop
