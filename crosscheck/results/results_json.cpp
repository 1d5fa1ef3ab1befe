// RunResults and SceneResult as JSON and back (see results_json.hpp).
#include "results/results_json.hpp"

#include "run/deviations.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace crosscheck {
namespace {

using nlohmann::json;

// ---- writing ----

json number(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return value;
}

json toleranceJson(const Tolerance& t) {
  return {{"colour_threshold", t.colourThreshold},
          {"depth_threshold", number(t.depthThreshold)},
          {"max_coverage_mismatches", t.maxCoverageMismatches},
          {"max_colour_pixels_over", t.maxColourPixelsOver},
          {"max_depth_pixels_over", t.maxDepthPixelsOver}};
}

json comparisonJson(const Comparison& c) {
  json mean = json::array();
  for (double v : c.colourMeanDelta) mean.push_back(number(v));
  json out = {{"pixels", c.pixels},
          {"samples_compared", c.samples},
          {"coverage_mismatches", c.coverageMismatches},
          {"colour_max_delta", c.colourMaxDelta},
          {"colour_unit", c.colourUnit},
          {"resolved_colour_max_delta", c.resolvedColourMaxDelta},
          {"colour_mean_delta", mean},
          {"colour_pixels_over", c.colourPixelsOver},
          {"psnr", number(c.psnr)},
          {"depth_max_delta", number(c.depthMaxDelta)},
          {"depth_pixels_over", c.depthPixelsOver},
          {"stencil_mismatches", c.stencilMismatches},
          {"failures", c.failures}};
  if (!c.moreColour.empty()) {  // colour attachments 1.. (absent with one)
    json more = json::array();
    for (const AttachmentComparison& m : c.moreColour) {
      more.push_back({{"colour_max_delta", m.colourMaxDelta},
                      {"colour_unit", m.colourUnit},
                      {"colour_pixels_over", m.colourPixelsOver}});
    }
    out["more_colour_attachments"] = more;
  }
  return out;
}

json optionalNumber(const std::optional<std::uint64_t>& v) { return v ? json(*v) : json(nullptr); }

// ---- reading: each accessor names the field it failed on ----

struct BadField : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void bad(const std::string& place, const std::string& what) {
  throw BadField((place.empty() ? "/" : place) + ": " + what);
}

const json& field(const json& object, const std::string& place, const char* key) {
  if (!object.is_object()) bad(place, "expected an object");
  const auto it = object.find(key);
  if (it == object.end()) bad(place + "/" + key, "missing");
  return *it;
}

std::string readString(const json& value, const std::string& place) {
  if (!value.is_string()) bad(place, "expected a string");
  return value.get<std::string>();
}

bool readBool(const json& value, const std::string& place) {
  if (!value.is_boolean()) bad(place, "expected true or false");
  return value.get<bool>();
}

double readNumber(const json& value, const std::string& place) {
  if (value.is_number()) return value.get<double>();
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    if (text == "inf") return std::numeric_limits<double>::infinity();
    if (text == "-inf") return -std::numeric_limits<double>::infinity();
    if (text == "nan") return std::numeric_limits<double>::quiet_NaN();
  }
  bad(place, "expected a number (or \"inf\", \"-inf\", \"nan\")");
}

template <class Integer>
Integer readInteger(const json& value, const std::string& place) {
  if (value.is_number_unsigned()) {
    const auto v = value.get<std::uint64_t>();
    if (std::in_range<Integer>(v)) return static_cast<Integer>(v);
  } else if (value.is_number_integer()) {
    const auto v = value.get<std::int64_t>();
    if (std::in_range<Integer>(v)) return static_cast<Integer>(v);
  }
  bad(place, "expected a whole number from " + std::to_string(std::numeric_limits<Integer>::min()) + " to " +
                 std::to_string(std::numeric_limits<Integer>::max()));
}

Outcome readOutcome(const json& value, const std::string& place) {
  const auto outcome = parseOutcome(readString(value, place));
  if (!outcome) bad(place, "'" + value.get<std::string>() + "' is not an outcome");
  return *outcome;
}

