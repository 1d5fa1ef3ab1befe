#!/usr/bin/env bash
# Opens a generated report in headless Chromium (Debian's chromium, from file://, no network) and
# checks that the page rendered (its script ran without errors), that every image and thumbnail
# loaded, that the pixel data for the value readout (written for the failing scene only) loaded
# and decoded, that the readout shows values under the pointer, that the summary table has a row
# per scene, sorts on a header click and filters by "only unexpected" and by name, that the
# expectations lines for the unexpected results are there to copy, that the flicker toggle
# swaps the render, and that the marks against a baseline (an earlier run, --baseline) show the
# new failure, the fixed scene and the changed metrics. Keeps screenshots:
#   ARTIFACTS/report/report.png        the page as it opens (1400x1000)
#   ARTIFACTS/report/report-check.png  every scene opened (?check, 1400x3000)
#   ARTIFACTS/report/report-chart.png  the speed-vs-accuracy chart (#chart)
#   ARTIFACTS/report/report-stability.png  a report of two stability cases: its table
#   ARTIFACTS/report/report-samples.png    an MSAA scene that differs, opened: its sample views
# It also checks the chart (panels as SVG elements, a marker with a tooltip per method and option,
# the Pareto fronts), --no-chart, the stability table of a report over two stability cases, and
# the sample menu of an MSAA scene that differs (picking a sample swaps its three images).
# Usage: report_chromium_test.sh CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
# Exit 0: passed, 1: failed, 77: skipped because chromium is not installed.
set -uo pipefail
crosscheck=$1
src=$2
artifacts=$3/report
chromium=$(command -v chromium || command -v chromium-browser) || { echo "SKIPPED: chromium is not installed"; exit 77; }
rm -rf "$artifacts"
mkdir -p "$artifacts"
cd "$src" || exit 1

fail() {
  echo "FAILED: $*"
  exit 1
}

# The baseline: the fixtures with lavapipe's own fmuladd rounding (depth_slope passes) and
# flat_triangle expected to fail (an UnexpectedPass there).
"$crosscheck" report tests/data/conformance -o "$artifacts/baseline" --jobs 2 \
  --expectations tests/data/expectations/baseline.txt >"$artifacts/baseline.txt" 2>&1
status=$?
[ "$status" -eq 1 ] || { cat "$artifacts/baseline.txt"; fail "baseline report exit status $status, expected 1"; }
[ -s "$artifacts/baseline/results.json" ] || fail "the baseline wrote no results.json"

# A suite of the fixtures with Pass (flat_triangle), Fail (depth_slope under the fmuladd rounding
# lavapipe does not use here), Crash (broken_obj) and Skip (malformed, through expectations),
# against the baseline: depth_slope a new failure with changed metrics, flat_triangle fixed.
case "$(uname -m)" in
  x86_64 | i?86) if grep -qw fma /proc/cpuinfo; then other_fma=separate; else other_fma=fused; fi ;;
  aarch64 | arm64) other_fma=separate ;;
  *) other_fma=fused ;;
esac
"$crosscheck" report tests/data/conformance -o "$artifacts/site" --jobs 2 --softraster-fma "$other_fma" \
  --expectations tests/data/expectations/report.txt --baseline "$artifacts/baseline" >"$artifacts/report.txt" 2>&1
status=$?
cat "$artifacts/report.txt"
[ "$status" -eq 1 ] || fail "report exit status $status, expected 1 (depth_slope fails, broken_obj crashes)"
[ -s "$artifacts/site/index.html" ] || fail "no index.html"
[ "$(tail -n 1 "$artifacts/report.txt")" = "1 passed, 2 failed, 1 skipped" ] || fail "unexpected counts line"
scenes=4

# Offline: the page names no network resource at all.
if grep -qiE '(src|href)="(https?:)?//' "$artifacts/site/index.html"; then fail "index.html refers to the network"; fi

page="file://$(cd "$artifacts/site" && pwd)/index.html"
browse() {
  local profile
  profile=$(mktemp -d)
  timeout 120 "$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync --user-data-dir="$profile" \
    --virtual-time-budget=10000 "$@" 2>>"$artifacts/chromium.log"
  local rc=$?
  rm -rf "$profile"
  return $rc
}

