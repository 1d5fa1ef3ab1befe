// The instruction sets the draw loops are compiled for, and callCompiledFor: a member function
// compiled as one function of its own for one of them, with everything it calls inlined.
// The draw loop's entry points are flattened for their instruction set (pipeline.hpp), so that
// fmuladd is one FMA instruction and the fast path's AVX2 batches never cross a function
// boundary. Flattening copies a callee into every call site, though, and one function holding the
// whole draw took GCC most of a minute per shader; the stages called from several places (a
// triangle's, a line's and a point's setup and fragments) go through callCompiledFor instead,
// which keeps one copy of each, flattened on its own, for the same instruction set.
// Deliberately no run-time dispatch: the caller picks the instruction set (pipeline.hpp).
//
// SOFTRASTER_FLATTEN is gnu::flatten on every such entry point, unless SOFTRASTER_NO_FLATTEN is
// defined (the sanitizer build defines it): instrumenting flattened draws with ASan and UBSan took
// GCC over ten minutes per shading-model file, against two minutes without. The arithmetic is the
// same either way: a call that is not inlined runs its FloatBatch lanes as SSE halves and std::fma
// as a library call, which round exactly as AVX2 and the FMA instruction do; only speed changes.
#pragma once

#include <cstdint>
#include <utility>

#if defined(SOFTRASTER_NO_FLATTEN)
#define SOFTRASTER_FLATTEN
#else
#define SOFTRASTER_FLATTEN gnu::flatten
#endif

// The baseline's pieces are flattened only where the baseline is what every draw runs (no x86
// dispatch). On x86 it is the unfused fallback alone (fusedMultiplyAdd off: a CPU without FMA,
// where lavapipe rounds every product too), with neither an FMA instruction nor an AVX2 batch
// to keep inline: the compiler's own inlining serves it, and it compiles in a fraction of the
// time (it was a third of each shading model's code).
#if defined(__x86_64__) && defined(__GNUC__)
#define SOFTRASTER_FLATTEN_BASELINE
#else
#define SOFTRASTER_FLATTEN_BASELINE SOFTRASTER_FLATTEN
#endif

namespace softraster::detail {

enum class InstructionSet : std::uint8_t { Baseline, Fma, Avx2Fma };

#if defined(__x86_64__) && defined(__GNUC__)
template <auto Member, class Self, class... Args>
[[gnu::target("avx2,fma"), SOFTRASTER_FLATTEN, gnu::noinline]] void callCompiledForAvx2Fma(Self& self, Args&&... args) {
  (self.*Member)(std::forward<Args>(args)...);
}
template <auto Member, class Self, class... Args>
[[gnu::target("fma"), SOFTRASTER_FLATTEN, gnu::noinline]] void callCompiledForFma(Self& self, Args&&... args) {
  (self.*Member)(std::forward<Args>(args)...);
}
#endif
template <auto Member, class Self, class... Args>
[[SOFTRASTER_FLATTEN_BASELINE, gnu::noinline]] void callCompiledForBaseline(Self& self, Args&&... args) {
  (self.*Member)(std::forward<Args>(args)...);
}

// (self.*Member)(args...), compiled for Isa (for Baseline where the compiler cannot target it).
template <InstructionSet Isa, auto Member, class Self, class... Args>
inline void callCompiledFor(Self& self, Args&&... args) {
#if defined(__x86_64__) && defined(__GNUC__)
  if constexpr (Isa == InstructionSet::Avx2Fma) {
    callCompiledForAvx2Fma<Member>(self, std::forward<Args>(args)...);
  } else if constexpr (Isa == InstructionSet::Fma) {
    callCompiledForFma<Member>(self, std::forward<Args>(args)...);
  } else {
    callCompiledForBaseline<Member>(self, std::forward<Args>(args)...);
  }
#else
  callCompiledForBaseline<Member>(self, std::forward<Args>(args)...);
#endif
}

}  // namespace softraster::detail
