// RunResults and SceneResult as JSON values and back, every field, so that what is read back
// equals what was written: the conformance runner's worker processes send each SceneResult to
// the parent this way (as CBOR of this JSON, which carries any byte in a string), and the same
// functions can back a results.json file that a later run reads and merges across shards.
// Doubles that are not finite (PSNR +inf when identical) are the strings "inf", "-inf", "nan";
// paths are their native strings; outcomes their names (run/outcome.hpp).
// Deliberately no file I/O and no text formatting: the caller dumps the value (as text with
// invalid UTF-8 replaced, or as CBOR) and owns the file; a value read back is checked field by
// field, and the error names the first field that is missing or of the wrong type.
#pragma once

#include "results/results.hpp"

#include <softraster/status.hpp>

#include <nlohmann/json_fwd.hpp>

namespace crosscheck {

nlohmann::json sceneResultToJson(const SceneResult& result);
// The error is one line: "results JSON: PLACE: what is wrong" (PLACE a JSON pointer).
softraster::Result<SceneResult> sceneResultFromJson(const nlohmann::json& value);

nlohmann::json runResultsToJson(const RunResults& run);
softraster::Result<RunResults> runResultsFromJson(const nlohmann::json& value);

}  // namespace crosscheck