browse --dump-dom "$page?check" >"$artifacts/dom.html" || fail "chromium failed (see $artifacts/chromium.log)"
body=$(grep -o '<body[^>]*>' "$artifacts/dom.html" | head -n 1)
echo "$body"
attr() { sed -nE "s/.* $1=\"([^\"]*)\".*/\\1/p" <<<"$body"; }
grep -q 'data-js-errors=' "$artifacts/dom.html" && fail "script errors: $(grep -o 'data-js-errors="[^"]*"' "$artifacts/dom.html")"
[ "$(attr data-ready)" = 1 ] || fail "the page's script did not run"
[ "$(attr data-check)" = done ] || fail "the self-check did not finish: '$(attr data-check)'"
loaded=$(attr data-images-loaded)
[ "$(attr data-images-failed)" = 0 ] || fail "images failed to load: $(attr data-images-failed-list)"
# depth_slope (failed): nine views (soft, vulkan, diff, two depth views, depth diff, flicker, the
# onion/wipe pair), a thumbnail in the table and three at the top; flat_triangle (passed,
# bit-identical): its preview and the preview as its thumbnail. Pixel data only for the scene outside its tolerance.
images=$((9 + 1 + 3 + 2))
[ "$loaded" = "$images/$images" ] || fail "images loaded: $loaded, expected $images of $images"
[ "$(attr data-thumbnails)" = 5 ] || fail "thumbnails: $(attr data-thumbnails), expected 5"
[ "$(attr data-pixels-loaded)" = "1/1" ] || fail "pixel data loaded: $(attr data-pixels-loaded) $(attr data-pixels-errors)"
[ ! -e "$artifacts/site/flat_triangle/pixels.js" ] || fail "pixel data written for a scene that passed"
[ "$(ls "$artifacts/site/flat_triangle")" = preview.png ] || fail "a bit-identical scene has more than preview.png: $(ls "$artifacts/site/flat_triangle")"
# Filters: every row, only unexpected (depth_slope, broken_obj), then the name "depth".
[ "$(attr data-filter-probe)" = "4,2,1" ] || fail "filter probe: '$(attr data-filter-probe)', expected 4,2,1"
attr data-expectations-lines | grep -qE '^broken_obj,Crash # .*broken_obj.* \| depth_slope,Fail # .*depth_pixels_over [0-9]+ &gt; 0 .* \| $' ||
  fail "expectations lines: '$(attr data-expectations-lines)'"
[ "$(attr data-summary-rows)" = "$scenes" ] || fail "summary table has $(attr data-summary-rows) rows, expected $scenes"
grep -q '<table id="summary"' "$artifacts/dom.html" || fail "no summary table"
[ "$(attr data-sort-probe)" = "malformed,flat_triangle,depth_slope,broken_obj" ] ||
  fail "sorting by scene name, Z to A, gave '$(attr data-sort-probe)'"
[ "$(attr data-flicker-probe)" = "depth_slope/vulkan.png" ] || fail "the flicker swap showed '$(attr data-flicker-probe)'"
# Baseline marks, worst first: depth_slope newly fails (its depth metrics changed), flat_triangle is
# fixed, broken_obj crashed in both (no mark), malformed was skipped in both.
[ "$(attr data-baseline-marks)" = "depth_slope:new failure+metrics changed,flat_triangle:fixed" ] ||
  fail "baseline marks: '$(attr data-baseline-marks)'"
attr data-baseline-summary | grep -qE '^Against the baseline .*/baseline/results\.json \([0-9 :-]+ UTC\): 1 new failure · 1 fixed · 1 scene with changed metrics$' ||
  fail "baseline summary line: '$(attr data-baseline-summary)'"
[ "$(attr data-baseline-changed-cells)" -ge 2 ] || fail "changed cells: '$(attr data-baseline-changed-cells)', expected depth pixels over and depth max at least"
[ "$(attr data-baseline-filter)" = 2 ] || fail "'only changed against the baseline' left $(attr data-baseline-filter) rows, expected 2"
attr data-readout | grep -qE '^x [0-9]+, y [0-9]+  \|  softraster RGBA [0-9 ]+  \|  Vulkan RGBA [0-9 ]+  \|' ||
  fail "the value readout shows no values: '$(attr data-readout)'"

# The chart (on by default): two scenes drew (flat_triangle, depth_slope), each with two panels,
# plus the overview; every method and option of the exact family at least as a marker in each
# panel (four variants today: exact and exact-scalar, each with z/w and 1/z depth), every marker
# with a tooltip, a Pareto front per panel; the panels are SVG elements in the page.
variants=$(python3 -c "import json;d=json.load(open('$artifacts/site/results.json'));print(max(len(s['variants']['runs']) for s in d['scenes'] if s['variants']))") ||
  fail "results.json has no variants"
[ "$variants" -ge 4 ] || fail "$variants variants per scene, expected at least 4"
[ "$(attr data-chart-panels)" = 5 ] || fail "chart panels: '$(attr data-chart-panels)', expected 5 (2 scenes x 2 + the overview)"
[ "$(attr data-chart-svg)" = true ] || fail "the chart's panels are not SVG elements in the page"
markers=$(attr data-chart-markers)
[ "$markers" -ge 8 ] && [ "$markers" -le $((3 * 2 * variants)) ] || fail "chart markers: '$markers'"
[ "$(attr data-chart-tooltips)" = "$markers" ] || fail "markers with a tooltip: $(attr data-chart-tooltips) of $markers"
[ "$(attr data-chart-pareto)" = 4 ] || fail "Pareto fronts: '$(attr data-chart-pareto)', expected one per scene panel"
grep -q '<h2 id="chart">Speed against accuracy</h2>' "$artifacts/dom.html" || fail "no chart section"
[ "$(attr data-stability-rows)" = 0 ] || fail "a stability table without stability cases"

# --no-chart: no chart, no variants.
"$crosscheck" report tests/data/conformance/flat_triangle.json -o "$artifacts/nochart" --no-chart >"$artifacts/nochart.txt" 2>&1 ||
  fail "report --no-chart failed: $(cat "$artifacts/nochart.txt")"
grep -q 'class="chart-panel' "$artifacts/nochart/index.html" && fail "--no-chart still drew a chart"
grep -q '"variants": null' "$artifacts/nochart/results.json" || fail "--no-chart wrote variants"

# Two stability cases: the stability table has a row per case and variant, exact passes both.
"$crosscheck" report scenes/stability/near_plane_crossing.json scenes/stability/closed_mesh_edges.json \
  -o "$artifacts/stability" >"$artifacts/stability.txt" 2>&1 || fail "stability report failed: $(cat "$artifacts/stability.txt")"
stability_page="file://$(cd "$artifacts/stability" && pwd)/index.html"
browse --dump-dom "$stability_page?check" >"$artifacts/stability-dom.html" || fail "chromium failed on the stability report"
body=$(grep -o '<body[^>]*>' "$artifacts/stability-dom.html" | head -n 1)
[ "$(attr data-check)" = done ] || fail "the stability report's self-check did not finish: '$(attr data-check)'"
[ "$(attr data-stability-rows)" = $((2 * variants)) ] || fail "stability rows: '$(attr data-stability-rows)', expected $((2 * variants))"
for name in near_plane_crossing closed_mesh_edges; do
  grep -qE "<tr class=\"st-Pass\"><td><a href=\"#scene=$name\">$name</a></td><td>exact</td>" "$artifacts/stability-dom.html" ||
    fail "exact does not pass $name in the stability table"
done
browse --window-size=1400,1600 --screenshot="$artifacts/report-stability.png" "$stability_page#stability" >/dev/null ||
  fail "no stability screenshot"
# An MSAA scene that differs (the MSAA scissor with softraster following the spec: lavapipe writes
# samples 1..3 in a column and a row, never sample 0): its sample menu shows each sample's images,
# every one of which loads.
"$crosscheck" report scenes/msaa_scissor_viewport.json --softraster-deviations spec --no-chart -o "$artifacts/samples" \
  >"$artifacts/samples.txt" 2>&1
[ $? -eq 1 ] || fail "the MSAA report should fail in spec mode: $(cat "$artifacts/samples.txt")"
samples_page="file://$(cd "$artifacts/samples" && pwd)/index.html"
browse --dump-dom "$samples_page?check" >"$artifacts/samples-dom.html" || fail "chromium failed on the MSAA report"
body=$(grep -o '<body[^>]*>' "$artifacts/samples-dom.html" | head -n 1)
[ "$(attr data-check)" = done ] || fail "the MSAA report's self-check did not finish: '$(attr data-check)'"
[ "$(attr data-images-failed)" = 0 ] || fail "MSAA report images failed to load: $(attr data-images-failed-list)"
[ "$(attr data-sample-probe)" = "msaa_scissor_viewport/soft.sample3.png msaa_scissor_viewport/vulkan.sample3.png msaa_scissor_viewport/sample3.diff.png 3" ] ||
  fail "picking sample 3 showed '$(attr data-sample-probe)'"
browse --window-size=1400,2400 --screenshot="$artifacts/report-samples.png" "$samples_page#scene=msaa_scissor_viewport" >/dev/null ||
  fail "no MSAA screenshot"

browse --window-size=1400,1400 --screenshot="$artifacts/report-chart.png" "$page#chart" >/dev/null || fail "no chart screenshot"

browse --window-size=1400,1000 --screenshot="$artifacts/report.png" "$page" >/dev/null || fail "no screenshot"
browse --window-size=1400,3000 --screenshot="$artifacts/report-check.png" "$page?check" >/dev/null || fail "no screenshot"
[ -s "$artifacts/report.png" ] && [ -s "$artifacts/report-check.png" ] || fail "screenshots are empty"
echo "passed: $loaded images, $(attr data-pixels-loaded) pixel data files, $scenes rows; screenshots in $artifacts"
