#!/usr/bin/env bash
# Command-line tests of `crosscheck bench` and of render/compare's --method and --threads, one case
# per ctest test:
#   bench_cli_test.sh CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
# Exit 0: passed, 1: failed (with a message), 77: skipped (a tool it needs is missing).
# Never checks a timing: the machine is shared.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
cli_case_begin bench-cli "$@"

tiny=tests/data/bench/tiny_sphere.json

# check_usage PATTERN ARGS...: exit 2, one error line matching PATTERN, nothing on stdout.
check_usage() {
  local pattern=$1
  shift
  run "$@"
  expect_status 2
  expect_err "$pattern"
  expect_one_error_line
}

case $case_name in
  bad_usage)
    check_usage '^crosscheck: --frames 0: expected a whole number from 1 to 100000$' bench --frames 0 "$tiny"
    check_usage '^crosscheck: --frames abc: expected a whole number from 1 to 100000$' bench --frames abc "$tiny"
    check_usage '^crosscheck: --frames -3: expected a whole number' bench --frames=-3 "$tiny"
    check_usage '^crosscheck: --warmup x: expected a whole number from 0 to 100000$' bench --warmup x "$tiny"
    check_usage '^crosscheck: --threads 2.5: expected a whole number from 0 to 1024$' bench --threads 2.5 "$tiny"
    check_usage '^crosscheck: tests/data/bench/no_such_scene.json: cannot open scene file: file not found$' \
      bench tests/data/bench/no_such_scene.json
    check_usage '^crosscheck: scenez/: no such file or directory$' bench scenez/
    check_usage '^crosscheck: tests/data/malformed_syntax.json: parse error at line 3' bench tests/data/malformed_syntax.json
    check_usage '^crosscheck: --method fast: expected one of exact, exact-scalar, scanline, trapezoid, barycentric$' \
      render "$tiny" --method fast -o "$artifacts/x.png"
    check_usage '^crosscheck: --threads many: expected a whole number from 0 to 1024$' compare "$tiny" --threads many
    check_usage '^crosscheck: --threads 5000: expected a whole number from 0 to 1024$' compare "$tiny" --threads 5000
    ;;
  bad_method)
    # bench --method: an unknown name, an empty entry, +affine on an exact method: one line, exit 2.
    list='exact, exact-scalar, scanline, trapezoid, barycentric'
    check_usage "^crosscheck: --method fast: expected all or a comma-separated list of $list \\(a course method may be NAME\\+affine\\)$" \
      bench --method fast "$tiny"
    check_usage '^crosscheck: --method exact,,scanline: expected all or a comma-separated list' bench --method exact,,scanline "$tiny"
    check_usage '^crosscheck: --method exact\+affine: expected all' bench --method exact+affine "$tiny"
    check_usage '^crosscheck: --method scanline,Barycentric: expected all' bench --method scanline,Barycentric "$tiny"
    check_usage '^crosscheck: --affine: applies only to the course.s methods \(scanline, trapezoid, barycentric\), not to --method exact$' \
      compare "$tiny" --affine
    check_usage '^crosscheck: --affine: applies only to the course.s methods' render "$tiny" --method exact-scalar --affine -o "$artifacts/x.png"
    ;;
  course_methods)
    # bench --method all: every method of kMethods in order, their agreement in the table and JSON;
    # a list with +affine; render and compare with a course method and --affine.
    need_python() { command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }; }
    need_python
    run bench "$tiny" --method all --frames 1 --warmup 0 --threads 1 --json "$artifacts/all.json"
    [ "$status" -le 1 ] || fail "exit status $status, expected 0 or 1"
    for m in exact exact-scalar scanline trapezoid barycentric; do
      expect_out "^tiny_sphere +48x32 +256 +softraster $m +1 "
    done
    python3 - "$artifacts/all.json" <<'PY' || fail "all.json does not list every method with its agreement"
import json, sys
d = json.load(open(sys.argv[1]))
(s,) = d["scenes"]
assert [(r["renderer"], r.get("method")) for r in s["results"]] == [
    ("softraster", m) for m in ("exact", "exact-scalar", "scanline", "trapezoid", "barycentric")] + [("lavapipe", None)]
for r in s["results"][:5]:
    assert r["affine_varyings"] is False
    for k in ("coverage_mismatches", "pixels_differing", "colour_max_delta", "colour_mean_delta", "depth_max_delta"):
        assert isinstance(r[k], (int, float)), k
    assert r["error"] is None
