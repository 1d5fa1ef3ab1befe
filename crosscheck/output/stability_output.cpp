// The stability run as a table and as JSON (see stability_output.hpp).
#include "output/stability_output.hpp"

#include "results/results_json.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>

namespace crosscheck {
namespace {

std::string count(const std::optional<std::uint64_t>& v) { return v ? std::to_string(*v) : "-"; }

std::string pad(std::string text, std::size_t width, bool right = false) {
  if (text.size() >= width) return text;
  const std::string space(width - text.size(), ' ');
  return right ? space + text : text + space;
}

}  // namespace

std::string stabilityTable(const StabilityResults& results) {
  std::size_t nameWidth = 4, labelWidth = 7;
  for (const StabilityCase& c : results.cases) {
    nameWidth = std::max(nameWidth, c.entry.name.size());
    for (const VariantRun& run : c.variants.runs) labelWidth = std::max(labelWidth, run.label.size());
  }
  std::string out = pad("case", nameWidth) + "  " + pad("variant", labelWidth) +
                    "  result  wrong px  coverage  |Δ|max  cracks  double  median ms\n";
  std::size_t passed = 0, rows = 0;
  for (const StabilityCase& c : results.cases) {
    if (!c.error.empty()) {
      out += pad(c.entry.name, nameWidth) + "  " + pad("-", labelWidth) + "  Fail    " + c.error + "\n";
      ++rows;
      continue;
    }
    for (const VariantRun& run : c.variants.runs) {
      const bool ok = variantPasses(run);
      passed += ok;
      ++rows;
      char ms[32];
      std::snprintf(ms, sizeof ms, "%.3f", run.medianMilliseconds);
      out += pad(c.entry.name, nameWidth) + "  " + pad(run.label, labelWidth) + "  " + pad(ok ? "Pass" : "Fail", 6) +
             "  " + pad(count(run.differingPixels), 8, true) + "  " + pad(count(run.coverageMismatches), 8, true) + "  " +
             pad(run.colourMaxDelta ? std::to_string(*run.colourMaxDelta) : "-", 6, true) + "  " +
             pad(run.hits ? std::to_string(run.hits->cracks) : "-", 6, true) + "  " +
             pad(run.hits ? std::to_string(run.hits->doubleHits) : "-", 6, true) + "  " + pad(ms, 9, true) + "\n";
      if (!run.ok()) out += pad("", nameWidth) + "  " + pad("", labelWidth) + "  error: " + run.error + "\n";
    }
  }
  out += "stability: " + std::to_string(results.cases.size()) + " cases, " + std::to_string(passed) + " of " +
         std::to_string(rows) + " rows pass; " + std::string(kStabilityReference) + " " +
         (results.referencePasses() ? "passes every case" : "FAILS a case") + "\n";
  return out;
}

std::string stabilityJson(const StabilityResults& results) {
  using nlohmann::json;
  json cases = json::array();
  for (const StabilityCase& c : results.cases) {
    json variants = variantResultsToJson(c.variants);
    for (json& run : variants["runs"]) run["passed"] = false;
    for (std::size_t i = 0; i < c.variants.runs.size(); ++i) {
      variants["runs"][i]["passed"] = c.error.empty() && variantPasses(c.variants.runs[i]);
    }
    cases.push_back({{"name", c.entry.name},
                     {"scene", c.entry.path.generic_string()},
                     {"description", c.description},
                     {"error", c.error},
                     {"variants", variants}});
  }
  const json document = {{"frames", results.frames},
                         {"reference", std::string(kStabilityReference)},
                         {"reference_passes", results.referencePasses()},
                         {"cases", cases}};
  return document.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace crosscheck