const json& readArray(const json& value, const std::string& place, std::size_t size) {
  if (!value.is_array() || value.size() != size) bad(place, "expected an array of " + std::to_string(size));
  return value;
}

Tolerance readTolerance(const json& j, const std::string& place) {
  Tolerance t;
  t.colourThreshold = readInteger<int>(field(j, place, "colour_threshold"), place + "/colour_threshold");
  t.depthThreshold = readNumber(field(j, place, "depth_threshold"), place + "/depth_threshold");
  t.maxCoverageMismatches =
      readInteger<std::uint64_t>(field(j, place, "max_coverage_mismatches"), place + "/max_coverage_mismatches");
  t.maxColourPixelsOver =
      readInteger<std::uint64_t>(field(j, place, "max_colour_pixels_over"), place + "/max_colour_pixels_over");
  t.maxDepthPixelsOver =
      readInteger<std::uint64_t>(field(j, place, "max_depth_pixels_over"), place + "/max_depth_pixels_over");
  return t;
}

Comparison readComparison(const json& j, const std::string& place) {
  Comparison c;
  c.pixels = readInteger<std::uint64_t>(field(j, place, "pixels"), place + "/pixels");
  c.coverageMismatches = readInteger<std::uint64_t>(field(j, place, "coverage_mismatches"), place + "/coverage_mismatches");
  const json& max = readArray(field(j, place, "colour_max_delta"), place + "/colour_max_delta", 4);
  const json& mean = readArray(field(j, place, "colour_mean_delta"), place + "/colour_mean_delta", 4);
  for (std::size_t i = 0; i < 4; ++i) {
    c.colourMaxDelta[i] = readInteger<int>(max[i], place + "/colour_max_delta/" + std::to_string(i));
    c.colourMeanDelta[i] = readNumber(mean[i], place + "/colour_mean_delta/" + std::to_string(i));
  }
  // Absent from files written before every sample was compared: one sample (the resolve) then.
  c.resolvedColourMaxDelta = c.colourMaxDelta;
  if (j.contains("samples_compared")) {
    c.samples = readInteger<std::uint32_t>(j["samples_compared"], place + "/samples_compared");
  }
  if (j.contains("resolved_colour_max_delta")) {
    const json& resolved = readArray(j["resolved_colour_max_delta"], place + "/resolved_colour_max_delta", 4);
    for (std::size_t i = 0; i < 4; ++i) {
      c.resolvedColourMaxDelta[i] =
          readInteger<int>(resolved[i], place + "/resolved_colour_max_delta/" + std::to_string(i));
    }
  }
  c.colourPixelsOver = readInteger<std::uint64_t>(field(j, place, "colour_pixels_over"), place + "/colour_pixels_over");
  c.psnr = readNumber(field(j, place, "psnr"), place + "/psnr");
  c.depthMaxDelta = readNumber(field(j, place, "depth_max_delta"), place + "/depth_max_delta");
  c.depthPixelsOver = readInteger<std::uint64_t>(field(j, place, "depth_pixels_over"), place + "/depth_pixels_over");
  // Absent from files written before wider colour formats: every target was 8-bit then.
  if (j.contains("colour_unit")) c.colourUnit = readString(j["colour_unit"], place + "/colour_unit");
  // Absent from files written before stencil was compared: none could mismatch then.
  if (j.contains("stencil_mismatches")) {
    c.stencilMismatches = readInteger<std::uint64_t>(j["stencil_mismatches"], place + "/stencil_mismatches");
  }
  // Absent with one colour attachment (and from files written before there could be more).
  if (j.contains("more_colour_attachments")) {
    const std::string mp = place + "/more_colour_attachments";
    const json& more = j["more_colour_attachments"];
    if (!more.is_array()) bad(mp, "expected an array");
    for (std::size_t k = 0; k < more.size(); ++k) {
      const std::string ap = mp + "/" + std::to_string(k);
      AttachmentComparison& m = c.moreColour.emplace_back();
      const json& max = readArray(field(more[k], ap, "colour_max_delta"), ap + "/colour_max_delta", 4);
      for (std::size_t i = 0; i < 4; ++i) {
        m.colourMaxDelta[i] = readInteger<int>(max[i], ap + "/colour_max_delta/" + std::to_string(i));
      }
      m.colourUnit = readString(field(more[k], ap, "colour_unit"), ap + "/colour_unit");
      m.colourPixelsOver =
          readInteger<std::uint64_t>(field(more[k], ap, "colour_pixels_over"), ap + "/colour_pixels_over");
    }
  }
  const json& failures = field(j, place, "failures");
  if (!failures.is_array()) bad(place + "/failures", "expected an array");
  for (std::size_t i = 0; i < failures.size(); ++i) {
    c.failures.push_back(readString(failures[i], place + "/failures/" + std::to_string(i)));
  }
  return c;
}

