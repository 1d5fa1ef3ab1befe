// The speed-vs-accuracy chart as SVG (see chart_svg.hpp).
#include "output/chart_svg.hpp"

#include "output/markup.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace crosscheck {
namespace {

// Panel geometry, in px.
constexpr double kPanelWidth = 380, kPanelHeight = 270;
constexpr double kLeft = 62, kRight = 14, kTop = 26, kBottom = 44;

const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                "#17becf", "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22"};
constexpr int kShapes = 6;  // circle, square, triangle, diamond, down triangle, cross

std::string num(double v, int precision = 4) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
  return buffer;
}

std::string fixed(double v, int decimals = 1) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

// A tick's text: 0.1, 1, 20, 500, 1000, 1e+05 -> 100000 spelled in full below a million.
std::string tickText(double v) {
  if (v >= 1e6) return num(v, 2);
  if (v >= 1) return num(v, 7);
  return num(v, 3);
}

std::size_t styleOf(const std::string& label, const std::vector<std::string>& labels) {
  const auto it = std::find(labels.begin(), labels.end(), label);
  return static_cast<std::size_t>(it - labels.begin());
}

// A marker of `style` centred at (x, y), with a tooltip.
std::string marker(std::size_t style, double x, double y, const std::string& tooltip, const std::string& data) {
  const std::string colour = kColours[style % std::size(kColours)];
  const int shape = static_cast<int>(style % kShapes);
  const double r = 5;
  std::string body;
  const std::string paint = " fill=\"" + colour + "\" fill-opacity=\"0.85\" stroke=\"#000\" stroke-width=\"0.7\"";
  auto polygon = [&](std::initializer_list<std::pair<double, double>> points) {
    std::string p;
    for (const auto& [dx, dy] : points) p += (p.empty() ? "" : " ") + fixed(x + dx) + "," + fixed(y + dy);
    return "<polygon points=\"" + p + "\"" + paint + "/>";
  };
  switch (shape) {
    case 0: body = "<circle cx=\"" + fixed(x) + "\" cy=\"" + fixed(y) + "\" r=\"" + fixed(r) + "\"" + paint + "/>"; break;
    case 1: body = polygon({{-r, -r}, {r, -r}, {r, r}, {-r, r}}); break;
    case 2: body = polygon({{0, -r * 1.2}, {r * 1.1, r * 0.8}, {-r * 1.1, r * 0.8}}); break;
    case 3: body = polygon({{0, -r * 1.3}, {r * 1.1, 0}, {0, r * 1.3}, {-r * 1.1, 0}}); break;
    case 4: body = polygon({{0, r * 1.2}, {r * 1.1, -r * 0.8}, {-r * 1.1, -r * 0.8}}); break;
    default:
      body = polygon({{-r, -r * 0.4}, {-r * 0.4, -r * 0.4}, {-r * 0.4, -r}, {r * 0.4, -r}, {r * 0.4, -r * 0.4},
                      {r, -r * 0.4}, {r, r * 0.4}, {r * 0.4, r * 0.4}, {r * 0.4, r}, {-r * 0.4, r},
                      {-r * 0.4, r * 0.4}, {-r, r * 0.4}});
  }
  return "<g class=\"marker\"" + data + "><title>" + escapeMarkup(tooltip) + "</title>" + body + "</g>\n";
}

// A log axis from lo to hi over [a, b] px (a < b for x; y is flipped by the caller).
struct LogAxis {
  double lo = 1, hi = 10;
  double at(double v, double a, double b) const {
    return a + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (b - a);
  }
};

// The error axis: log10(1 + v) from 0 to log10(1 + top).
struct CountAxis {
  double top = 10;
  double at(double v, double a, double b) const { return a + std::log10(1 + v) / std::log10(1 + top) * (b - a); }
};

