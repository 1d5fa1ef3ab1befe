#!/usr/bin/env bash
# Command-line tests of `crosscheck stability`, one case per ctest test:
#   stability_cli_test.sh CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
#   exact_passes  every case of scenes/stability/ (one per case of issue 11's list) runs with every
#                 variant, and exact passes each: 0 wrong pixels, 0 coverage mismatches, 0 cracks,
#                 0 double hits; exit 0; the table and the JSON say so; no variant crashed the run
#   reproducible  two runs give the same numbers for every variant (timings aside)
#   bad_usage     one error line, exit 2
# Exit 0: passed, 1: failed (with a message), 77: skipped (python3 missing). Never checks a timing.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
cli_case_begin stability-cli "$@"
stderr_lines=20  # its log is long

need_python() { command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }; }

cases=$(ls scenes/stability/*.json | wc -l)

case $case_name in
  exact_passes)
    need_python
    run stability --frames 1 --threads 2 --json "$artifacts/stability.json"
    expect_status 0
    cat "$artifacts/out.txt"
    expect_out "^stability: $cases cases, [0-9]+ of [0-9]+ rows pass; exact passes every case\$"
    for name in near_plane_crossing inside_room_yaw_90 inside_room_yaw_180 behind_camera_only closed_mesh_edges \
      slivers_needles sub_pixel_triangles zero_area_triangles huge_coordinate_values coplanar_z_fighting \
      tiny_near_plane nan_inf_vertices w_zero_vertices; do
      expect_out "^$name +exact +Pass +0 +0 +0 +0 +0 "
    done
    python3 - "$artifacts/stability.json" "$cases" <<'PY' || fail "stability.json is not as expected"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["reference"] == "exact" and d["reference_passes"] is True
assert len(d["cases"]) == int(sys.argv[2])
labels = None
for c in d["cases"]:
    assert c["error"] == "", c
    runs = c["variants"]["runs"]
    if labels is None:
        labels = [r["label"] for r in runs]
        assert labels[:2] == ["exact", "exact 1/z"] and "exact-scalar" in labels, labels
    assert [r["label"] for r in runs] == labels
    for r in runs:
        # every variant ran to the end: measured, not crashed
        assert r["error"] == "" or r["error"].startswith(("softraster", "hit count", "exception")), r
        if r["label"] in ("exact", "exact-scalar"):
            assert r["passed"] and r["differing_pixels"] == 0 and r["coverage_mismatches"] == 0, (c["name"], r)
            assert r["hits"]["cracks"] == 0 and r["hits"]["double_hits"] == 0, (c["name"], r)
        if r["error"] == "":
            assert isinstance(r["differing_pixels"], int) and r["hits"] is not None, (c["name"], r)
closed = next(c for c in d["cases"] if c["name"] == "closed_mesh_edges")
exact = closed["variants"]["runs"][0]
assert exact["hits"]["reference_covered"] > 1000, exact  # the sphere's silhouette, counted
PY
    ;;
  reproducible)
    need_python
    run stability --frames 1 --threads 1 --json "$artifacts/one.json"
    expect_status 0
    run stability --frames 1 --threads 2 --json "$artifacts/two.json"
    expect_status 0
    python3 - "$artifacts/one.json" "$artifacts/two.json" <<'PY' || fail "two runs gave different numbers"
import json, sys
def numbers(path):
    d = json.load(open(path))
    def strip(v):
        if isinstance(v, dict):
            return {k: strip(x) for k, x in v.items() if not k.endswith("milliseconds")}
        if isinstance(v, list):
            return [strip(x) for x in v]
        return v
    return strip(d)
a, b = numbers(sys.argv[1]), numbers(sys.argv[2])
for ca, cb in zip(a["cases"], b["cases"]):
    assert ca == cb, (ca["name"], ca, cb)
assert a == b
PY
    ;;
  bad_usage)
    run stability --frames 0
    expect_status 2
    grep -qE '^crosscheck: --frames 0: expected a whole number from 1 to 1000$' "$artifacts/err.txt" || fail "no --frames error"
    run stability scenez/
    expect_status 2
    grep -qE '^crosscheck: scenez/: no such file or directory$' "$artifacts/err.txt" || fail "no folder error"
    : >"$artifacts/file"
    run stability scenes/stability/near_plane_crossing.json --json "$artifacts/file/out.json"
    expect_status 2
    grep -qE "^crosscheck: $artifacts/file/out.json: cannot write this file\$" "$artifacts/err.txt" || fail "no JSON error"
    # A case that cannot be loaded is a failing row, not a fault: the rest still runs, exit 1.
    run stability tests/data/malformed_syntax.json scenes/stability/near_plane_crossing.json
    expect_status 1
    expect_out '^malformed_syntax +- +Fail +.*parse error'
    expect_out '^near_plane_crossing +exact +Pass '
    expect_out 'exact FAILS a case$'
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "passed: $case_name"
