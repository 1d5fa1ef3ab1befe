// How a Context draws: the options that are not Vulkan pipeline state (that is state.hpp) but
// choices of this library: how lavapipe's fmuladd rounds on the machine being matched, and what
// the depth buffer holds.
// Deliberately absent until their issues land: the rasterization method, the thread count.
#pragma once

#include <softraster/detail/fused_multiply_add.hpp>

#include <cstdint>

namespace softraster {

// What the depth buffer holds.
//   Vulkan:   window z (z/w mapped to the viewport's depth range), as Vulkan and lavapipe do.
//   InverseZ: the course's 1/z buffer: 1/w (w = camera-space depth for perspective cameras),
//             interpolated linearly in screen space; NOT a Vulkan mode, so it is never
//             cross-checked bit for bit, only charted. Clear the depth buffer to 0 (infinitely
//             far); compare ops keep their meaning in distance (LESS passes the nearer fragment,
//             i.e. the larger 1/z). Needs D32_SFLOAT; the viewport depth range does not apply.
enum class DepthMode : std::uint8_t { Vulkan, InverseZ };

struct ContextOptions {
  // How lavapipe's fmuladd rounds on the machine being matched: fused where the CPU has FMA.
  bool fusedMultiplyAdd = detail::cpuHasFma();
  DepthMode depthMode = DepthMode::Vulkan;
};

}  // namespace softraster
