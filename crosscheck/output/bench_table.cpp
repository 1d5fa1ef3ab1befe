// The bench's terminal table (see bench_table.hpp).
#include "output/bench_table.hpp"

#include "output/metric_text.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

namespace crosscheck {
namespace {

std::string format(const char* pattern, auto... values) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, values...);
  return buffer;
}

std::string agreementText(const BenchRun& run) {
  if (!run.agreement) return run.renderer == "lavapipe" ? "(reference)" : "-";
  const Comparison& c = *run.agreement;
  const int colour = *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end());
  std::string text = std::to_string(c.coverageMismatches) + "/" + std::to_string(colour) + "/" + depthText(c.depthMaxDelta);
  if (!c.passed()) text += " OUTSIDE TOLERANCE";
  return text;
}

}  // namespace

std::string benchTable(const BenchResults& results) {
  const BenchMachine& m = results.machine;
  std::string out;
  out += format("bench: %zu scene%s, %u timed frame%s after %u warm-up, renderers alternating frame by frame\n",
                results.scenes.size(), results.scenes.size() == 1 ? "" : "s", results.frames,
                results.frames == 1 ? "" : "s", results.warmup);
  out += format("machine: %s, %u cores, memset %.1f GB/s from memory (%.1f GB/s in cache)\n", m.cpu.c_str(), m.cores,
                m.memsetGigabytesPerSecond, m.memsetWarmGigabytesPerSecond);
  if (!m.allocator.empty()) out += "allocator: " + m.allocator + "\n";
  if (!results.allowAvx512) out += "softraster: AVX-512 not allowed (--softraster-no-avx512): its fast path is AVX2 only\n";
  out += "times in ms per frame; setup = make ready + first frame; mem = colour + depth bytes at memset speed from memory\n";
  out += "lavapipe/x = lavapipe median / this median (> 1: softraster is faster)\n";
  out += "differing = pixels whose colour differs from Vulkan's at all; mean = colour mean " + std::string(kAbsDelta) +
         " over pixels and channels\n";
  out += "agreement with Vulkan = coverage mismatches / colour max " + std::string(kAbsDelta) + " / depth max " + kAbsDelta + "\n\n";
  out += format("%-26s %-12s %9s  %-29s %3s %9s %9s %9s %8s %10s %9s %7s  %s\n", "scene", "size", "triangles", "renderer",
                "thr", "median", "min", "setup", "mem", "lavapipe/x", "differing", "mean", "agreement");
  for (const BenchScene& scene : results.scenes) {
    const std::string name = scene.scene.stem().string();
    const std::string size = format("%ux%u", scene.width, scene.height) +
                             (scene.samples > 1 ? format("x%u", scene.samples) : std::string());
    for (const BenchRun& run : scene.runs) {
      const std::string renderer =
          run.method.empty() ? run.renderer : run.renderer + " " + run.method + (run.affineVaryings ? "+affine" : "");
      const std::string ratio = run.ratioVsLavapipe > 0 ? format("%.2f", run.ratioVsLavapipe) : "-";
      std::string differing = "-", mean = "-";
      if (run.agreement) {
        const auto& m = run.agreement->colourMeanDelta;
        differing = std::to_string(run.pixelsDiffering);
        mean = format("%.3f", (m[0] + m[1] + m[2] + m[3]) / 4);
      }
      out += format("%-26s %-12s %9llu  %-29s %3u %9.2f %9.2f %9.2f %8.2f %10s %9s %7s  %s\n", name.c_str(), size.c_str(),
                    static_cast<unsigned long long>(scene.triangles), renderer.c_str(), run.threads,
                    run.medianMilliseconds, run.minMilliseconds, run.setupMilliseconds,
                    scene.memoryLimitMilliseconds, ratio.c_str(), differing.c_str(), mean.c_str(),
                    agreementText(run).c_str());
      if (!run.ok()) out += "    error: " + run.error + "\n";
    }
  }
  return out;
}

}  // namespace crosscheck