// The range of a log axis around the values, a little wider than them, in whole or half decades.
LogAxis logAxisFor(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !(v > 0) || !std::isfinite(v); }),
               values.end());
  if (values.empty()) return {0.1, 10};
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  double lo = std::pow(10, std::floor(std::log10(*mn))), hi = std::pow(10, std::ceil(std::log10(*mx)));
  if (hi <= lo) hi = lo * 10;
  return {lo, hi};
}

struct PlotArea {
  double x0, y0, x1, y1;  // the plot area
};

PlotArea plotArea(double width, double height) { return {kLeft, kTop, width - kRight, height - kBottom}; }

std::string axes(const PlotArea& f, const LogAxis& x, const std::vector<double>& yTicks, const CountAxis& y,
                 const std::string& xLabel, const std::string& yLabel, const std::string& title) {
  std::string s;
  s += "<text x=\"" + fixed((f.x0 + f.x1) / 2) + "\" y=\"16\" text-anchor=\"middle\" font-size=\"13\" font-weight=\"bold\">" +
       escapeMarkup(title) + "</text>\n";
  s += "<rect x=\"" + fixed(f.x0) + "\" y=\"" + fixed(f.y0) + "\" width=\"" + fixed(f.x1 - f.x0) + "\" height=\"" +
       fixed(f.y1 - f.y0) + "\" fill=\"#fff\" stroke=\"#444\"/>\n";
  for (double t : logTicks(x.lo, x.hi)) {
    const double px = x.at(t, f.x0, f.x1);
    s += "<line class=\"xtick\" data-value=\"" + tickText(t) + "\" x1=\"" + fixed(px) + "\" y1=\"" + fixed(f.y0) +
         "\" x2=\"" + fixed(px) + "\" y2=\"" + fixed(f.y1 + 4) + "\" stroke=\"#ddd\"/>\n";
    s += "<text x=\"" + fixed(px) + "\" y=\"" + fixed(f.y1 + 15) + "\" text-anchor=\"middle\" font-size=\"10\">" +
         tickText(t) + "</text>\n";
  }
  for (double t : yTicks) {
    const double py = y.at(t, f.y1, f.y0);
    s += "<line class=\"ytick\" data-value=\"" + tickText(t) + "\" x1=\"" + fixed(f.x0 - 4) + "\" y1=\"" + fixed(py) +
         "\" x2=\"" + fixed(f.x1) + "\" y2=\"" + fixed(py) + "\" stroke=\"#ddd\"/>\n";
    s += "<text x=\"" + fixed(f.x0 - 6) + "\" y=\"" + fixed(py + 3.5) + "\" text-anchor=\"end\" font-size=\"10\">" +
         tickText(t) + "</text>\n";
  }
  s += "<text x=\"" + fixed((f.x0 + f.x1) / 2) + "\" y=\"" + fixed(f.y1 + 32) +
       "\" text-anchor=\"middle\" font-size=\"11\">" + escapeMarkup(xLabel) + "</text>\n";
  s += "<text transform=\"translate(14," + fixed((f.y0 + f.y1) / 2) +
       ") rotate(-90)\" text-anchor=\"middle\" font-size=\"11\">" + escapeMarkup(yLabel) + "</text>\n";
  return s;
}

std::string pointTooltip(const std::string& prefix, const ChartPoint& p, double lavapipe) {
  std::string t = prefix + p.label + ": " + num(p.milliseconds) + " ms";
  if (lavapipe > 0) t += " (" + num(lavapipe / p.milliseconds, 3) + "x as fast as lavapipe)";
  t += ", " + tickText(*p.coverageMismatches) + " coverage mismatches, colour max |Δ| " + tickText(*p.colourMaxDelta);
  return t;
}

