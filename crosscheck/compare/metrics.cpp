// The limits a comparison breaks (see metrics.hpp).
#include "compare/metrics.hpp"

#include <sstream>

namespace crosscheck {
namespace {

std::string formatLimit(const char* metric, double value, double limit) {
  std::ostringstream s;
  s << metric << " " << value << " > " << limit;
  return s.str();
}

}  // namespace

std::vector<std::string> limitFailures(const Comparison& c, const Tolerance& tol) {
  std::vector<std::string> failures;
  if (c.coverageMismatches > tol.maxCoverageMismatches)
    failures.push_back(formatLimit("coverage_mismatches", double(c.coverageMismatches), double(tol.maxCoverageMismatches)));
  if (c.colourPixelsOver > tol.maxColourPixelsOver)
    failures.push_back(formatLimit("colour_pixels_over", double(c.colourPixelsOver), double(tol.maxColourPixelsOver)));
  if (c.depthPixelsOver > tol.maxDepthPixelsOver)
    failures.push_back(formatLimit("depth_pixels_over", double(c.depthPixelsOver), double(tol.maxDepthPixelsOver)));
  return failures;
}

}  // namespace crosscheck
