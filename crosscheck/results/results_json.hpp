// RunResults and SceneResult as JSON values and back, every field (but RunResults::commandLine,
// which describes one invocation, not the results), so that what is read back equals what was
// written: the conformance runner's worker processes send each SceneResult to the parent this way
// (as CBOR of this JSON, which carries any byte in a string), and results.json (results_file.hpp)
// is this JSON of a whole run, which merge reads across shards and report --baseline compares
// against. The run's value carries "format": kResultsFormat, checked when read back.
// Doubles that are not finite (PSNR +inf when identical) are the strings "inf", "-inf", "nan";
// paths are their native strings, as they are (results_file.hpp makes them relative to the file);
// outcomes their names (run/outcome.hpp). The fields: docs/results-json.md.
// Deliberately no file I/O and no text formatting: the caller dumps the value (as text with
// invalid UTF-8 replaced, or as CBOR) and owns the file; a value read back is checked field by
// field, and the error names the first field that is missing or of the wrong type.
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <nlohmann/json_fwd.hpp>

namespace crosscheck {

// The version of the format, the top-level "format" field; bumped when a field changes meaning
// or goes away (a reader refuses any other version).
inline constexpr int kResultsFormat = 1;

nlohmann::json sceneResultToJson(const SceneResult& result);
// The error is one line: "results JSON: PLACE: what is wrong" (PLACE a JSON pointer).
softraster::Result<SceneResult> sceneResultFromJson(const nlohmann::json& value);

// A scene's variant runs (the chart's data), as results.json's "variants" and the stability JSON
// carry them.
nlohmann::json variantResultsToJson(const VariantResults& variants);
softraster::Result<VariantResults> variantResultsFromJson(const nlohmann::json& value);

nlohmann::json runResultsToJson(const RunResults& run);
softraster::Result<RunResults> runResultsFromJson(const nlohmann::json& value);

}  // namespace crosscheck