// The polyline through the front's points, as a staircase (each point's error holds until the
// next, faster-but-worse point's time).
std::string frontLine(const std::vector<std::pair<double, double>>& pixels, const std::vector<std::size_t>& front) {
  if (front.empty()) return "";
  std::string p;
  for (std::size_t k = 0; k < front.size(); ++k) {
    const auto [x, y] = pixels[front[k]];
    if (k > 0) p += " " + fixed(x) + "," + fixed(pixels[front[k - 1]].second);
    p += (p.empty() ? "" : " ") + fixed(x) + "," + fixed(y);
  }
  return "<polyline class=\"pareto\" data-points=\"" + std::to_string(front.size()) + "\" points=\"" + p +
         "\" fill=\"none\" stroke=\"#e6a000\" stroke-width=\"2\" stroke-dasharray=\"none\" opacity=\"0.8\">"
         "<title>Pareto front: no other point is both faster and closer to Vulkan</title></polyline>\n";
}

std::string svgOpen(double width, double height, const std::string& cls) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"" + cls + "\" width=\"" + fixed(width, 0) +
         "\" height=\"" + fixed(height, 0) + "\" viewBox=\"0 0 " + fixed(width, 0) + " " + fixed(height, 0) +
         "\" font-family=\"DejaVu Sans, Arial, sans-serif\">\n";
}

}  // namespace

std::vector<std::size_t> paretoFront(const std::vector<std::pair<double, double>>& points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      const auto [xi, yi] = points[i];
      const auto [xj, yj] = points[j];
      dominated = xj <= xi && yj <= yi && (xj < xi || yj < yi);
    }
    if (!dominated) front.push_back(i);
  }
  std::stable_sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) { return points[a] < points[b]; });
  return front;
}

std::vector<double> logTicks(double lo, double hi) {
  std::vector<double> ticks;
  if (!(lo > 0) || !(hi >= lo)) return ticks;
  const int first = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
  const int last = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
  const bool fine = last - first < 2;
  for (int e = first; e <= last; ++e) {
    const double decade = std::pow(10.0, e);
    for (double m : {1.0, 2.0, 5.0}) {
      if (m != 1.0 && !fine) continue;
      const double t = m * decade;
      if (t >= lo * (1 - 1e-9) && t <= hi * (1 + 1e-9)) ticks.push_back(t);
    }
  }
  return ticks;
}

std::vector<double> countTicks(double hi) {
  std::vector<double> ticks{0};
  for (double t = 1; ; t *= 10) {
    ticks.push_back(t);
    if (t >= hi) break;
  }
  return ticks;
}

std::vector<std::string> chartLabels(const ChartSet& set) {
  std::vector<std::string> labels;
  for (const ChartScene& scene : set.scenes) {
    for (const ChartPoint& p : scene.points) {
      if (std::find(labels.begin(), labels.end(), p.label) == labels.end()) labels.push_back(p.label);
    }
  }
  return labels;
}

