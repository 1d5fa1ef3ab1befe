// The HTML report and its pixel data (see report.hpp).
#include "output/report/report.hpp"

#include "output/artifacts.hpp"  // kPreviewSize
#include "output/chart_svg.hpp"
#include "run/deviations.hpp"  // knownDeviations
#include "run/stability.hpp"  // variantPasses, kStabilityReference
#include "output/markup.hpp"
#include "output/metric_text.hpp"
#include "output/summary.hpp"
#include "report_assets.hpp"  // generated from report.css and report.js

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <limits>
#include <iterator>
#include <numeric>
#include <sstream>
#include <tuple>

namespace crosscheck {
namespace {

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t b0 = bytes[i], b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t triple = (b0 << 16) | (b1 << 8) | b2;
    out += kAlphabet[(triple >> 18) & 63];
    out += kAlphabet[(triple >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(triple >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[triple & 63] : '=';
  }
  return out;
}

// zlib format (what DecompressionStream('deflate') reads).
std::vector<std::uint8_t> compressed(const std::vector<std::uint8_t>& bytes) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::vector<std::uint8_t> out(size);
  if (compress2(out.data(), &size, bytes.data(), static_cast<uLong>(bytes.size()), 6) != Z_OK) return {};
  out.resize(size);
  return out;
}

std::vector<std::uint8_t> littleEndian(const std::vector<float>& values) {
  std::vector<std::uint8_t> bytes(values.size() * 4);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto bits = std::bit_cast<std::uint32_t>(values[i]);
    for (int b = 0; b < 4; ++b) bytes[4 * i + b] = static_cast<std::uint8_t>(bits >> (8 * b));
  }
  return bytes;
}

std::string fixed(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

int outcomeRank(Outcome s) {
  switch (s) {
    case Outcome::Crash: return 0;
    case Outcome::Timeout: return 1;
    case Outcome::Fail: return 2;
    case Outcome::UnexpectedPass: return 3;
    case Outcome::ExpectedFail: return 4;
    case Outcome::Pass: return 5;
    case Outcome::Skip: return 6;
  }
  return 7;
}

std::string e(std::string_view text) { return escapeMarkup(text); }

std::string url(const std::filesystem::path& relative) { return e(encodeUrlPath(relative.generic_string())); }

const SceneImage* imageOf(const SceneResult& r, std::string_view kind) {
  for (const SceneImage& image : r.images) {
    if (image.kind == kind) return &image;
  }
  return nullptr;
}

// A metric's value as the baseline marks show it: whole numbers as such, PSNR of identical images
// "inf" (as psnrText spells it, metric_text.hpp), anything else with six significant digits.
std::string metricValue(double value) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (value == std::floor(value) && std::fabs(value) < 1e15) return fixed("%.0f", value);
  return fixed("%.6g", value);
}

// The change of one summary table column against the baseline, or null.
const MetricChange* changeOf(const SceneVersusBaseline* versus, std::string_view metric) {
  if (!versus) return nullptr;
  for (const MetricChange& change : versus->changes) {
    if (change.metric == metric) return &change;
  }
  return nullptr;
}

// One numeric table cell: data-v for sorting, the shown text, "over" when past its limit and
// "changed" (with the baseline's value in its title) when it differs from the baseline.
std::string numberCell(double sortValue, const std::string& shown, bool over, const std::string& title = "",
                       const MetricChange* change = nullptr) {
  std::string v = std::isinf(sortValue) ? (sortValue > 0 ? "Infinity" : "-Infinity") : fixed("%.9g", sortValue);
  std::string cell =
      "<td class=\"num" + std::string(over ? " over" : "") + (change ? " changed" : "") + "\" data-v=\"" + v + "\"";
  std::string tip = title;
  if (change) tip += (tip.empty() ? "" : "; ") + std::string("baseline ") + metricValue(change->before);
  if (!tip.empty()) cell += " title=\"" + e(tip) + "\"";
  return cell + ">" + e(shown) + "</td>";
}

std::string emptyCell() { return "<td class=\"num none\" data-v=\"\">&#8212;</td>"; }

std::string badge(Outcome s) {
  return "<span class=\"badge st-" + std::string(outcomeName(s)) + "\">" + std::string(outcomeName(s)) + "</span>";
}

std::string rgbaText(const std::array<int, 4>& v) {
  return std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + " " + std::to_string(v[3]);
}

std::string meanText(const std::array<double, 4>& v) {
  return fixed("%.4f", v[0]) + fixed(" %.4f", v[1]) + fixed(" %.4f", v[2]) + fixed(" %.4f", v[3]);
}

// A file linked from the report: relative to its folder, so the link survives moving both
// together; absolute when there is no folder or no relative path.
std::filesystem::path linkFrom(const std::filesystem::path& reportDir, const std::filesystem::path& file) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
  if (reportDir.empty() || ec) return absolute;
  const std::filesystem::path relative = std::filesystem::relative(absolute, std::filesystem::absolute(reportDir, ec), ec);
  return ec || relative.empty() ? absolute : relative;
}

// The scene's stable anchor (documented in the README): #scene=NAME.
std::string anchorOf(const SceneResult& r) { return "#scene=" + e(encodeUrlPath(r.entry.name)); }

// A small render of the scene (its PNG, scaled by the browser), or nothing when none was written.
std::string thumbnail(const SceneResult& r, std::string_view kind, const std::string& title) {
  const SceneImage* image = imageOf(r, kind);
  if (!image && kind == "soft") image = imageOf(r, "preview");  // a bit-identical scene's one image
  if (!image) return "";
  return "<img class=\"thumb\" loading=\"lazy\" decoding=\"async\" src=\"" + url(image->file) + "\" alt=\"" +
         e(title + " of " + r.entry.name) + "\" title=\"" + e(title) + "\">";
}

