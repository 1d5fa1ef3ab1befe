// The runners' clock: steady_clock milliseconds since a start, and the median of frame times (the
// headline on a noisy machine), shared by the conformance runner, the bench and the chart's variants.
// Deliberately nothing else: no statistics beyond the median.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace crosscheck::timing {

using Clock = std::chrono::steady_clock;

inline double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The median of `values` (the mean of the middle two for an even count), 0 for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

}  // namespace crosscheck::timing
