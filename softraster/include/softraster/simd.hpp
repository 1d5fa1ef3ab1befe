// FloatBatch: the SIMD float type a shader twin is written over, beside plain float. A shader's
// fragment function is a template over its float type F; with F = float it shades one pixel,
// with F = FloatBatch it shades kBatchLanes pixels at once (the fast path's 4x2 block: two 2x2
// quads side by side, lane = 4 * row + column). Every operation rounds per lane exactly as the
// same float operation does, so both give the same bits.
//
// Built on GCC/Clang vector extensions rather than a SIMD library, deliberately: an extension
// vector carries no instruction-set attribute of its own, so the same shader source (which a
// library user compiles with their own flags) inlines into the fast path's AVX2 entry point and
// becomes AVX2 code there, while the binary stays portable and picks the instruction set at run
// time. Highway, xsimd and std::experimental::simd bind the instruction set at the definition
// (per-target namespaces, target-specific always_inline operations, or compile-time macros), so a
// shader twin would have to be compiled once per target inside the library's dispatch machinery.
//
// Helpers here follow lavapipe's shader arithmetic (see docs/lavapipe-rules.md): sseMin/sseMax
// are SSE minps/maxps (the second operand when either is NaN). The lane-wise primitives the
// shaders' built-ins are made of (sqrt, fma, floor, truncation to int32, the lanes' bits) are
// written so that they need no instruction set of their own either: sqrt a loop of sqrtf that
// GCC turns into one vsqrtps where AVX is on (or SSE's sqrtps on each half), fma a loop of
// fmaf that GCC turns into one vfmadd where FMA is on, floor and truncation the vector
// conversions; each gives exactly its float counterpart's bits. Integer work on the lanes (a
// float's bits, an exponent) uses NativeMask, the int32 vector, through native().
// FloatBatchPair (below) carries two batches for shaders that take them (shader.hpp, kBlockPairs),
// FloatBatch16Pair two FloatBatch16.
// FloatBatch is FloatLanes<8>; FloatBatch16 (FloatLanes<16>, one zmm register) is the same type at
// 16 lanes, which the fast path shades a block pair with where the CPU has AVX-512: its
// arithmetic, sqrt, fma, sseMin and sseMax are the templates' (16-lane instructions once inlined
// into AVX-512 code); floor has an AVX-512 overload of its own (below, with why).
// Deliberately absent until a shader needs them: transcendental functions (lavapipe's own
// polynomials live with the shaders' built-ins, shaders/lavapipe_builtins.hpp), gathers.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

// The native vectors are 32 bytes wide; outside AVX code GCC notes that passing one by value has
// a different ABI there. FloatBatch itself never travels in a register (its copy constructor says
// why), and the functions that take or return a Native vector are always inlined.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
#if defined(__clang__)  // every lane rounds on its own, whatever the user's flags (math.hpp says why)
#pragma float_control(push)
#pragma clang fp contract(off)
#endif

namespace softraster {

inline constexpr int kBatchLanes = 8;

// The vector-extension types of a batch of 8 or 16 lanes (GCC 12 drops a vector_size that
// depends on a template parameter, leaving a scalar, so each width is spelt out).
template <int Lanes>
struct NativeLanes;
template <>
struct NativeLanes<8> {
  using Float = float __attribute__((vector_size(32)));
  using Int = std::int32_t __attribute__((vector_size(32)));
  using Bits = std::uint32_t __attribute__((vector_size(32)));
};
template <>
struct NativeLanes<16> {
  using Float = float __attribute__((vector_size(64)));
  using Int = std::int32_t __attribute__((vector_size(64)));
  using Bits = std::uint32_t __attribute__((vector_size(64)));
};

// FloatLanes<Lanes>: the batch type at a width. FloatBatch (8 lanes, AVX2) is the one shaders
// are written over; FloatBatch16 (16 lanes) shades a block pair on the fast path with AVX-512.
template <int Lanes>
class FloatLanes {
 public:
  static constexpr int kLanes = Lanes;
  using Native = typename NativeLanes<Lanes>::Float;
  using NativeMask = typename NativeLanes<Lanes>::Int;