// The marks of a scene against the baseline, as words: "new-failure", "fixed", "changed", "added".
std::string baselineMarks(const SceneVersusBaseline* versus) {
  if (!versus) return "";
  std::string marks;
  const auto add = [&](bool on, const char* mark) {
    if (on) marks += (marks.empty() ? "" : " ") + std::string(mark);
  };
  add(versus->newFailure, "new-failure");
  add(versus->fixed, "fixed");
  add(!versus->changes.empty(), "changed");
  add(!versus->inBaseline, "added");
  return marks;
}

// The attributes the page's filters read: the status, the name and the marks against a baseline.
std::string filterAttributes(const SceneResult& r, const SceneVersusBaseline* versus = nullptr) {
  std::string a = " data-status=\"" + std::string(outcomeName(r.outcome)) + "\" data-unexpected=\"" +
                  (isUnexpected(r.outcome) ? "1" : "0") + "\" data-name=\"" + e(r.entry.name) + "\"";
  if (versus) a += " data-baseline=\"" + baselineMarks(versus) + "\"";
  return a;
}

// What changed against the baseline, one line: "Pass → Fail; coverage mismatches 0 → 12".
std::string baselineText(const SceneVersusBaseline& versus, Outcome now) {
  if (!versus.inBaseline) return "not in the baseline";
  std::string text = std::string(outcomeName(versus.before)) + " \xE2\x86\x92 " + std::string(outcomeName(now));
  if (versus.before == now) text = "baseline " + std::string(outcomeName(now));
  for (const MetricChange& change : versus.changes) {
    text += "; " + change.metric + " " + metricValue(change.before) + " \xE2\x86\x92 " + metricValue(change.after);
  }
  return text;
}

// The badges beside a scene's name.
std::string baselineBadges(const SceneVersusBaseline* versus, Outcome now) {
  if (!versus) return "";
  const std::string title = e(baselineText(*versus, now));
  std::string badges;
  const auto add = [&](bool on, const char* mark, const char* text) {
    if (on) badges += " <span class=\"mark mark-" + std::string(mark) + "\" title=\"" + title + "\">" + text + "</span>";
  };
  add(versus->newFailure, "new-failure", "new failure");
  add(versus->fixed, "fixed", "fixed");
  add(!versus->changes.empty(), "changed", "metrics changed");
  add(!versus->inBaseline, "added", "new scene");
  return badges;
}

std::string summaryRow(const SceneResult& r, std::size_t rank, const SceneVersusBaseline* versus) {
  std::string row = "<tr class=\"st-" + std::string(outcomeName(r.outcome)) + "\" data-rank=\"" + std::to_string(rank) + "\"" +
                    filterAttributes(r, versus) + ">";
  row += "<td data-v=\"" + std::to_string(outcomeRank(r.outcome)) + "\">" + badge(r.outcome) + "</td>";
  row += "<td class=\"thumbs\">" + thumbnail(r, "soft", "softraster") + "</td>";
  row += "<td data-v=\"" + e(r.entry.name) + "\"><a href=\"" + anchorOf(r) + "\">" + e(r.entry.name) + "</a>" +
         baselineBadges(versus, r.outcome);
  if (!r.error.empty()) row += "<div class=\"row-error\">" + e(r.error) + "</div>";
  row += "</td>";
  if (r.comparison) {
    const Comparison& c = *r.comparison;
    const Tolerance& t = r.tolerance;
    const int colourMax = *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end());
    const double colourMean = *std::max_element(c.colourMeanDelta.begin(), c.colourMeanDelta.end());
    // The metric names are baseline.hpp's (the columns' headings).
    row += numberCell(double(c.coverageMismatches), std::to_string(c.coverageMismatches),
                      c.coverageMismatches > t.maxCoverageMismatches, "allowed " + std::to_string(t.maxCoverageMismatches),
                      changeOf(versus, "coverage mismatches"));
    row += numberCell(double(c.colourPixelsOver), std::to_string(c.colourPixelsOver), c.colourPixelsOver > t.maxColourPixelsOver,
                      "pixels with a channel |\xCE\x94| over " + std::to_string(t.colourThreshold) +
                          "; allowed " + std::to_string(t.maxColourPixelsOver),
                      changeOf(versus, "colour pixels over"));
    row += numberCell(colourMax, std::to_string(colourMax), colourMax > t.colourThreshold,
                      "RGBA " + rgbaText(c.colourMaxDelta) + "; threshold " + std::to_string(t.colourThreshold) + "; " +
                          c.colourUnit,
                      changeOf(versus, "colour max |\xCE\x94|"));
    row += numberCell(colourMean, fixed("%.4f", colourMean), false, "RGBA " + meanText(c.colourMeanDelta),
                      changeOf(versus, "colour mean |\xCE\x94|"));
    row += numberCell(c.psnr, psnrText(c.psnr), false, "", changeOf(versus, "PSNR"));
    row += numberCell(double(c.depthPixelsOver), std::to_string(c.depthPixelsOver), c.depthPixelsOver > t.maxDepthPixelsOver,
                      "pixels with depth |\xCE\x94| over " + depthText(t.depthThreshold) +
                          "; allowed " + std::to_string(t.maxDepthPixelsOver),
                      changeOf(versus, "depth pixels over"));
    row += numberCell(c.depthMaxDelta, depthText(c.depthMaxDelta), c.depthMaxDelta > t.depthThreshold,
                      "threshold " + depthText(t.depthThreshold), changeOf(versus, "depth max |\xCE\x94|"));
    row += numberCell(double(c.stencilMismatches), std::to_string(c.stencilMismatches), c.stencilMismatches > 0,
                      "pixels whose stored stencil differs; allowed 0", changeOf(versus, "stencil mismatches"));
    row += numberCell(r.softMilliseconds, fixed("%.2f", r.softMilliseconds), false);
    row += numberCell(r.vulkanMilliseconds, fixed("%.2f", r.vulkanMilliseconds), false);
  } else {
    for (int i = 0; i < 10; ++i) row += emptyCell();
  }
  return row + "</tr>\n";
}