std::string scenePanelSvg(const ChartScene& scene, ChartMetric metric, const std::vector<std::string>& labels) {
  const bool coverage = metric == ChartMetric::CoverageMismatches;
  std::vector<const ChartPoint*> drawn;
  std::vector<double> xs;
  double top = 1;
  for (const ChartPoint& p : scene.points) {
    if (!p.drawable()) continue;
    drawn.push_back(&p);
    xs.push_back(p.milliseconds);
    top = std::max(top, coverage ? *p.coverageMismatches : *p.colourMaxDelta);
  }
  if (scene.lavapipeMilliseconds > 0) xs.push_back(scene.lavapipeMilliseconds);
  const LogAxis x = logAxisFor(xs);
  const std::vector<double> yTicks = countTicks(top);
  const CountAxis y{yTicks.back()};
  const double height = kPanelHeight + 14 * static_cast<double>(scene.points.size() - drawn.size());
  const PlotArea f = plotArea(kPanelWidth, kPanelHeight);
  std::string s = svgOpen(kPanelWidth, height, coverage ? "chart-panel chart-coverage" : "chart-panel chart-colour");
  s += axes(f, x, yTicks, y, "frame time (median, ms, log scale)",
            coverage ? "coverage mismatches (pixels, log(1+n))" : "colour max |Δ| (8-bit steps, log(1+n))",
            scene.name + (coverage ? ": coverage" : ": colour"));
  if (scene.lavapipeMilliseconds > 0) {
    const double px = x.at(scene.lavapipeMilliseconds, f.x0, f.x1);
    s += "<g class=\"lavapipe\"><title>lavapipe: " + num(scene.lavapipeMilliseconds) + " ms (median)</title><line x1=\"" +
         fixed(px) + "\" y1=\"" + fixed(f.y0) + "\" x2=\"" + fixed(px) + "\" y2=\"" + fixed(f.y1) +
         "\" stroke=\"#555\" stroke-width=\"1.5\" stroke-dasharray=\"5,4\"/><text x=\"" + fixed(px + 3) + "\" y=\"" +
         fixed(f.y0 + 11) + "\" font-size=\"10\" fill=\"#555\">lavapipe</text></g>\n";
  }
  std::vector<std::pair<double, double>> values, pixels;
  for (const ChartPoint* p : drawn) {
    const double v = coverage ? *p->coverageMismatches : *p->colourMaxDelta;
    values.push_back({p->milliseconds, v});
    pixels.push_back({x.at(p->milliseconds, f.x0, f.x1), y.at(v, f.y1, f.y0)});
  }
  const std::vector<std::size_t> front = paretoFront(values);
  s += frontLine(pixels, front);
  for (std::size_t i : front) {  // a ring behind each point of the front, visible even on an axis
    s += "<circle class=\"front-ring\" cx=\"" + fixed(pixels[i].first) + "\" cy=\"" + fixed(pixels[i].second) +
         "\" r=\"9\" fill=\"none\" stroke=\"#e6a000\" stroke-width=\"2.5\"/>\n";
  }
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    s += marker(styleOf(drawn[i]->label, labels), pixels[i].first, pixels[i].second,
                pointTooltip("", *drawn[i], scene.lavapipeMilliseconds) + (onFront ? " (on the Pareto front)" : ""),
                " data-label=\"" + escapeMarkup(drawn[i]->label) + "\" data-pareto=\"" + (onFront ? "1" : "0") + "\"");
  }
  double noteY = kPanelHeight - 2;
  for (const ChartPoint& p : scene.points) {
    if (p.drawable()) continue;
    s += "<text class=\"not-drawn\" x=\"" + fixed(f.x0) + "\" y=\"" + fixed(noteY) + "\" font-size=\"10\" fill=\"#a00\">" +
         escapeMarkup("not drawn: " + p.label + (p.error.empty() ? " (not compared)" : ": " + p.error)) + "</text>\n";
    noteY += 14;
  }
  return s + "</svg>\n";
}

std::string overviewPanelSvg(const ChartSet& set, const std::vector<std::string>& labels) {
  struct Dot {
    const ChartPoint* point;
    std::string scene;
    double ratio;
  };
  std::vector<Dot> dots;
  std::vector<double> xs{1};
  double top = 1;
  for (const ChartScene& scene : set.scenes) {
    if (!(scene.lavapipeMilliseconds > 0)) continue;
    for (const ChartPoint& p : scene.points) {
      if (!p.drawable()) continue;
      dots.push_back({&p, scene.name, scene.lavapipeMilliseconds / p.milliseconds});
      xs.push_back(dots.back().ratio);
      top = std::max(top, *p.coverageMismatches);
    }
  }
  const double width = kPanelWidth * 2, height = kPanelHeight + 40;
  const LogAxis x = logAxisFor(xs);
  const std::vector<double> yTicks = countTicks(top);
  const CountAxis y{yTicks.back()};
  const PlotArea f = plotArea(width, height);
  std::string s = svgOpen(width, height, "chart-panel chart-overview");
  s += axes(f, x, yTicks, y, "speed relative to lavapipe (lavapipe median / median, log scale; > 1: faster)",
            "coverage mismatches (pixels, log(1+n))", "All scenes: speed against accuracy");
  const double one = x.at(1, f.x0, f.x1);
  s += "<g class=\"lavapipe\"><title>lavapipe's speed (1x)</title><line x1=\"" + fixed(one) + "\" y1=\"" + fixed(f.y0) +
       "\" x2=\"" + fixed(one) + "\" y2=\"" + fixed(f.y1) +
       "\" stroke=\"#555\" stroke-width=\"1.5\" stroke-dasharray=\"5,4\"/></g>\n";
  for (const Dot& d : dots) {
    s += marker(styleOf(d.point->label, labels), x.at(d.ratio, f.x0, f.x1), y.at(*d.point->coverageMismatches, f.y1, f.y0),
                pointTooltip(d.scene + ", ", *d.point, d.ratio > 0 ? d.ratio * d.point->milliseconds : 0),
                " data-label=\"" + escapeMarkup(d.point->label) + "\" data-scene=\"" + escapeMarkup(d.scene) + "\"");
  }
  return s + "</svg>\n";
}