  FloatLanes() : v_{} {}
  // Every lane s (implicit, so a shader writes `c * 0.5f` for both of its float types); -0 and
  // NaN stay as they are (no arithmetic). splat() fills the lanes in a loop: the initializer
  // {s, s, s, s, s, s, s, s} became eight vinsertps (and a 32-byte load and two shuffles for
  // a uniform's x, y or z) where a lit shader broadcast its uniforms in the pixel loop; the
  // loop is one vbroadcastss (shufps in baseline code). The lit room: 4.33 -> 4.12 ms.
  FloatLanes(float s) : v_(splat(s)) {}  // NOLINT(google-explicit-constructor)
  [[gnu::always_inline]] explicit FloatLanes(Native v) : v_(v) {}
  // User-provided on purpose: it makes the batch "non-trivial for the purposes of calls", so the
  // C++ ABI passes and returns it through memory whatever the instruction set. A trivially
  // copyable 32-byte vector travels in a ymm register between AVX functions but through memory
  // from baseline ones, so an AVX2 draw loop calling a shader function that was not inlined (the
  // sanitizer build does not flatten) read its arguments from the wrong place. Inlined code, and
  // so every flattened draw, is unchanged.
  FloatLanes(const FloatLanes& other) : v_(other.v_) {}
  FloatLanes& operator=(const FloatLanes& other) = default;

  static FloatLanes load(const float* p) {
    Native v;
    std::memcpy(&v, p, sizeof v);
    return FloatLanes(v);
  }
  void store(float* p) const { std::memcpy(p, &v_, sizeof v_); }

  float operator[](int lane) const { return v_[lane]; }
  [[gnu::always_inline]] Native native() const { return v_; }

  friend FloatLanes operator+(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ + b.v_); }
  friend FloatLanes operator-(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ - b.v_); }
  friend FloatLanes operator*(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ * b.v_); }
  friend FloatLanes operator/(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ / b.v_); }
  friend FloatLanes operator-(FloatLanes a) { return FloatLanes(-a.v_); }
  FloatLanes& operator+=(FloatLanes b) { return *this = *this + b; }
  FloatLanes& operator-=(FloatLanes b) { return *this = *this - b; }
  FloatLanes& operator*=(FloatLanes b) { return *this = *this * b; }
  FloatLanes& operator/=(FloatLanes b) { return *this = *this / b; }

  // Lane-wise a < b ? a : b (SSE minps) and a > b ? a : b (maxps).
  friend FloatLanes sseMin(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ < b.v_ ? a.v_ : b.v_); }
  friend FloatLanes sseMax(FloatLanes a, FloatLanes b) { return FloatLanes(a.v_ > b.v_ ? a.v_ : b.v_); }

 private:
  [[gnu::always_inline]] static Native splat(float s) {
    Native v;
    for (int i = 0; i < Lanes; ++i) v[i] = s;
    return v;
  }

  Native v_;
};

using FloatBatch = FloatLanes<kBatchLanes>;
// A block pair's 16 lanes (block a's eight, then block b's), for AVX-512 code only.
using FloatBatch16 = FloatLanes<2 * kBatchLanes>;

