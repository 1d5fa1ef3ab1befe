// fmuladd as lavapipe's JIT code computes it: one rounding when the CPU has FMA (LLVM fuses
// llvm.fmuladd there), two roundings otherwise. Used only where lavapipe uses it: the viewport
// transform of shaded vertices and the per-pixel plane evaluation.
#pragma once

#include <cmath>

namespace softraster::detail {

template <bool Fused>
inline float fmuladd(float a, float b, float c) {
  if constexpr (Fused) {
    return std::fma(a, b, c);
  } else {
    return a * b + c;  // -ffp-contract=off keeps the two roundings
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
