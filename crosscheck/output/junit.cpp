// JUnit XML writer (see junit.hpp).
#include "output/junit.hpp"

#include "output/markup.hpp"
#include "output/metric_text.hpp"
#include "output/summary.hpp"

#include <cmath>
#include <cstdio>

namespace crosscheck {
namespace {

std::string seconds(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f", value);
  return buffer;
}

std::string number(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

std::string systemOut(const SceneResult& r) {
  std::string out = "status: " + std::string(outcomeName(r.outcome)) + "\nscene: " + r.entry.path.string() + "\n";
  if (r.expectation) {
    out += "expected: " + std::string(outcomeName(r.expectation->outcome)) + " (line " +
           std::to_string(r.expectation->line) + ")" + (r.expectation->reason.empty() ? "" : ": " + r.expectation->reason) + "\n";
  }
  if (!r.error.empty()) out += "error: " + r.error + "\n";
  if (r.comparison) {
    const Comparison& c = *r.comparison;
    const Tolerance& t = r.tolerance;
    if (c.samples > 1) out += "samples_compared: " + std::to_string(c.samples) + " per pixel (every sample; colour also resolved)\n";
    out += "coverage_mismatches: " + std::to_string(c.coverageMismatches) + " (allowed " + std::to_string(t.maxCoverageMismatches) + ")\n";
    out += "colour_max_delta_rgba: " + std::to_string(c.colourMaxDelta[0]) + " " + std::to_string(c.colourMaxDelta[1]) + " " +
           std::to_string(c.colourMaxDelta[2]) + " " + std::to_string(c.colourMaxDelta[3]) + " (threshold " +
           std::to_string(t.colourThreshold) + "; " + c.colourUnit + ")\n";
    if (c.samples > 1) {
      out += "resolved_colour_max_delta_rgba: " + std::to_string(c.resolvedColourMaxDelta[0]) + " " +
             std::to_string(c.resolvedColourMaxDelta[1]) + " " + std::to_string(c.resolvedColourMaxDelta[2]) + " " +
             std::to_string(c.resolvedColourMaxDelta[3]) + "\n";
    }
    out += "colour_mean_delta_rgba: " + number("%.6f", c.colourMeanDelta[0]) + number(" %.6f", c.colourMeanDelta[1]) +
           number(" %.6f", c.colourMeanDelta[2]) + number(" %.6f", c.colourMeanDelta[3]) + "\n";
    out += "colour_pixels_over: " + std::to_string(c.colourPixelsOver) + " (allowed " + std::to_string(t.maxColourPixelsOver) + ")\n";
    out += "psnr: " + psnrText(c.psnr) + "\n";
    for (std::size_t k = 0; k < c.moreColour.size(); ++k) {  // colour attachments 1..
      const AttachmentComparison& m = c.moreColour[k];
      out += "attachment_" + std::to_string(k + 1) + "_colour_max_delta_rgba: " + std::to_string(m.colourMaxDelta[0]) +
             " " + std::to_string(m.colourMaxDelta[1]) + " " + std::to_string(m.colourMaxDelta[2]) + " " +
             std::to_string(m.colourMaxDelta[3]) + " (threshold " + std::to_string(t.colourThreshold) + "; " +
             m.colourUnit + "), pixels over " + std::to_string(m.colourPixelsOver) + "\n";
    }
    out += "depth_max_delta: " + depthText(c.depthMaxDelta) + " (threshold " + depthText(t.depthThreshold) + ")\n";
    out += "depth_pixels_over: " + std::to_string(c.depthPixelsOver) + " (allowed " + std::to_string(t.maxDepthPixelsOver) + ")\n";
    out += "stencil_mismatches: " + std::to_string(c.stencilMismatches) + " (allowed 0)\n";
    out += "time_ms: soft " + number("%.3f", r.softMilliseconds) + ", vulkan " + number("%.3f", r.vulkanMilliseconds) +
           ", scene " + number("%.3f", r.milliseconds) + "\n";
    out += "step_ms: load " + number("%.3f", r.timings.load) + ", softraster " + number("%.3f", r.timings.soft) +
           ", vulkan " + number("%.3f", r.timings.vulkan) + ", compare " + number("%.3f", r.timings.compare) + ", images " +
           number("%.3f", r.timings.images) + "\n";
  }
  for (const SceneImage& image : r.images) out += "image " + image.kind + ": " + (r.imageRoot / image.file).string() + "\n";
  return out;
}

}  // namespace

std::string junitXml(const RunResults& run) {
  const std::vector<SceneResult>& results = run.scenes;
  const Counts counts = countResults(results);
  const std::size_t failures = counts.of(Outcome::Fail) + counts.of(Outcome::UnexpectedPass);
  const std::size_t errors = counts.of(Outcome::Crash) + counts.of(Outcome::Timeout);
  const std::size_t skipped = counts.of(Outcome::Skip) + counts.of(Outcome::ExpectedFail);
  const std::string totals = " tests=\"" + std::to_string(results.size()) + "\" failures=\"" + std::to_string(failures) +
                             "\" errors=\"" + std::to_string(errors) + "\" skipped=\"" + std::to_string(skipped) +
                             "\" time=\"" + seconds(run.seconds) + "\"";
  const std::string suite = escapeMarkup(run.suiteName);
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  xml += "<testsuites name=\"" + suite + "\"" + totals + ">\n";
  xml += "  <testsuite name=\"" + suite + "\"" + totals;
  if (run.finished != 0) xml += " timestamp=\"" + escapeMarkup(utcTime(run.finished, "%Y-%m-%dT%H:%M:%S")) + "\"";
  xml += ">\n";
  // The shard is a property, never part of a name: a scene's identity is the same in every shard.
  if (run.shard.count > 1) {
    xml += "    <properties>\n      <property name=\"shard\" value=\"" + std::to_string(run.shard.index) + "/" +
           std::to_string(run.shard.count) + "\"/>\n    </properties>\n";
  }
  for (const SceneResult& r : results) {
    xml += "    <testcase classname=\"" + suite + "\" name=\"" + escapeMarkup(r.entry.name) + "\" file=\"" +
           escapeMarkup(r.entry.path.string()) + "\" time=\"" + seconds(r.milliseconds / 1000.0) + "\">\n";
    const std::string message = escapeMarkup(resultDetail(r));
    const std::string reason = r.expectation && !r.expectation->reason.empty() ? " [" + r.expectation->reason + "]" : "";
    switch (r.outcome) {
      case Outcome::Pass: break;
      case Outcome::Skip:
        xml += "      <skipped message=\"" + escapeMarkup("skipped by expectations" + reason) + "\"/>\n";
        break;
      case Outcome::ExpectedFail:
        xml += "      <skipped message=\"" + escapeMarkup("expected failure: " + resultDetail(r) + reason) + "\"/>\n";
        break;
      case Outcome::Fail:
        xml += "      <failure type=\"Fail\" message=\"" + message + "\"/>\n";
        break;
      case Outcome::UnexpectedPass:
        xml += "      <failure type=\"UnexpectedPass\" message=\"" + message + "\"/>\n";
        break;
      case Outcome::Crash:
        xml += "      <error type=\"Crash\" message=\"" + message + "\"/>\n";
        break;
      case Outcome::Timeout:
        xml += "      <error type=\"Timeout\" message=\"" + message + "\"/>\n";
        break;
    }
    xml += "      <system-out>" + escapeMarkup(systemOut(r)) + "</system-out>\n";
    xml += "    </testcase>\n";
  }
  xml += "  </testsuite>\n</testsuites>\n";
  return xml;
}

softraster::Status writeJUnit(const std::filesystem::path& file, const RunResults& run) {
  return writeDocument(file, junitXml(run), "JUnit file");
}

}  // namespace crosscheck