template <class Integer>
std::optional<Integer> readOptionalInteger(const json& value, const std::string& place) {
  if (value.is_null()) return std::nullopt;
  return readInteger<Integer>(value, place);
}

VariantResults readVariantResults(const json& j, const std::string& place) {
  VariantResults v;
  v.frames = readInteger<unsigned>(field(j, place, "frames"), place + "/frames");
  v.lavapipeMilliseconds = readNumber(field(j, place, "lavapipe_milliseconds"), place + "/lavapipe_milliseconds");
  v.lavapipeError = readString(field(j, place, "lavapipe_error"), place + "/lavapipe_error");
  const json& runs = field(j, place, "runs");
  if (!runs.is_array()) bad(place + "/runs", "expected an array");
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::string p = place + "/runs/" + std::to_string(i);
    const json& r = runs[i];
    const auto at = [&](const char* key) -> const json& { return field(r, p, key); };
    const auto where = [&](const char* key) { return p + "/" + key; };
    VariantRun run;
    run.label = readString(at("label"), where("label"));
    run.method = readString(at("method"), where("method"));
    run.depth = readString(at("depth"), where("depth"));
    const json& frames = at("frame_milliseconds");
    if (!frames.is_array()) bad(where("frame_milliseconds"), "expected an array");
    for (std::size_t k = 0; k < frames.size(); ++k) {
      run.frameMilliseconds.push_back(readNumber(frames[k], where("frame_milliseconds") + "/" + std::to_string(k)));
    }
    run.medianMilliseconds = readNumber(at("median_milliseconds"), where("median_milliseconds"));
    run.coverageMismatches = readOptionalInteger<std::uint64_t>(at("coverage_mismatches"), where("coverage_mismatches"));
    run.colourMaxDelta = readOptionalInteger<int>(at("colour_max_delta"), where("colour_max_delta"));
    run.differingPixels = readOptionalInteger<std::uint64_t>(at("differing_pixels"), where("differing_pixels"));
    if (const json& w = at("within_tolerance"); !w.is_null()) run.withinTolerance = readBool(w, where("within_tolerance"));
    if (const json& h = at("hits"); !h.is_null()) {
      const std::string hp = where("hits");
      HitCounts hits;
      hits.cracks = readInteger<std::uint64_t>(field(h, hp, "cracks"), hp + "/cracks");
      hits.doubleHits = readInteger<std::uint64_t>(field(h, hp, "double_hits"), hp + "/double_hits");
      hits.referenceCovered = readInteger<std::uint64_t>(field(h, hp, "reference_covered"), hp + "/reference_covered");
      run.hits = hits;
    }
    run.error = readString(at("error"), where("error"));
    v.runs.push_back(std::move(run));
  }
  return v;
}

