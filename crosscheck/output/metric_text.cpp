// Metric spellings (see metric_text.hpp).
#include "output/metric_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace crosscheck {

std::string psnrText(double psnr) {
  if (std::isinf(psnr) && psnr > 0) return "inf";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", psnr);
  return buffer;
}

std::string depthText(double depth) {
  char buffer[40];
  const float asFloat = static_cast<float>(depth);
  if (std::isfinite(depth) && static_cast<double>(asFloat) == depth) {
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, asFloat);
    if (error == std::errc{}) return std::string(buffer, end);
  }
  std::snprintf(buffer, sizeof buffer, "%.9g", depth);
  return buffer;
}

}  // namespace crosscheck