// The lines an expectations file would need for this run's unexpected results to be expected
// (run/expectations.hpp's format); an UnexpectedPass is a comment: its line is to be removed.
std::string expectationsLines(const RunResults& run) {
  std::string lines;
  for (const std::size_t i : worstFirst(run.scenes)) {
    const SceneResult& r = run.scenes[i];
    if (!isUnexpected(r.outcome)) continue;
    if (r.outcome == Outcome::UnexpectedPass) {
      lines += "# " + r.entry.name + " passes now: remove its line" +
               (r.expectation ? " (expectations line " + std::to_string(r.expectation->line) + ")" : std::string()) + "\n";
      continue;
    }
    std::string reason = resultDetail(r);
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    lines += r.entry.name + "," + std::string(outcomeName(r.actual)) + (reason.empty() ? "" : " # " + reason) + "\n";
  }
  return lines;
}

// The command that reproduces one scene: compare with the run's options that change a render.
std::string reproduceCommand(const RunResults& run, const SceneResult& r) {
  std::string command = "crosscheck compare " + r.entry.path.generic_string();
  if (!run.renderArguments.empty()) command += " " + run.renderArguments;
  return command + " -o out/" + r.entry.name;
}

std::string metricRow(const std::string& metric, const std::string& measured, const std::string& allowed, bool over) {
  return "<tr><th>" + e(metric) + "</th><td" + (over ? " class=\"over\"" : "") + ">" + e(measured) + "</td><td>" +
         e(allowed) + "</td></tr>";
}

std::string metricsTable(const SceneResult& r) {
  const Tolerance& t = r.tolerance;
  std::string rows;
  if (r.comparison) {
    const Comparison& c = *r.comparison;
    if (c.samples > 1) {
      rows += metricRow("samples compared", std::to_string(c.samples) + " per pixel (every sample; colour also resolved)", "",
                        false);
    }
    rows += metricRow("coverage mismatches", std::to_string(c.coverageMismatches),
                      "\xE2\x89\xA4 " + std::to_string(t.maxCoverageMismatches), c.coverageMismatches > t.maxCoverageMismatches);
    rows += metricRow("colour pixels over threshold", std::to_string(c.colourPixelsOver),
                      "\xE2\x89\xA4 " + std::to_string(t.maxColourPixelsOver), c.colourPixelsOver > t.maxColourPixelsOver);
    rows += metricRow("colour max |\xCE\x94| RGBA (" + c.colourUnit + ")", rgbaText(c.colourMaxDelta),
                      "threshold " + std::to_string(t.colourThreshold),
                      *std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end()) > t.colourThreshold);
    if (c.samples > 1) rows += metricRow("resolved colour max |\xCE\x94| RGBA", rgbaText(c.resolvedColourMaxDelta), "", false);
    rows += metricRow("colour mean |\xCE\x94| RGBA", meanText(c.colourMeanDelta), "", false);
    rows += metricRow("PSNR (RGB, dB)", psnrText(c.psnr), "", false);
    rows += metricRow("depth pixels over threshold", std::to_string(c.depthPixelsOver),
                      "\xE2\x89\xA4 " + std::to_string(t.maxDepthPixelsOver), c.depthPixelsOver > t.maxDepthPixelsOver);
    rows += metricRow("depth max |\xCE\x94|", depthText(c.depthMaxDelta), "threshold " + depthText(t.depthThreshold),
                      c.depthMaxDelta > t.depthThreshold);
    rows += metricRow("stencil mismatches", std::to_string(c.stencilMismatches), "0", c.stencilMismatches > 0);
    for (std::size_t k = 0; k < c.moreColour.size(); ++k) {  // colour attachments 1.. (their images are not shown)
      const AttachmentComparison& m = c.moreColour[k];
      const std::string name = "attachment " + std::to_string(k + 1);
      rows += metricRow(name + " colour pixels over threshold", std::to_string(m.colourPixelsOver),
                        "\xE2\x89\xA4 " + std::to_string(t.maxColourPixelsOver),
                        m.colourPixelsOver > t.maxColourPixelsOver);
      rows += metricRow(name + " colour max |\xCE\x94| RGBA (" + m.colourUnit + ")", rgbaText(m.colourMaxDelta),
                        "threshold " + std::to_string(t.colourThreshold),
                        *std::max_element(m.colourMaxDelta.begin(), m.colourMaxDelta.end()) > t.colourThreshold);
    }
    rows += metricRow("time", fixed("softraster %.2f ms", r.softMilliseconds) + fixed(", Vulkan %.2f ms", r.vulkanMilliseconds) +
                      fixed(", whole scene %.2f ms", r.milliseconds), "", false);
  } else if (r.loaded) {
    rows += metricRow("tolerance", "", "colour threshold " + std::to_string(t.colourThreshold) +
                      ", depth threshold " + depthText(t.depthThreshold) + ", coverage mismatches \xE2\x89\xA4 " +
                      std::to_string(t.maxCoverageMismatches) + ", colour pixels over \xE2\x89\xA4 " +
                      std::to_string(t.maxColourPixelsOver) + ", depth pixels over \xE2\x89\xA4 " +
                      std::to_string(t.maxDepthPixelsOver), false);
  }
  if (rows.empty()) return "";
  return "<table class=\"metrics\"><tr><th>metric</th><th>measured</th><th>allowed</th></tr>" + rows + "</table>\n";
}

// Large images fit their box (0); small ones grow by a power of two up to about 320 pixels wide.
std::uint32_t defaultZoom(const SceneResult& r) {
  if (r.width > 440) return 0;
  std::uint32_t zoom = 1;
  while (zoom < 8 && 2 * zoom * r.width <= 320) zoom *= 2;
  return zoom;
}

