// The compare command's text (see compare_text.hpp).
#include "output/compare_text.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace crosscheck {
namespace {

[[gnu::format(printf, 2, 3)]] void append(std::string& out, const char* pattern, ...) {
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof buffer, pattern, args);
  va_end(args);
  out += buffer;
}

unsigned long long count(std::uint64_t n) { return static_cast<unsigned long long>(n); }

void appendScene(std::string& out, const SceneResult& r) {
  const std::string path = r.entry.path.string();
  if (!r.comparison) {  // not compared: the outcome and its error line
    append(out, "%s: %s\n", path.c_str(), std::string(outcomeName(r.outcome)).c_str());
    if (!r.error.empty()) append(out, "  %s\n", r.error.c_str());
    return;
  }
  const Comparison& c = *r.comparison;
  const Tolerance& t = r.tolerance;
  append(out, "%s: %s\n", path.c_str(), c.passed() ? "PASS" : "FAIL");
  append(out, "  coverage mismatches  %llu (max %llu)\n", count(c.coverageMismatches), count(t.maxCoverageMismatches));
  append(out, "  colour max |d| RGBA  %d %d %d %d\n", c.colourMaxDelta[0], c.colourMaxDelta[1], c.colourMaxDelta[2],
         c.colourMaxDelta[3]);
  append(out, "  colour mean |d| RGBA %.6f %.6f %.6f %.6f\n", c.colourMeanDelta[0], c.colourMeanDelta[1],
         c.colourMeanDelta[2], c.colourMeanDelta[3]);
  append(out, "  colour pixels over   %llu (threshold %d, max %llu)\n", count(c.colourPixelsOver), t.colourThreshold,
         count(t.maxColourPixelsOver));
  append(out, "  PSNR                 %s\n", std::isfinite(c.psnr) ? std::to_string(c.psnr).c_str() : "inf (identical)");
  append(out, "  depth max |d|        %.9g\n", c.depthMaxDelta);
  append(out, "  depth pixels over    %llu (threshold %.9g, max %llu)\n", count(c.depthPixelsOver), t.depthThreshold,
         count(t.maxDepthPixelsOver));
  append(out, "  time soft %.2f ms, vulkan %.2f ms\n", r.softMilliseconds, r.vulkanMilliseconds);
  for (const std::string& f : c.failures) append(out, "  over tolerance: %s\n", f.c_str());
}

}  // namespace

std::string compareText(const RunResults& run) {
  std::string out;
  for (const SceneResult& r : run.scenes) appendScene(out, r);
  return out;
}

}  // namespace crosscheck
