// How a Context draws: the options that are not Vulkan pipeline state (that is state.hpp) but
// choices of this library: the method, how lavapipe's fmuladd rounds on the machine being
// matched, and what the depth buffer holds.
// Deliberately absent until their issue lands: the course's methods.
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

// How pixels are found and shaded. Both give the same bits; ExactScalar is the reference the
// fast one is tested against (and a point on the speed/accuracy chart).
//   Exact:       lavapipe's rules; filled single-sample triangles take the SIMD fast path (4x2
//                pixel batches, AVX2) where the CPU has AVX2 and FMA, fmuladd is fused and the
//                shader's fragment function is written over its float type (shader.hpp);
//                everything else takes the scalar path.
//   ExactScalar: lavapipe's rules, one pixel at a time.
enum class Method : std::uint8_t { Exact, ExactScalar };

// Every method, in the order the CLI, the bench and the chart list them.
inline constexpr std::array kMethods{Method::Exact, Method::ExactScalar};

// A method's name on the command line and in results ("exact", "exact-scalar").
constexpr std::string_view methodName(Method method) {
  switch (method) {
    case Method::Exact: return "exact";
    case Method::ExactScalar: return "exact-scalar";
  }
  return "unknown";
}

// The method a name stands for, or nothing for an unknown name.
constexpr std::optional<Method> methodFromName(std::string_view name) {
  for (Method m : kMethods) {
    if (methodName(m) == name) return m;
  }
  return std::nullopt;
}

struct ContextOptions {
  Method method = Method::Exact;
  // Threads that draw, the caller's included: 0 = one per core, 1 = the calling thread only.
  // The Context owns them; the output is the same bits for every count.
  unsigned threads = 0;
  // How lavapipe's fmuladd rounds on the machine being matched: fused where the CPU has FMA.
  bool fusedMultiplyAdd = detail::cpuHasFma();
  DepthMode depthMode = DepthMode::Vulkan;
};

}  // namespace softraster