std::string figure(const SceneResult& r, std::string_view kind, const std::string& caption, const std::string& extra = "") {
  const SceneImage* image = imageOf(r, kind);
  if (!image) return "";
  const std::uint32_t zoom = defaultZoom(r);
  return "<figure><figcaption>" + caption + "</figcaption><div class=\"view" + (zoom ? " zoomed" : "") +
         "\"><img loading=\"lazy\" decoding=\"async\" src=\"" + url(image->file) + "\" width=\"" + std::to_string(r.width) +
         "\" height=\"" + std::to_string(r.height) + "\"" +
         (zoom ? " style=\"width:" + std::to_string(zoom * r.width) + "px\"" : std::string()) + " alt=\"" +
         e(caption + " of " + r.entry.name) + "\"" + extra + "><div class=\"marker\"></div></div></figure>\n";
}

// An MSAA scene's samples as stored before the resolve: softraster's, Vulkan's and their
// difference for the sample the menu picks (report.js swaps the three images' sources from their
// data-samples lists), so a sample that differs while the resolve agrees can be seen.
std::string sampleViews(const SceneResult& r) {
  std::string menu, lists[3];
  int samples = 0;
  for (; imageOf(r, "soft.sample" + std::to_string(samples)); ++samples) {
    const std::string n = std::to_string(samples);
    const SceneImage* images[3] = {imageOf(r, "soft.sample" + n), imageOf(r, "vulkan.sample" + n), imageOf(r, "sample" + n + ".diff")};
    for (int k = 0; k < 3; ++k) lists[k] += (samples ? " " : "") + (images[k] ? url(images[k]->file) : std::string());
    menu += "<option value=\"" + n + "\">" + n + "</option>";
  }
  const auto pickable = [&](int k) { return " data-samples=\"" + lists[k] + "\""; };
  return "<div class=\"tools\"><label>sample <select class=\"sample-pick\">" + menu + "</select></label><span>each of the " +
         std::to_string(samples) + " samples as stored before the resolve (compared one by one, as the metrics are)</span></div>\n"
         "<div class=\"views\">\n" +
         figure(r, "soft.sample0", "softraster, sample <b class=\"sample-label\">0</b>", pickable(0)) +
         figure(r, "vulkan.sample0", "Vulkan, sample <b class=\"sample-label\">0</b>", pickable(1)) +
         figure(r, "sample0.diff", "difference of sample <b class=\"sample-label\">0</b> (heatmap)", pickable(2)) + "</div>\n";
}

// The diff heatmap's colours (diffHeatmap); `threshold` is the scene's colour threshold, or
// "T" for the legend at the top of the page.
std::string colourLegend(const std::string& threshold) {
  return "<div class=\"legend\"><span><i class=\"swatch sw-equal\"></i>equal</span>"
         "<span><i class=\"swatch sw-within\"></i>differs, |\xCE\x94| \xE2\x89\xA4 " + threshold +
         "</span><span><i class=\"swatch sw-over\"></i>|\xCE\x94| &gt; " + threshold +
         ", red to yellow by size (yellow at |\xCE\x94| \xE2\x89\xA5 128)</span>"
         "<span><i class=\"swatch sw-coverage\"></i>covered by one renderer only</span></div>";
}

std::string depthLegend(double threshold) {
  return "<div class=\"legend\"><span><i class=\"swatch sw-equal\"></i>equal</span>"
         "<span><i class=\"swatch sw-within\"></i>|\xCE\x94z| \xE2\x89\xA4 " + e(depthText(threshold)) +
         "</span><span><i class=\"swatch sw-depth-over\"></i>over, log scale (yellow \xE2\x89\xA5 2<sup>16</sup>\xC3\x97 threshold)</span>"
         "<span><i class=\"swatch sw-coverage\"></i>NaN in one only</span></div>";
}

// A scene's two chart panels (coverage, colour), when its variants were drawn.
std::string sceneChart(const SceneResult& r, const std::vector<std::string>& labels) {
  if (!r.variants) return "";
  RunResults one;
  one.scenes.push_back(r);
  const ChartSet set = chartFromResults(one);
  return "<div class=\"chart\" data-scene=\"" + e(r.entry.name) + "\"><p class=\"run\">speed against accuracy: " +
         std::to_string(r.variants->frames) + " timed frames per method and option, lavapipe's median " +
         fixed("%.3f", r.variants->lavapipeMilliseconds) + " ms</p>" +
         scenePanelSvg(set.scenes.front(), ChartMetric::CoverageMismatches, labels) +
         scenePanelSvg(set.scenes.front(), ChartMetric::ColourMaxDelta, labels) + "</div>\n";
}

std::string countText(const std::optional<std::uint64_t>& v) { return v ? std::to_string(*v) : "&#8212;"; }

// The overview chart over every scene with variants, and the legend.
std::string chartSection(const ChartSet& set, const std::vector<std::string>& labels) {
  std::string s = "<h2 id=\"chart\">Speed against accuracy</h2>\n<p class=\"run\">Every method and option drawn a "
                  "few timed frames per scene after the comparison (each scene's section has its own two panels: "
                  "coverage mismatches and colour max |\xCE\x94| against frame time, lavapipe's median as the dashed "
                  "line, the Pareto front in orange). Below: every scene at once, speed relative to lavapipe against "
                  "coverage mismatches. Hover a marker for its numbers; <code>--no-chart</code> leaves this out.</p>\n";
  s += "<div class=\"chart chart-overview-box\">" + overviewPanelSvg(set, labels) + legendSvg(labels) + "</div>\n";
  return s;
}