SceneResult readSceneResult(const json& j, const std::string& place) {
  const auto at = [&](const char* key) -> const json& { return field(j, place, key); };
  const auto where = [&](const char* key) { return place + "/" + key; };
  SceneResult r;
  r.entry.name = readString(at("name"), where("name"));
  r.entry.path = readString(at("path"), where("path"));
  r.outcome = readOutcome(at("outcome"), where("outcome"));
  r.actual = readOutcome(at("actual"), where("actual"));
  if (const json& e = at("expectation"); !e.is_null()) {
    const std::string p = where("expectation");
    Expectation expectation;
    expectation.outcome = readOutcome(field(e, p, "outcome"), p + "/outcome");
    expectation.reason = readString(field(e, p, "reason"), p + "/reason");
    expectation.line = readInteger<int>(field(e, p, "line"), p + "/line");
    r.expectation = expectation;
  }
  r.error = readString(at("error"), where("error"));
  r.loaded = readBool(at("loaded"), where("loaded"));
  r.description = readString(at("description"), where("description"));
  r.width = readInteger<std::uint32_t>(at("width"), where("width"));
  r.height = readInteger<std::uint32_t>(at("height"), where("height"));
  r.tolerance = readTolerance(at("tolerance"), where("tolerance"));
  if (const json& c = at("comparison"); !c.is_null()) r.comparison = readComparison(c, where("comparison"));
  r.softMilliseconds = readNumber(at("soft_milliseconds"), where("soft_milliseconds"));
  r.vulkanMilliseconds = readNumber(at("vulkan_milliseconds"), where("vulkan_milliseconds"));
  r.milliseconds = readNumber(at("milliseconds"), where("milliseconds"));
  {
    const std::string p = where("step_milliseconds");
    const json& t = at("step_milliseconds");
    r.timings.load = readNumber(field(t, p, "load"), p + "/load");
    r.timings.soft = readNumber(field(t, p, "soft"), p + "/soft");
    r.timings.vulkan = readNumber(field(t, p, "vulkan"), p + "/vulkan");
    r.timings.compare = readNumber(field(t, p, "compare"), p + "/compare");
    r.timings.images = readNumber(field(t, p, "images"), p + "/images");
    if (t.contains("variants")) r.timings.variants = readNumber(t["variants"], p + "/variants");  // since the chart
  }
  r.imageRoot = readString(at("image_root"), where("image_root"));
  const json& images = at("images");
  if (!images.is_array()) bad(where("images"), "expected an array");
  for (std::size_t i = 0; i < images.size(); ++i) {
    const std::string p = where("images") + "/" + std::to_string(i);
    r.images.push_back({readString(field(images[i], p, "kind"), p + "/kind"),
                        readString(field(images[i], p, "file"), p + "/file")});
  }
  r.pixelData = readString(at("pixel_data"), where("pixel_data"));
  const json& range = readArray(at("depth_view_range"), where("depth_view_range"), 2);
  r.depthViewRange = {static_cast<float>(readNumber(range[0], where("depth_view_range") + "/0")),
                      static_cast<float>(readNumber(range[1], where("depth_view_range") + "/1"))};
  // Added with the chart: absent in older files, read as none.
  if (j.contains("variants") && !j["variants"].is_null()) r.variants = readVariantResults(j["variants"], where("variants"));
  if (j.contains("stability_case")) r.stabilityCase = readBool(j["stability_case"], where("stability_case"));
  // Added with the deviations: absent in older files, read as not measured.
  if (j.contains("spec_deviation_pixels") && !j["spec_deviation_pixels"].is_null()) {
    r.specDeviationPixels = readInteger<std::uint64_t>(j["spec_deviation_pixels"], where("spec_deviation_pixels"));
  }
  return r;
}

template <class T, class Read>
softraster::Result<T> guarded(const Read& read) {
  try {
    return read();
  } catch (const BadField& e) {
    return softraster::Status::error(std::string("results JSON: ") + e.what());
  } catch (const json::exception& e) {
    return softraster::Status::error(std::string("results JSON: ") + e.what());
  }
}

}  // namespace