for r in s["results"][:2]:
    assert (r["pixels_differing"], r["colour_mean_delta"]) == (0, 0)
for r in s["results"][2:5]:
    assert r["threads"] == 1
lavapipe = s["results"][5]
assert lavapipe["pixels_differing"] is None and lavapipe["colour_mean_delta"] is None
PY
    run bench "$tiny" --method scanline,barycentric+affine,scanline --frames 1 --warmup 0 --threads 1 --json "$artifacts/list.json"
    [ "$status" -le 1 ] || fail "exit status $status, expected 0 or 1"
    expect_out '^tiny_sphere +48x32 +256 +softraster barycentric\+affine +1 '
    python3 - "$artifacts/list.json" <<'PY' || fail "list.json does not have the methods asked for"
import json, sys
(s,) = json.load(open(sys.argv[1]))["scenes"]
assert [(r.get("method"), r.get("affine_varyings")) for r in s["results"]] == [
    ("scanline", False), ("barycentric", True), (None, None)]
PY
    for m in scanline trapezoid barycentric; do
      run render "$tiny" --renderer soft --method $m -o "$artifacts/$m.png"
      expect_status 0
      expect_out "with softraster \($m, every core\)"
      run render "$tiny" --renderer soft --method $m --affine --threads 1 -o "$artifacts/$m-affine.png"
      expect_status 0
      expect_out "with softraster \($m, 1 thread, affine varyings\)"
      run compare "$tiny" --method $m --json
      [ "$status" -le 1 ] || fail "compare --method $m: exit status $status, expected 0 or 1"
      expect_out '"coverage_mismatches"'
    done
    ;;
  tiny_json)
    need_python() { command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }; }
    need_python
    run bench "$tiny" --frames 2 --warmup 1 --threads 1 --json "$artifacts/bench.json"
    expect_status 0
    expect_out '> 1: softraster is faster'
    expect_out '^tiny_sphere +48x32 +256 +softraster exact +1 '
    expect_out '^tiny_sphere +48x32 +256 +softraster exact-scalar +1 '
    expect_out '^tiny_sphere +48x32 +256 +lavapipe +1 .*\(reference\)$'
    [ "$(grep -c ' 0/0/0$' "$artifacts/out.txt")" -eq 2 ] || fail "expected agreement 0/0/0 for both methods"
    python3 - "$artifacts/bench.json" <<'PY' || fail "bench.json does not have the documented shape"
import json, sys
d = json.load(open(sys.argv[1]))
assert set(d["machine"]) >= {"cpu", "cores", "memset_gb_per_s", "memset_warm_gb_per_s", "allocator"}
assert d["machine"]["allocator"] in ("glibc: mmap threshold 32 MiB, trim threshold 64 MiB",
                                    "AddressSanitizer's allocator: its own (mallopt does not reach it)"), d["machine"]["allocator"]
assert d["softraster_allow_avx512"] is True
(s,) = d["scenes"]
assert s["pixels"] == 48 * 32 and s["triangles"] == 256 and s["memory_limit_ms"] > 0
assert [(r["renderer"], r.get("method")) for r in s["results"]] == [
    ("softraster", "exact"), ("softraster", "exact-scalar"), ("lavapipe", None)]
for r in s["results"]:
    assert r["threads"] == 1 and len(r["frames_ms"]) == 2
    for k in ("median_ms", "min_ms", "setup_ms", "ratio_vs_lavapipe"):
        assert isinstance(r[k], (int, float)), k
for r in s["results"][:2]:
    assert (r["coverage_mismatches"], r["colour_max_delta"], r["depth_max_delta"]) == (0, 0, 0)
PY
    ;;
  no_avx512)
    # --softraster-no-avx512: the fast path without AVX-512 (the same bits), said in the table and the JSON.
    command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }
    run bench "$tiny" --frames 2 --warmup 1 --threads 2 --method exact --softraster-no-avx512 --json "$artifacts/bench.json"
    expect_status 0
    expect_out '^softraster: AVX-512 not allowed \(--softraster-no-avx512\)'
    expect_out '^tiny_sphere +48x32 +256 +softraster exact +2 .* 0/0/0$'
    python3 - "$artifacts/bench.json" <<'PY' || fail "bench.json does not say AVX-512 was not allowed"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["softraster_allow_avx512"] is False