// The stability cases (scenes of a stability/ folder) x variants: pass or fail with the numbers.
std::string stabilitySection(const RunResults& run) {
  std::string rows;
  std::size_t cases = 0, failing = 0;
  for (const SceneResult& r : run.scenes) {
    if (!r.stabilityCase || !r.variants) continue;
    ++cases;
    for (const VariantRun& v : r.variants->runs) {
      const bool pass = variantPasses(v);
      failing += !pass;
      rows += "<tr class=\"" + std::string(pass ? "st-Pass" : "st-Fail") + "\"><td><a href=\"" + anchorOf(r) + "\">" +
              e(r.entry.name) + "</a></td><td>" + e(v.label) + "</td><td>" + badge(pass ? Outcome::Pass : Outcome::Fail) +
              "</td><td class=\"num\">" + countText(v.differingPixels) + "</td><td class=\"num\">" +
              countText(v.coverageMismatches) + "</td><td class=\"num\">" +
              (v.colourMaxDelta ? std::to_string(*v.colourMaxDelta) : "&#8212;") + "</td><td class=\"num\">" +
              (v.hits ? std::to_string(v.hits->cracks) : "&#8212;") + "</td><td class=\"num\">" +
              (v.hits ? std::to_string(v.hits->doubleHits) : "&#8212;") + "</td><td class=\"num\">" +
              fixed("%.3f", v.medianMilliseconds) + "</td><td>" + e(v.error) + "</td></tr>\n";
    }
  }
  if (cases == 0) return "";
  return "<h2 id=\"stability\">Stability</h2>\n<p class=\"run\">" + std::to_string(cases) +
         " cases (the scenes of a stability/ folder) with every method and option: a row passes when every pixel "
         "equals lavapipe's and the hit counts match (cracks: pixels lavapipe draws and the method leaves empty; "
         "double hits: pixels the method draws more often than lavapipe). " +
         std::to_string(failing) + " rows fail; " + std::string(kStabilityReference) + " must pass every case.</p>\n"
         "<table id=\"stability-table\" class=\"summary stability\"><thead><tr><th>case</th><th>method</th><th>result</th>"
         "<th>wrong px</th><th>coverage</th><th>colour max |\xCE\x94|</th><th>cracks</th><th>double hits</th>"
         "<th>median ms</th><th>error</th></tr></thead>\n<tbody>\n" + rows + "</tbody></table>\n";
}

// The known lavapipe deviations from the Vulkan spec (run/deviations.hpp): the spec's words, what
// lavapipe does, the scene that shows it and how many pixels following the spec changes there.
std::string deviationsSection(const RunResults& run) {
  std::string rows;
  for (const KnownDeviation& d : knownDeviations()) {
    const SceneResult* shown = nullptr;
    for (const SceneResult& r : run.scenes) {
      if (r.entry.name == d.scene) shown = &r;
    }
    const std::string scene = shown ? "<a href=\"" + anchorOf(*shown) + "\">" + e(d.scene) + "</a>" : e(d.scene);
    const std::string measured = shown && shown->specDeviationPixels ? std::to_string(*shown->specDeviationPixels)
                                                                     : std::string("&#8212;");
    rows += "<tr><td>" + e(d.name) + "</td><td>" + e(d.spec) + "</td><td>" + e(d.lavapipe) + "</td><td>" + scene +
            "</td><td class=\"num\">" + measured + "</td></tr>\n";
  }
  return "<h2 id=\"deviations\">Deviations from the Vulkan spec</h2>\n<p class=\"run\">Where lavapipe provably "
         "deviates from the specification softraster follows the driver (so the scenes agree) and can follow the spec "
         "instead (<code>--softraster-deviations spec</code>). The last column counts the pixels of the scene whose "
         "colour changes against lavapipe's when softraster follows the spec (&#8212;: the scene was not in this "
         "run).</p>\n<table id=\"deviations-table\" class=\"summary\"><thead><tr><th>deviation</th><th>the spec"
         "</th><th>lavapipe</th><th>scene</th><th>px changed by the spec</th></tr></thead>\n<tbody>\n" + rows +
         "</tbody></table>\n";
}