std::string legendSvg(const std::vector<std::string>& labels) {
  const double height = 18.0 * static_cast<double>(labels.size()) + 12 + 2 * 18;
  std::string s = svgOpen(200, height, "chart-legend");
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const double y = 14 + 18.0 * static_cast<double>(i);
    std::string m = marker(i, 12, y, labels[i], " data-label=\"" + escapeMarkup(labels[i]) + "\"");
    m.replace(m.find("class=\"marker\""), 14, "class=\"legend-marker\"");
    s += m;
    s += "<text x=\"26\" y=\"" + fixed(y + 4) + "\" font-size=\"12\">" + escapeMarkup(labels[i]) + "</text>\n";
  }
  const double y = 14 + 18.0 * static_cast<double>(labels.size());
  s += "<line x1=\"4\" y1=\"" + fixed(y) + "\" x2=\"20\" y2=\"" + fixed(y) +
       "\" stroke=\"#e6a000\" stroke-width=\"2\"/><circle cx=\"12\" cy=\"" + fixed(y) +
       "\" r=\"6\" fill=\"none\" stroke=\"#e6a000\" stroke-width=\"2\"/><text x=\"26\" y=\"" + fixed(y + 4) +
       "\" font-size=\"12\">Pareto front</text>\n";
  s += "<line x1=\"12\" y1=\"" + fixed(y + 10) + "\" x2=\"12\" y2=\"" + fixed(y + 26) +
       "\" stroke=\"#555\" stroke-width=\"1.5\" stroke-dasharray=\"4,3\"/><text x=\"26\" y=\"" + fixed(y + 22) +
       "\" font-size=\"12\">lavapipe (median)</text>\n";
  s += "</svg>\n";
  return s;
}

std::string chartDocument(const ChartSet& set) {
  const std::vector<std::string> labels = chartLabels(set);
  const std::string legend = legendSvg(labels), overview = overviewPanelSvg(set, labels);
  std::vector<std::pair<std::string, std::string>> rows;
  for (const ChartScene& scene : set.scenes) {
    rows.push_back({scenePanelSvg(scene, ChartMetric::CoverageMismatches, labels),
                    scenePanelSvg(scene, ChartMetric::ColourMaxDelta, labels)});
  }
  // Nested <svg> elements placed by x and y: the panels' heights are read back from their tags.
  auto heightOf = [](const std::string& svg) {
    const auto at = svg.find("height=\"");
    return std::stod(svg.substr(at + 8));
  };
  auto place = [](std::string svg, double x, double y) {
    const auto at = svg.find("<svg ") + 5;
    return svg.insert(at, "x=\"" + fixed(x, 0) + "\" y=\"" + fixed(y, 0) + "\" ");
  };
  const double width = 2 * kPanelWidth + 220;
  double y = 40;
  std::string body;
  body += place(overview, 0, y);
  body += place(legend, 2 * kPanelWidth + 10, y + kTop);
  y += heightOf(overview) + 10;
  for (const auto& [left, right] : rows) {
    body += place(left, 0, y);
    body += place(right, kPanelWidth, y);
    y += std::max(heightOf(left), heightOf(right)) + 8;
  }
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += svgOpen(width, y, "speed-accuracy-chart");
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>\n";
  s += "<text x=\"12\" y=\"26\" font-size=\"16\" font-weight=\"bold\">" +
       escapeMarkup(set.title.empty() ? "Speed against accuracy" : set.title) + "</text>\n";
  return s + body + "</svg>\n";
}

