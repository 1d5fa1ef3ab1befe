// The compare command's text (see compare_text.hpp).
#include "output/compare_text.hpp"

#include "output/metric_text.hpp"

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
  append(out, "%s: %s\n", path.c_str(), std::string(outcomeName(r.outcome)).c_str());
  if (c.samples > 1) {
    append(out, "  samples compared     %u per pixel (every sample; colour also resolved)\n", c.samples);
  }
  append(out, "  coverage mismatches  %llu (allowed %llu)\n", count(c.coverageMismatches), count(t.maxCoverageMismatches));
  append(out, "  colour max %s RGBA  %d %d %d %d (threshold %d; %s)\n", kAbsDelta, c.colourMaxDelta[0], c.colourMaxDelta[1],
         c.colourMaxDelta[2], c.colourMaxDelta[3], t.colourThreshold, c.colourUnit.c_str());
  if (c.samples > 1) {
    append(out, "  resolved max %s RGBA %d %d %d %d\n", kAbsDelta, c.resolvedColourMaxDelta[0], c.resolvedColourMaxDelta[1],
           c.resolvedColourMaxDelta[2], c.resolvedColourMaxDelta[3]);
  }
  append(out, "  colour mean %s RGBA %.6f %.6f %.6f %.6f\n", kAbsDelta, c.colourMeanDelta[0], c.colourMeanDelta[1],
         c.colourMeanDelta[2], c.colourMeanDelta[3]);
  append(out, "  colour pixels over   %llu (allowed %llu)\n", count(c.colourPixelsOver), count(t.maxColourPixelsOver));
  append(out, "  PSNR (RGB, dB)       %s\n", psnrText(c.psnr).c_str());
  append(out, "  depth max %s        %s (threshold %s)\n", kAbsDelta, depthText(c.depthMaxDelta).c_str(),
         depthText(t.depthThreshold).c_str());
  append(out, "  depth pixels over    %llu (allowed %llu)\n", count(c.depthPixelsOver), count(t.maxDepthPixelsOver));
  append(out, "  stencil mismatches   %llu (allowed 0)\n", count(c.stencilMismatches));
  for (std::size_t k = 0; k < c.moreColour.size(); ++k) {  // colour attachments 1..
    const AttachmentComparison& m = c.moreColour[k];
    append(out, "  attachment %zu max %s   %d %d %d %d (threshold %d; %s), pixels over %llu (allowed %llu)\n", k + 1,
           kAbsDelta, m.colourMaxDelta[0], m.colourMaxDelta[1], m.colourMaxDelta[2], m.colourMaxDelta[3],
           t.colourThreshold, m.colourUnit.c_str(), count(m.colourPixelsOver), count(t.maxColourPixelsOver));
  }
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