std::string sceneSection(const RunResults& run, const SceneResult& r, std::size_t position, bool open,
                         const std::filesystem::path& reportDir, const SceneVersusBaseline* versus,
                         const std::vector<std::string>& labels) {
  std::string s = "<details class=\"scene st-" + std::string(outcomeName(r.outcome)) + "\" id=\"s-" + std::to_string(position) +
                  "\"" + filterAttributes(r, versus) + " data-w=\"" + std::to_string(r.width) + "\" data-h=\"" +
                  std::to_string(r.height) + "\"";
  if (!r.pixelData.empty()) s += " data-pixels=\"" + url(r.pixelData) + "\"";
  s += open ? " open>" : ">";
  const std::string detail = resultDetail(r);
  s += "<summary>" + badge(r.outcome) + "<span class=\"name\">" + e(r.entry.name) + "</span><span class=\"path\">" +
       e(r.entry.path.string()) + "</span>" + baselineBadges(versus, r.outcome);
  if (!detail.empty() && r.actual != Outcome::Crash && r.actual != Outcome::Timeout) {
    s += "<span class=\"brief\">" + e(detail) + "</span>";
  }
  s += "</summary>\n<div class=\"scene-body\">\n";
  if (!r.description.empty()) s += "<p class=\"desc\">" + e(r.description) + "</p>\n";
  s += "<p class=\"run\">scene file <a href=\"" + url(linkFrom(reportDir, r.entry.path)) + "\">" +
       e(r.entry.path.generic_string()) + "</a> \xC2\xB7 <a href=\"" + anchorOf(r) + "\">link to this scene</a>"
       " \xC2\xB7 reproduce: <code class=\"reproduce\">" + e(reproduceCommand(run, r)) + "</code></p>\n";
  s += sceneChart(r, labels);
  if (r.expectation) {
    s += "<p class=\"expect\">expected " + std::string(outcomeName(r.expectation->outcome)) + " (expectations line " +
         std::to_string(r.expectation->line) + ")" + (r.expectation->reason.empty() ? "" : ": " + e(r.expectation->reason)) +
         "</p>\n";
  }
  if (!r.error.empty()) s += "<p class=\"error\">" + e(r.error) + "</p>\n";
  if (versus) s += "<p class=\"baseline\">against the baseline: " + e(baselineText(*versus, r.outcome)) + "</p>\n";
  s += metricsTable(r);
  if (const SceneImage* preview = imageOf(r, "preview")) {
    // Compact (artifacts.hpp): both frames bit-identical, so a preview and nothing to compare.
    s += "<template class=\"scene-views\"><figure><figcaption>softraster = Vulkan (lavapipe): colour and depth "
         "bit-identical; a preview (at most " + std::to_string(kPreviewSize) + " pixels wide or tall) of the " +
         std::to_string(r.width) + "\xC3\x97" + std::to_string(r.height) + " frame</figcaption><img class=\"preview\" "
         "loading=\"lazy\" src=\"" + url(preview->file) + "\" alt=\"" + e("preview of " + r.entry.name) + "\"></figure>"
         "<p class=\"run\">Nothing differs, so no other views or pixel values were kept; the command above writes "
         "them all.</p></template>\n";
  } else if (!r.images.empty()) {
    // The images live in a <template> until the section is first opened: 100 scenes of closed
    // sections then cost the page no image elements, requests or layout.
    s += "<noscript><p class=\"run\">Images: the files in " + e(r.entry.name) +
         "/ next to this page (showing them here needs JavaScript).</p></noscript>\n<template class=\"scene-views\">\n";
    s += "<div class=\"tools\"><label>zoom <select class=\"zoom\">";
    const std::uint32_t zoom = defaultZoom(r);
    for (const std::uint32_t z : {0u, 1u, 2u, 4u, 8u, 16u, 32u}) {
      const std::string value = z == 0 ? "fit" : std::to_string(z);
      s += "<option value=\"" + value + "\"" + (z == zoom ? " selected" : "") + ">" +
           (z == 0 ? value : value + "\xC3\x97") + "</option>";
    }
    s += "</select></label><span class=\"readout\">point at an image to read the values of both renders</span></div>\n";
    s += "<div class=\"views\">\n" + figure(r, "soft", "softraster") + figure(r, "vulkan", "Vulkan (lavapipe)") +
         figure(r, "diff", "difference (heatmap)") + "</div>\n" + colourLegend(std::to_string(r.tolerance.colourThreshold));
    s += "<div class=\"views\">\n" +
         figure(r, "soft.depth", "softraster depth") + figure(r, "vulkan.depth", "Vulkan depth") +
         figure(r, "depth.diff", "depth difference (heatmap)") + "</div>\n" + depthLegend(r.tolerance.depthThreshold);
    if (imageOf(r, "soft.stencil")) {
      s += "<div class=\"views\">\n" + figure(r, "soft.stencil", "softraster stencil (grey = value)") +
           figure(r, "vulkan.stencil", "Vulkan stencil") +
           figure(r, "stencil.diff", "stencil difference (magenta: differs; compared exactly)") + "</div>\n";
    }
    for (int n = 1; imageOf(r, "soft.attachment" + std::to_string(n)); ++n) {  // colour attachments 1..
      const std::string a = "attachment" + std::to_string(n);
      s += "<div class=\"views\">\n" + figure(r, "soft." + a, "softraster colour attachment " + std::to_string(n)) +
           figure(r, "vulkan." + a, "Vulkan colour attachment " + std::to_string(n)) +
           figure(r, a + ".diff", "colour attachment " + std::to_string(n) + " difference (heatmap)") + "</div>\n";
    }
    if (imageOf(r, "soft.sample0")) s += sampleViews(r);
    s += "<p class=\"run\">Depth views map " + e(fixed("%.9g", r.depthViewRange.first)) + " to black and " +
         e(fixed("%.9g", r.depthViewRange.second)) + " to white, the same for both (the range they drew); depths outside it, such as the "
         "clear depth, saturate.</p>\n";
    const SceneImage* soft = imageOf(r, "soft");
    const SceneImage* vulkan = imageOf(r, "vulkan");
    if (soft && vulkan) {
      s += "<div class=\"views\">" +
           figure(r, "soft", "flicker: <b class=\"flicker-label\">softraster</b> <button type=\"button\" class=\"swap\">swap</button> "
                             "<button type=\"button\" class=\"flick\">flicker</button>",
                  " class=\"flicker\" data-showing=\"a\" data-a=\"" + url(soft->file) + "\" data-b=\"" + url(vulkan->file) + "\"") +
           "</div>\n";
      // Onion skin (Vulkan over softraster, its opacity on the slider) and wipe (Vulkan right of the slider).
      const std::uint32_t zoom = defaultZoom(r);
      const std::string size = "width=\"" + std::to_string(r.width) + "\" height=\"" + std::to_string(r.height) + "\"" +
                               (zoom ? " style=\"width:" + std::to_string(zoom * r.width) + "px\"" : std::string());
      s += "<div class=\"views\"><figure><figcaption>compare: <select class=\"blend-mode\"><option value=\"onion\">onion skin"
           "</option><option value=\"wipe\">wipe</option></select> softraster <input type=\"range\" class=\"blend-amount\" "
           "min=\"0\" max=\"100\" value=\"50\" aria-label=\"how much of Vulkan shows\"> Vulkan</figcaption><div class=\"view"
           + std::string(zoom ? " zoomed" : "") + "\"><div class=\"stack\"><img loading=\"lazy\" src=\"" + url(soft->file) + "\" " +
           size + " alt=\"softraster\"><img class=\"stack-top\" loading=\"lazy\" src=\"" + url(vulkan->file) + "\" " + size +
           " alt=\"Vulkan over softraster\" style=\"opacity:0.5\"></div><div class=\"marker\"></div></div></figure></div>\n";
    }
    s += "</template>\n";
  }
  return s + "</div></details>\n";
}

}  // namespace