// Lane-wise std::sqrt (IEEE, correctly rounded). Where square roots need not set errno
// (-fno-math-errno, which softraster's CMake target passes on), a loop over the lanes that GCC
// turns into one vsqrtps in the AVX2 entry point (and two sqrtps in baseline code); 128-bit
// quarters through sqrtps otherwise.
template <int Lanes>
FloatLanes<Lanes> sqrt(FloatLanes<Lanes> a) {
  using Native = typename FloatLanes<Lanes>::Native;
  const Native v = a.native();
#if defined(__NO_MATH_ERRNO__)
  Native r;
  for (int i = 0; i < Lanes; ++i) r[i] = __builtin_sqrtf(v[i]);
  return FloatLanes<Lanes>(r);
#elif defined(__x86_64__)
  Native r;
  for (int q = 0; q < Lanes; q += 4) {
    __m128 quarter;
    std::memcpy(&quarter, reinterpret_cast<const float*>(&v) + q, sizeof quarter);
    quarter = _mm_sqrt_ps(quarter);
    std::memcpy(reinterpret_cast<float*>(&r) + q, &quarter, sizeof quarter);
  }
  return FloatLanes<Lanes>(r);
#else
  Native r;
  for (int i = 0; i < Lanes; ++i) r[i] = std::sqrt(v[i]);
  return FloatLanes<Lanes>(r);
#endif
}

// Lane-wise std::fma: a * b + c rounded once.
template <int Lanes>
FloatLanes<Lanes> fma(FloatLanes<Lanes> a, FloatLanes<Lanes> b, FloatLanes<Lanes> c) {
  using Native = typename FloatLanes<Lanes>::Native;
  const Native x = a.native(), y = b.native(), z = c.native();
  Native r;
  for (int i = 0; i < Lanes; ++i) r[i] = __builtin_fmaf(x[i], y[i], z[i]);
  return FloatLanes<Lanes>(r);
}

