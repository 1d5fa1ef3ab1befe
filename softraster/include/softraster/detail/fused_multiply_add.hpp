// fmuladd as lavapipe's JIT code computes it: one rounding when the CPU has FMA (LLVM fuses
// llvm.fmuladd there), two roundings otherwise. Used only where lavapipe uses it: the viewport
// transform of shaded vertices and the per-pixel plane evaluation.
#pragma once

#include <cmath>

#if defined(__clang__)  // the separate form must stay two roundings whatever the user's flags
#pragma float_control(push)
#pragma clang fp contract(off)
#endif

namespace softraster::detail {

template <bool Fused>
inline float fmuladd(float a, float b, float c) {
  if constexpr (Fused) {
    return std::fma(a, b, c);
  } else {
    return a * b + c;  // -ffp-contract=off (and under Clang the pragma above) keeps the two roundings
  }
}

// Whether this CPU executes FMA instructions, which decides how lavapipe's fmuladd rounds.
inline bool cpuHasFma() {
#if defined(__x86_64__) || defined(__i386__)
  return __builtin_cpu_supports("fma");
#elif defined(__aarch64__)
  return true;
#else
  return false;
#endif
}

}  // namespace softraster::detail

#if defined(__clang__)
#pragma float_control(pop)
#endif
