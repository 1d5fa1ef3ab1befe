// softraster's device limits: the VkPhysicalDeviceLimits values that bound what a draw may ask
// for, equal to lavapipe's (Mesa 22.3, measured with vulkaninfo on this project's machines), so a
// state softraster accepts is one Vulkan accepts on lavapipe. Context::draw returns an error for a
// state outside them instead of drawing it; the scene loader quotes the same values.
// Deliberately only the limits a state can exceed: no feature bits, no per-format limits.
#pragma once

namespace softraster {

struct DeviceLimits {
  // VkPhysicalDeviceLimits::lineWidthRange (wideLines is supported).
  static constexpr float kMinLineWidth = 1.0f, kMaxLineWidth = 255.0f;
  // VkPhysicalDeviceLimits::pointSizeRange: a shader's gl_PointSize is clamped to it.
  static constexpr float kMinPointSize = 0.0f, kMaxPointSize = 255.0f;
  // VkPhysicalDeviceLimits::maxViewportDimensions (both) and viewportBoundsRange.
  static constexpr float kMaxViewportDimension = 16384.0f;
  static constexpr float kViewportBoundsMin = -32768.0f, kViewportBoundsMax = 32768.0f;
};

}  // namespace softraster