// Lane-wise std::floor: -0 stays -0; NaN, infinities and lanes of magnitude 2^23 or more (whole
// already) pass as they are.
template <int Lanes>
FloatLanes<Lanes> floor(FloatLanes<Lanes> a) {
  using Native = typename FloatLanes<Lanes>::Native;
  using Ints = typename FloatLanes<Lanes>::NativeMask;
  const Native v = a.native();
  const Ints small = (v < 8388608.0f) & (v > -8388608.0f);  // false for NaN
  const Native whole = __builtin_convertvector(__builtin_convertvector(small ? v : Native{}, Ints), Native);
  const Native down = whole > v ? whole - 1.0f : whole;
  // A lane that comes down to zero keeps its sign: floor(-0) is -0, floor(0.5) is +0.
  const Ints sign = reinterpret_cast<Ints>(v) & (down == 0.0f) & (Ints{} + INT32_MIN);
  const Native signedDown = reinterpret_cast<Native>(reinterpret_cast<Ints>(down) | sign);
  return FloatLanes<Lanes>(small ? signedDown : v);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
// The AVX-512 code a FloatBatch16 runs in (the fast path's wide block pairs, fast/fragments.hpp).
#define SOFTRASTER_WIDE_TARGET gnu::target("avx512f,avx512vl,avx512bw,avx512dq,avx2,fma")
// floor for 16 lanes, as vrndscaleps (round down): the template's bits for every number, -0 and
// infinity (a NaN stays a NaN, quietened). An AVX-512 function of its own because GCC 12 turns a
// 16-lane comparison whose result is used as a vector (the template's masks), written in code
// without that target, into one scalar compare per lane even once inlined into AVX-512 code
// (a 16-lane shader ran slower than the 8-lane pairs); a comparison feeding only a select
// (sseMin, sseMax) is one instruction. Not always_inline: code without the target calls it too
// (FloatBatch16Pair's floor), which flatten inlines into the AVX-512 function around it.
[[SOFTRASTER_WIDE_TARGET]] inline FloatBatch16 floor(FloatBatch16 a) {
  const __m512 v = _mm512_maskz_roundscale_ps(0xffff, reinterpret_cast<__m512>(a.native()), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
  return FloatBatch16(reinterpret_cast<FloatBatch16::Native>(v));
}
#endif

// FloatBatchPair: two blocks' batches as one value, each operation applied to the low half and
// then the high half, so each lane rounds as FloatBatch's does. A long shader (three normalizes
// and a pow per pixel) is one chain of dependent divisions, roots and polynomials per block,
// too long for the CPU to overlap with the next block's; over a pair the two chains are
// interleaved instruction by instruction (the Blinn-Phong quad: 12-17% off its frame). A shader
// takes it with `static constexpr bool kBlockPairs = true` (shader.hpp). FloatBatch16Pair is the
// same over two FloatBatch16 (four blocks, AVX-512): one 16-lane chain is again one chain.
template <class Half>
struct BatchPair {
  Half low, high;
  BatchPair() = default;
  BatchPair(float s) : low(s), high(s) {}  // NOLINT(google-explicit-constructor)
  BatchPair(Half l, Half h) : low(l), high(h) {}
  friend BatchPair operator+(const BatchPair& a, const BatchPair& b) { return {a.low + b.low, a.high + b.high}; }
  friend BatchPair operator-(const BatchPair& a, const BatchPair& b) { return {a.low - b.low, a.high - b.high}; }
  friend BatchPair operator*(const BatchPair& a, const BatchPair& b) { return {a.low * b.low, a.high * b.high}; }
  friend BatchPair operator/(const BatchPair& a, const BatchPair& b) { return {a.low / b.low, a.high / b.high}; }
  friend BatchPair operator-(const BatchPair& a) { return {-a.low, -a.high}; }
  BatchPair& operator+=(const BatchPair& b) { return *this = *this + b; }
  BatchPair& operator-=(const BatchPair& b) { return *this = *this - b; }
  BatchPair& operator*=(const BatchPair& b) { return *this = *this * b; }
  BatchPair& operator/=(const BatchPair& b) { return *this = *this / b; }
  friend BatchPair sseMin(const BatchPair& a, const BatchPair& b) { return {sseMin(a.low, b.low), sseMin(a.high, b.high)}; }
  friend BatchPair sseMax(const BatchPair& a, const BatchPair& b) { return {sseMax(a.low, b.low), sseMax(a.high, b.high)}; }
  friend BatchPair sqrt(const BatchPair& a) { return {sqrt(a.low), sqrt(a.high)}; }
  friend BatchPair fma(const BatchPair& a, const BatchPair& b, const BatchPair& c) {
    return {fma(a.low, b.low, c.low), fma(a.high, b.high, c.high)};
  }
  friend BatchPair floor(const BatchPair& a) { return {floor(a.low), floor(a.high)}; }
};
using FloatBatchPair = BatchPair<FloatBatch>;
using FloatBatch16Pair = BatchPair<FloatBatch16>;

#if defined(SOFTRASTER_WIDE_TARGET)
// A FloatBatchPair's halves as one FloatBatch16 (low: lanes 0-7, high: lanes 8-15), and back:
// where the fast path's AVX2 code and its AVX-512 shading meet (fast/fragments.hpp).
[[SOFTRASTER_WIDE_TARGET]] inline FloatBatch16 joinHalves(const FloatBatchPair& p) {
  return FloatBatch16(__builtin_shufflevector(p.low.native(), p.high.native(), 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15));
}
[[SOFTRASTER_WIDE_TARGET]] inline FloatBatchPair splitHalves(const FloatBatch16& f) {
  const FloatBatch16::Native v = f.native();
  return FloatBatchPair(FloatBatch(__builtin_shufflevector(v, v, 0, 1, 2, 3, 4, 5, 6, 7)),
                        FloatBatch(__builtin_shufflevector(v, v, 8, 9, 10, 11, 12, 13, 14, 15)));
}
#endif

// The same helpers for plain float, so a shader twin calls them unqualified for either type.
inline float sseMin(float a, float b) { return a < b ? a : b; }
inline float sseMax(float a, float b) { return a > b ? a : b; }

}  // namespace softraster

#if defined(__clang__)
#pragma float_control(pop)
#endif
#pragma GCC diagnostic pop