softraster::Result<ChartSet> chartFromBenchJson(std::string_view text, const std::string& file) {
  using nlohmann::json;
  auto fail = [&](const std::string& what) { return softraster::Status::error(file + ": " + what); };
  json document;
  try {
    document = json::parse(text);
  } catch (const json::exception& e) {
    std::string what = e.what();
    if (const auto at = what.find("] "); at != std::string::npos) what = what.substr(at + 2);
    return fail("not JSON: " + what);
  }
  if (!document.is_object() || !document.contains("scenes") || !document["scenes"].is_array()) {
    return fail("not a bench JSON: no \"scenes\" array");
  }
  auto numberOr = [](const json& j, const char* key) -> std::optional<double> {
    if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
    return j[key].get<double>();
  };
  ChartSet set;
  set.title = "Speed against accuracy";
  if (document.contains("machine") && document["machine"].is_object() && document["machine"].contains("cpu") &&
      document["machine"]["cpu"].is_string()) {
    set.title += " (" + document["machine"]["cpu"].get<std::string>();
    if (document.contains("threads") && document["threads"].is_number()) {
      set.title += ", threads " + std::to_string(document["threads"].get<unsigned>());
    }
    set.title += ")";
  }
  std::size_t index = 0;
  for (const json& s : document["scenes"]) {
    const std::string where = "scenes/" + std::to_string(index++);
    if (!s.is_object() || !s.contains("results") || !s["results"].is_array()) return fail(where + ": no \"results\" array");
    ChartScene scene;
    scene.name = s.contains("scene") && s["scene"].is_string()
                     ? std::filesystem::path(s["scene"].get<std::string>()).stem().string()
                     : where;
    for (const json& r : s["results"]) {
      if (!r.is_object() || !r.contains("renderer") || !r["renderer"].is_string()) {
        return fail(where + ": a result without \"renderer\"");
      }
      const std::string renderer = r["renderer"].get<std::string>();
      const std::optional<double> median = numberOr(r, "median_ms");
      if (renderer == "lavapipe") {
        if (median && (!r.contains("error") || r["error"].is_null())) scene.lavapipeMilliseconds = *median;
        continue;
      }
      ChartPoint p;
      if (r.contains("label") && r["label"].is_string()) {
        p.label = r["label"].get<std::string>();
      } else if (r.contains("method") && r["method"].is_string()) {
        p.label = r["method"].get<std::string>();
      } else {
        p.label = renderer;
      }
      p.milliseconds = median.value_or(0);
      p.coverageMismatches = numberOr(r, "coverage_mismatches");
      p.colourMaxDelta = numberOr(r, "colour_max_delta");
      if (r.contains("error") && r["error"].is_string()) p.error = r["error"].get<std::string>();
      scene.points.push_back(std::move(p));
    }
    set.scenes.push_back(std::move(scene));
  }
  return set;
}

ChartSet chartFromResults(const RunResults& results) {
  ChartSet set;
  set.title = "Speed against accuracy";
  for (const SceneResult& r : results.scenes) {
    if (!r.variants) continue;
    ChartScene scene;
    scene.name = r.entry.name;
    scene.lavapipeMilliseconds = r.variants->lavapipeMilliseconds;
    for (const VariantRun& v : r.variants->runs) {
      ChartPoint p;
      p.label = v.label;
      p.milliseconds = v.medianMilliseconds;
      if (v.coverageMismatches) p.coverageMismatches = static_cast<double>(*v.coverageMismatches);
      if (v.colourMaxDelta) p.colourMaxDelta = *v.colourMaxDelta;
      p.error = v.error;
      scene.points.push_back(std::move(p));
    }
    set.scenes.push_back(std::move(scene));
  }
  return set;
}

}  // namespace crosscheck