json sceneResultToJson(const SceneResult& r) {
  json j;
  j["name"] = r.entry.name;
  j["path"] = r.entry.path.string();
  j["outcome"] = outcomeName(r.outcome);
  j["actual"] = outcomeName(r.actual);
  j["expectation"] = r.expectation ? json{{"outcome", outcomeName(r.expectation->outcome)},
                                          {"reason", r.expectation->reason},
                                          {"line", r.expectation->line}}
                                   : json(nullptr);
  j["error"] = r.error;
  j["loaded"] = r.loaded;
  j["description"] = r.description;
  j["width"] = r.width;
  j["height"] = r.height;
  j["tolerance"] = toleranceJson(r.tolerance);
  j["comparison"] = r.comparison ? comparisonJson(*r.comparison) : json(nullptr);
  j["soft_milliseconds"] = number(r.softMilliseconds);
  j["vulkan_milliseconds"] = number(r.vulkanMilliseconds);
  j["milliseconds"] = number(r.milliseconds);
  j["step_milliseconds"] = {{"load", number(r.timings.load)},
                            {"soft", number(r.timings.soft)},
                            {"vulkan", number(r.timings.vulkan)},
                            {"compare", number(r.timings.compare)},
                            {"images", number(r.timings.images)},
                            {"variants", number(r.timings.variants)}};
  j["image_root"] = r.imageRoot.string();
  json images = json::array();
  for (const SceneImage& image : r.images) images.push_back({{"kind", image.kind}, {"file", image.file.string()}});
  j["images"] = images;
  j["pixel_data"] = r.pixelData.string();
  j["depth_view_range"] = {number(r.depthViewRange.first), number(r.depthViewRange.second)};
  j["variants"] = r.variants ? variantResultsToJson(*r.variants) : json(nullptr);
  j["stability_case"] = r.stabilityCase;
  j["spec_deviation_pixels"] = optionalNumber(r.specDeviationPixels);
  return j;
}

json variantResultsToJson(const VariantResults& v) {
  json runs = json::array();
  for (const VariantRun& run : v.runs) {
    json frames = json::array();
    for (double ms : run.frameMilliseconds) frames.push_back(number(ms));
    runs.push_back({{"label", run.label},
                    {"method", run.method},
                    {"depth", run.depth},
                    {"frame_milliseconds", frames},
                    {"median_milliseconds", number(run.medianMilliseconds)},
                    {"coverage_mismatches", optionalNumber(run.coverageMismatches)},
                    {"colour_max_delta", run.colourMaxDelta ? json(*run.colourMaxDelta) : json(nullptr)},
                    {"differing_pixels", optionalNumber(run.differingPixels)},
                    {"within_tolerance", run.withinTolerance ? json(*run.withinTolerance) : json(nullptr)},
                    {"hits", run.hits ? json{{"cracks", run.hits->cracks},
                                             {"double_hits", run.hits->doubleHits},
                                             {"reference_covered", run.hits->referenceCovered}}
                                      : json(nullptr)},
                    {"error", run.error}});
  }
  return {{"frames", v.frames},
          {"lavapipe_milliseconds", number(v.lavapipeMilliseconds)},
          {"lavapipe_error", v.lavapipeError},
          {"runs", runs}};
}

softraster::Result<VariantResults> variantResultsFromJson(const json& value) {
  return guarded<VariantResults>([&] { return readVariantResults(value, ""); });
}

softraster::Result<SceneResult> sceneResultFromJson(const json& value) {
  return guarded<SceneResult>([&] { return readSceneResult(value, ""); });
}

namespace {

// The known deviations (run/deviations.hpp), each with what this run measured on its scene
// (null when the scene was not in the run or did not draw). Derived from the scenes, so a reader
// does not read it back.
json deviationsJson(const RunResults& run) {
  json list = json::array();
  for (const KnownDeviation& d : knownDeviations()) {
    std::optional<std::uint64_t> measured;
    for (const SceneResult& r : run.scenes) {
      if (r.entry.name == d.scene && r.specDeviationPixels) measured = r.specDeviationPixels;
    }
    list.push_back({{"name", d.name},
                    {"spec", d.spec},
                    {"lavapipe", d.lavapipe},
                    {"scene", d.scene},
                    {"spec_mode_differing_pixels", optionalNumber(measured)}});
  }
  return list;
}

// The expectations file as a run applied it: its path as given and every entry in name order.
json expectationsJson(const std::optional<Expectations>& expectations) {
  if (!expectations) return nullptr;
  json entries = json::array();
  for (const auto& [name, e] : expectations->byScene) {
    entries.push_back({{"scene", name}, {"outcome", outcomeName(e.outcome)}, {"reason", e.reason}, {"line", e.line}});
  }
  return {{"file", expectations->file.generic_string()}, {"entries", entries}};
}

std::optional<Expectations> readExpectations(const json& value, const std::string& place) {
  if (value.is_null()) return std::nullopt;
  Expectations expectations;
  expectations.file = readString(field(value, place, "file"), place + "/file");
  const json& entries = field(value, place, "entries");
  if (!entries.is_array()) bad(place + "/entries", "expected an array");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const std::string p = place + "/entries/" + std::to_string(i);
    Expectation e;
    e.outcome = readOutcome(field(entries[i], p, "outcome"), p + "/outcome");
    e.reason = readString(field(entries[i], p, "reason"), p + "/reason");
    e.line = readInteger<int>(field(entries[i], p, "line"), p + "/line");
    expectations.byScene[readString(field(entries[i], p, "scene"), p + "/scene")] = e;
  }
  return expectations;
}

}  // namespace