PY
    ;;
  chart_svg)
    # A bench JSON charted: the SVG parses as XML, has one marker per softraster result in each of a
    # scene's two panels and in the overview, each with a tooltip, the lavapipe line and a front.
    command -v python3 >/dev/null || { echo "SKIPPED: python3 is not installed"; exit 77; }
    run bench "$tiny" --frames 2 --warmup 1 --threads 1 --json "$artifacts/bench.json"
    expect_status 0
    run chart "$artifacts/bench.json"
    expect_status 0
    expect_out "^chart: 1 scenes, 2 points: $artifacts/bench.svg\$"
    run chart "$artifacts/bench.json" -o "$artifacts/sub/chart.svg"
    expect_status 0
    python3 - "$artifacts/sub/chart.svg" "$artifacts/bench.json" <<'PY' || fail "the chart's SVG is not as expected"
import json, sys
import xml.etree.ElementTree as ET
ns = {"s": "http://www.w3.org/2000/svg"}
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "{http://www.w3.org/2000/svg}svg", root.tag
bench = json.load(open(sys.argv[2]))
soft = [r for s in bench["scenes"] for r in s["results"] if r["renderer"] == "softraster"]
markers = [g for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("class") == "marker"]
# two panels per scene plus the overview
assert len(markers) == 3 * len(soft), (len(markers), len(soft))
for m in markers:
    t = m.find("s:title", ns)
    assert t is not None and " ms" in t.text and "coverage mismatches" in t.text, ET.tostring(m)
labels = {m.get("data-label") for m in markers}
assert labels == {r["method"] for r in soft}, labels
lines = [g for g in root.iter("{http://www.w3.org/2000/svg}g") if g.get("class") == "lavapipe"]
assert len(lines) == 3, len(lines)
fronts = [p for p in root.iter("{http://www.w3.org/2000/svg}polyline") if p.get("class") == "pareto"]
assert len(fronts) == 2, len(fronts)
texts = " ".join(t.text or "" for t in root.iter("{http://www.w3.org/2000/svg}text"))
assert "frame time (median, ms, log scale)" in texts and "coverage mismatches (pixels" in texts
PY
    ;;
  chart_errors)
    # Each is one error line naming the file, exit 2, nothing written.
    printf '{"scenes": [' >"$artifacts/truncated.json"
    printf '{"frames": 3}' >"$artifacts/other.json"
    printf '{"scenes": [{"scene": "a.json", "results": [{"renderer": "softraster", "median_ms": 1}]}]}' >"$artifacts/ok.json"
    : >"$artifacts/file"
    check_usage "^crosscheck: $artifacts/missing.json: file not found\$" chart "$artifacts/missing.json"
    check_usage "^crosscheck: $artifacts: is a directory" chart "$artifacts"
    check_usage "^crosscheck: $artifacts/truncated.json: not JSON: " chart "$artifacts/truncated.json"
    check_usage "^crosscheck: $artifacts/other.json: not a bench JSON: no \"scenes\" array\$" chart "$artifacts/other.json"
    check_usage "^crosscheck: $artifacts/file/chart.svg: cannot write the chart" chart "$artifacts/ok.json" -o "$artifacts/file/chart.svg"
    run chart
    expect_status 2
    expect_err '^crosscheck: BENCH is required'
    [ ! -e "$artifacts/truncated.svg" ] && [ ! -e "$artifacts/other.svg" ] || fail "a chart was written for a bad JSON"
    run chart "$artifacts/ok.json"
    expect_status 0
    ;;
  render_methods)
    # Both methods and any thread count give the same bits (and the same as Vulkan).
    run render "$tiny" --renderer vulkan -o "$artifacts/vulkan.png"
    expect_status 0
    for args in "--method exact --threads 1" "--method exact --threads 3" "--method exact-scalar" "--threads 0"; do
      # shellcheck disable=SC2086
      run render "$tiny" --renderer soft $args -o "$artifacts/soft.png"
      expect_status 0
      cmp -s "$artifacts/soft.png" "$artifacts/vulkan.png" || fail "render $args differs from Vulkan"
    done
    run compare "$tiny" --method exact-scalar --threads 2 --json
    expect_status 0
    expect_out '"passed":true'
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "passed: $case_name"