std::string renderArgumentsOf(const std::string& commandLine) {
  std::string arguments;
  const auto add = [&](const std::string& text) { arguments += (arguments.empty() ? "" : " ") + text; };
  std::istringstream words(commandLine);
  std::vector<std::string> tokens{std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& t = tokens[i];
    if (t == "--validation") add(t);
    const bool takesValue = t == "--softraster-fma" || t == "--softraster-deviations" || t == "--device" || t == "--set";
    if (takesValue && i + 1 < tokens.size()) {
      add(t + " " + tokens[i + 1]);
      ++i;
    }
    for (const char* option : {"--softraster-fma=", "--softraster-deviations=", "--device=", "--set="}) {
      if (t.rfind(option, 0) == 0) add(t);
    }
  }
  return arguments;
}

std::string pixelDataScript(const std::string& sceneName, const Frame& soft, const Frame& vulkan) {
  using nlohmann::json;
  const json data = {{"w", soft.width},
                     {"h", soft.height},
                     {"soft", base64(compressed(soft.rgba))},
                     {"vulkan", base64(compressed(vulkan.rgba))},
                     {"softDepth", base64(compressed(littleEndian(soft.depth)))},
                     {"vulkanDepth", base64(compressed(littleEndian(vulkan.depth)))}};
  const auto dump = [](const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); };
  return "crosscheckPixels(" + dump(json(sceneName)) + "," + dump(data) + ");\n";
}

softraster::Status writePixelData(const std::filesystem::path& root, const std::filesystem::path& relative,
                                  SceneResult* result, const Frame& soft, const Frame& vulkan) {
  softraster::Status status = writeDocument(root / relative, pixelDataScript(result->entry.name, soft, vulkan), "pixel data");
  if (status) result->pixelData = relative;
  return status;
}

