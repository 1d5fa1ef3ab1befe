// A run against its baseline (see baseline.hpp).
#include "results/baseline.hpp"

#include <algorithm>
#include <map>

namespace crosscheck {
namespace {

// The values of the report's summary table columns, in its order.
std::vector<std::pair<const char*, double>> tableMetrics(const Comparison& c) {
  return {{"coverage mismatches", double(c.coverageMismatches)},
          {"colour pixels over", double(c.colourPixelsOver)},
          {"colour max |\xCE\x94|", double(*std::max_element(c.colourMaxDelta.begin(), c.colourMaxDelta.end()))},
          {"colour mean |\xCE\x94|", *std::max_element(c.colourMeanDelta.begin(), c.colourMeanDelta.end())},
          {"PSNR", c.psnr},
          {"depth pixels over", double(c.depthPixelsOver)},
          {"depth max |\xCE\x94|", c.depthMaxDelta},
          {"stencil mismatches", double(c.stencilMismatches)}};
}

bool same(double a, double b) { return a == b || (a != a && b != b); }  // NaN equals NaN here

}  // namespace

BaselineComparison compareWithBaseline(const RunResults& run, const RunResults& baseline) {
  std::map<std::string, const SceneResult*> before;
  for (const SceneResult& r : baseline.scenes) before.emplace(r.entry.name, &r);
  BaselineComparison out;
  std::map<std::string, bool> present;
  for (const SceneResult& r : run.scenes) {
    present[r.entry.name] = true;
    SceneVersusBaseline v;
    const auto it = before.find(r.entry.name);
    const SceneResult* b = it == before.end() ? nullptr : it->second;
    v.inBaseline = b != nullptr;
    if (b) v.before = b->outcome;
    v.newFailure = isUnexpected(r.outcome) && (!b || !isUnexpected(b->outcome));
    v.fixed = b && isUnexpected(b->outcome) && (r.outcome == Outcome::Pass || r.outcome == Outcome::ExpectedFail);
    if (b && b->comparison && r.comparison) {
      const auto was = tableMetrics(*b->comparison), now = tableMetrics(*r.comparison);
      for (std::size_t i = 0; i < now.size(); ++i) {
        if (!same(was[i].second, now[i].second)) v.changes.push_back({now[i].first, was[i].second, now[i].second});
      }
    }
    out.newFailures += v.newFailure;
    out.fixed += v.fixed;
    out.changed += !v.changes.empty();
    out.added += !v.inBaseline;
    out.scenes.push_back(std::move(v));
  }
  for (const SceneResult& r : baseline.scenes) {
    if (!present.count(r.entry.name)) out.gone.push_back(r.entry.name);
  }
  return out;
}

}  // namespace crosscheck
