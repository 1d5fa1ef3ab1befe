// The limits a comparison breaks (see metrics.hpp).
#include "compare/metrics.hpp"

#include <cstdint>
#include <string>

namespace crosscheck {
namespace {

// "colour_pixels_over 12 > 0": the tolerance key, the count and the count allowed.
std::string formatLimit(const std::string& metric, std::uint64_t value, std::uint64_t limit) {
  return metric + " " + std::to_string(value) + " > " + std::to_string(limit);
}

}  // namespace

std::vector<std::string> limitFailures(const Comparison& c, const Tolerance& tol) {
  std::vector<std::string> failures;
  if (c.coverageMismatches > tol.maxCoverageMismatches)
    failures.push_back(formatLimit("coverage_mismatches", c.coverageMismatches, tol.maxCoverageMismatches));
  if (c.colourPixelsOver > tol.maxColourPixelsOver)
    failures.push_back(formatLimit("colour_pixels_over", c.colourPixelsOver, tol.maxColourPixelsOver));
  if (c.depthPixelsOver > tol.maxDepthPixelsOver)
    failures.push_back(formatLimit("depth_pixels_over", c.depthPixelsOver, tol.maxDepthPixelsOver));
  if (c.stencilMismatches > 0) failures.push_back(formatLimit("stencil_mismatches", c.stencilMismatches, 0));
  for (std::size_t k = 0; k < c.moreColour.size(); ++k) {
    if (c.moreColour[k].colourPixelsOver > tol.maxColourPixelsOver) {
      failures.push_back(formatLimit("colour_pixels_over (attachment " + std::to_string(k + 1) + ")",
                                     c.moreColour[k].colourPixelsOver, tol.maxColourPixelsOver));
    }
  }
  return failures;
}

}  // namespace crosscheck