json runResultsToJson(const RunResults& run) {
  json scenes = json::array();
  for (const SceneResult& r : run.scenes) scenes.push_back(sceneResultToJson(r));
  json suite = json::array();
  for (const SceneEntry& entry : run.suite) suite.push_back({{"name", entry.name}, {"path", entry.path.string()}});
  return {{"format", kResultsFormat},
          {"suite_name", run.suiteName},
          {"suite", suite},
          {"shard", {{"index", run.shard.index}, {"count", run.shard.count}}},
          {"render_arguments", run.renderArguments},
          {"expectations", expectationsJson(run.expectations)},
          {"junit_file", run.junitFile.generic_string()},
          {"seconds", number(run.seconds)},
          {"jobs", run.jobs},
          {"finished", static_cast<std::int64_t>(run.finished)},
          {"deviations", deviationsJson(run)},
          {"scenes", scenes}};
}

softraster::Result<RunResults> runResultsFromJson(const json& value) {
  return guarded<RunResults>([&] {
    RunResults run;
    const int format = readInteger<int>(field(value, "", "format"), "/format");
    if (format != kResultsFormat) {
      bad("/format", "version " + std::to_string(format) + ", but this crosscheck reads version " +
                         std::to_string(kResultsFormat));
    }
    run.suiteName = readString(field(value, "", "suite_name"), "/suite_name");
    const json& suite = field(value, "", "suite");
    if (!suite.is_array()) bad("/suite", "expected an array");
    for (std::size_t i = 0; i < suite.size(); ++i) {
      const std::string p = "/suite/" + std::to_string(i);
      run.suite.push_back(
          {readString(field(suite[i], p, "name"), p + "/name"), readString(field(suite[i], p, "path"), p + "/path")});
    }
    const json& shard = field(value, "", "shard");
    run.shard.index = readInteger<std::size_t>(field(shard, "/shard", "index"), "/shard/index");
    run.shard.count = readInteger<std::size_t>(field(shard, "/shard", "count"), "/shard/count");
    if (run.shard.count == 0 || run.shard.index == 0 || run.shard.index > run.shard.count) {
      bad("/shard", "expected 1 <= index <= count");
    }
    run.renderArguments = readString(field(value, "", "render_arguments"), "/render_arguments");
    // Absent in files written before it was recorded: not known, as no expectations.
    if (value.contains("expectations")) run.expectations = readExpectations(value["expectations"], "/expectations");
    run.junitFile = readString(field(value, "", "junit_file"), "/junit_file");
    run.seconds = readNumber(field(value, "", "seconds"), "/seconds");
    run.jobs = readInteger<unsigned>(field(value, "", "jobs"), "/jobs");
    run.finished = static_cast<std::time_t>(readInteger<std::int64_t>(field(value, "", "finished"), "/finished"));
    const json& scenes = field(value, "", "scenes");
    if (!scenes.is_array()) bad("/scenes", "expected an array");
    for (std::size_t i = 0; i < scenes.size(); ++i) run.scenes.push_back(readSceneResult(scenes[i], "/scenes/" + std::to_string(i)));
    return run;
  });
}

}  // namespace crosscheck