std::vector<std::size_t> worstFirst(const std::vector<SceneResult>& results) {
  std::vector<std::size_t> order(results.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto key = [&](std::size_t i) {
    const SceneResult& r = results[i];
    const Comparison none;
    const Comparison& c = r.comparison ? *r.comparison : none;
    const double psnr = r.comparison ? c.psnr : std::numeric_limits<double>::infinity();
    return std::make_tuple(outcomeRank(r.outcome), ~c.coverageMismatches, ~c.colourPixelsOver, ~c.depthPixelsOver, psnr,
                           std::string_view(r.entry.name));
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  return order;
}

std::string reportHtml(const RunResults& run, const std::filesystem::path& reportDir, const ReportBaseline* baseline) {
  const std::vector<SceneResult>& results = run.scenes;
  const auto versusOf = [&](std::size_t i) -> const SceneVersusBaseline* {
    return baseline && i < baseline->versus.scenes.size() ? &baseline->versus.scenes[i] : nullptr;
  };
  const Counts counts = countResults(results);
  const std::vector<std::size_t> order = worstFirst(results);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>crosscheck report: " + e(countsLine(counts)) + "</title>\n"
      "<script>window.addEventListener('error',function(ev){var r=document.documentElement;"
      "r.setAttribute('data-js-errors',(r.getAttribute('data-js-errors')||'')+ev.message+' | ');});"
      "window.addEventListener('unhandledrejection',function(ev){var r=document.documentElement;"
      "r.setAttribute('data-js-errors',(r.getAttribute('data-js-errors')||'')+String(ev.reason)+' | ');});</script>\n"
      "<style>\n" + std::string(report_assets::kCss) + "</style>\n</head>\n";
  html += "<body data-scenes=\"" + std::to_string(results.size()) + "\">\n";
  html += "<h1>softraster \xC3\x97 Vulkan (lavapipe): conformance report</h1>\n";
  html += "<p class=\"counts\">" + e(countsLine(counts)) + "</p>\n";
  html += "<p class=\"run\">" + std::to_string(results.size()) + " scenes";
  for (Outcome s : kAllOutcomes) {
    if (counts.of(s)) html += " \xC2\xB7 " + std::to_string(counts.of(s)) + " " + std::string(outcomeName(s));
  }
  html += " \xC2\xB7 " + e(fixed("%.2f s", run.seconds)) + " with " + std::to_string(run.jobs) + (run.jobs == 1 ? " job" : " jobs");
  if (run.finished != 0) html += " \xC2\xB7 " + e(utcTime(run.finished, "%Y-%m-%d %H:%M:%S UTC"));
  if (!run.commandLine.empty()) html += "<br><code>" + e(run.commandLine) + "</code>";
  if (!run.junitFile.empty()) {
    html += "<br>JUnit: <a href=\"" + url(linkFrom(reportDir, run.junitFile)) + "\">" + e(run.junitFile.generic_string()) + "</a>";
  }
  html += "</p>\n";
  if (baseline) {
    const BaselineComparison& v = baseline->versus;
    const auto counted = [](std::size_t n, const char* one, const char* many) {
      return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    html += "<p class=\"baseline-summary\" id=\"baseline-summary\">Against the baseline <a href=\"" +
            url(linkFrom(reportDir, baseline->file)) + "\">" + e(baseline->file.generic_string()) + "</a>";
    if (baseline->finished != 0) html += " (" + e(utcTime(baseline->finished, "%Y-%m-%d %H:%M:%S UTC")) + ")";
    html += ": <b>" + counted(v.newFailures, "new failure", "new failures") + "</b> \xC2\xB7 " +
            counted(v.fixed, "fixed", "fixed") + " \xC2\xB7 " +
            counted(v.changed, "scene with changed metrics", "scenes with changed metrics");
    if (v.added) html += " \xC2\xB7 " + counted(v.added, "new scene", "new scenes");
    if (!v.gone.empty()) {
      std::string names;
      for (const std::string& name : v.gone) names += (names.empty() ? "" : ", ") + name;
      html += " \xC2\xB7 " + counted(v.gone.size(), "scene", "scenes") + " of the baseline not run: " + e(names);
    }
    html += "</p>\n";
  }

  // Everything unexpected, at the top, with its renders and what went wrong.
  std::string attention;
  std::size_t unexpected = 0;
  for (const std::size_t i : order) {
    const SceneResult& r = results[i];
    if (!isUnexpected(r.outcome)) continue;
    ++unexpected;
    const std::string detail = resultDetail(r);
    attention += "<li" + filterAttributes(r, versusOf(i)) + ">" + badge(r.outcome) + " <a href=\"" + anchorOf(r) + "\">" +
                 e(r.entry.name) + "</a>" + baselineBadges(versusOf(i), r.outcome) + " <span class=\"thumbs\">" +
                 thumbnail(r, "soft", "softraster") + thumbnail(r, "vulkan", "Vulkan") + thumbnail(r, "diff", "difference") +
                 "</span><div class=\"brief\">" + e(detail) + "</div></li>\n";
  }
  if (unexpected) {
    html += "<h2>Unexpected results (" + std::to_string(unexpected) + ")</h2>\n<ul id=\"attention\" class=\"attention\">\n" +
            attention + "</ul>\n";
    html += "<details class=\"expectations\"><summary>Expectations lines for these results</summary><p class=\"run\">"
            "To accept them as known, add these lines to the expectations file (format: SCENE,STATUS # reason)."
            " <button type=\"button\" id=\"copy-expectations\">copy</button> <span id=\"copy-status\"></span></p>"
            "<textarea id=\"expectations-lines\" readonly rows=\"" + std::to_string(std::min<std::size_t>(unexpected, 12) + 1) +
            "\" spellcheck=\"false\">" + e(expectationsLines(run)) + "</textarea></details>\n";
  }

  html += "<h2>Summary</h2>\n<div class=\"filters\" id=\"filters\"><label>find <input type=\"search\" id=\"filter-name\" "
          "placeholder=\"scene name\"></label><label><input type=\"checkbox\" id=\"filter-unexpected\"> only unexpected</label>";
  if (baseline) {
    html += "<label><input type=\"checkbox\" id=\"filter-baseline\"> only changed against the baseline</label>";
  }
  html += "<span class=\"status-filters\">";
  for (Outcome s : kAllOutcomes) {
    if (!counts.of(s)) continue;
    html += "<label><input type=\"checkbox\" class=\"filter-status\" value=\"" + std::string(outcomeName(s)) + "\" checked> " +
            std::string(outcomeName(s)) + " (" + std::to_string(counts.of(s)) + ")</label>";
  }
  html += "</span><span id=\"filter-count\" class=\"run\"></span></div>\n";
  html += "<table id=\"summary\" class=\"summary\">\n<thead><tr>"
          "<th data-type=\"number\" data-first=\"ascending\" aria-sort=\"ascending\" title=\"worst first\">status</th>"
          "<th data-type=\"none\">render</th>"
          "<th data-type=\"text\" data-first=\"ascending\">scene</th>"
          "<th data-type=\"number\" title=\"pixels covered by one renderer only\">coverage mismatches</th>"
          "<th data-type=\"number\" title=\"pixels with a channel over the colour threshold\">colour pixels over</th>"
          "<th data-type=\"number\" title=\"largest over R, G, B, A (in the format's steps: 8-bit; 10-bit for A2B10G10R10)\">colour max |\xCE\x94|</th>"
          "<th data-type=\"number\" title=\"largest channel mean (in the format's steps)\">colour mean |\xCE\x94|</th>"
          "<th data-type=\"number\" data-first=\"ascending\" title=\"RGB, dB; lowest first\">PSNR</th>"
          "<th data-type=\"number\" title=\"pixels with depth over the depth threshold\">depth pixels over</th>"
          "<th data-type=\"number\">depth max |\xCE\x94|</th>"
          "<th data-type=\"number\" title=\"pixels whose stored stencil differs (exact)\">stencil mismatches</th>"
          "<th data-type=\"number\">softraster ms</th>"
          "<th data-type=\"number\">Vulkan ms</th>"
          "</tr></thead>\n<tbody>\n";
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    html += summaryRow(results[order[rank]], rank, versusOf(order[rank]));
  }
  html += "</tbody>\n</table>\n";
  const ChartSet chart = chartFromResults(run);
  const std::vector<std::string> labels = chartLabels(chart);
  if (!chart.scenes.empty()) html += chartSection(chart, labels);
  html += stabilitySection(run);
  html += deviationsSection(run);
  html += "<h2>Difference heatmaps</h2>\n" + colourLegend("T") +
          "<p class=\"run\">T is the scene's colour threshold (in the format's steps: 8-bit; 10-bit for A2B10G10R10); each scene's section shows its own. "
          "Depth differences use the same colours against the depth threshold.</p>\n";

  html += "<h2>Scenes</h2>\n";
  std::size_t opened = 0;
  for (const std::size_t position : order) {
    const SceneResult& r = results[position];
    const bool open = isUnexpected(r.outcome) && !r.images.empty() && opened < 3;
    opened += open;
    html += sceneSection(run, r, position, open, reportDir, versusOf(position), labels);
  }
  html += "<script>\n" + std::string(report_assets::kScript) + "</script>\n</body>\n</html>\n";
  return html;
}

softraster::Status writeReport(const std::filesystem::path& dir, const RunResults& run, const ReportBaseline* baseline) {
  return writeDocument(dir / "index.html", reportHtml(run, dir, baseline), "report");
}

}  // namespace crosscheck
