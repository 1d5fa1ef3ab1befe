#!/usr/bin/env bash
# Command-line tests of `crosscheck conformance` and `crosscheck report`, one case per ctest test:
#   conformance_cli_test.sh CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
# Each case runs the real binary on the fixtures in tests/data/ and checks its exit status and
# output. Exit 0: passed, 1: failed (with a message), 77: skipped (a tool it needs is missing).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
cli_case_begin conformance-cli "$@"

fixtures=tests/data/conformance
expectations=tests/data/expectations

# other_fma (cli_case.sh): with it, depth_slope's depths differ in the last bits and it fails for real.

# Scene names of a JUnit file, one a line, sorted.
junit_names() { xmllint --xpath '//testcase/@name' "$1" | grep -oE 'name="[^"]*"' | sed 's/^name="//; s/"$//' | sort; }
xpath_number() { xmllint --xpath "string($2)" "$1"; }
need() { command -v "$1" >/dev/null || { echo "SKIPPED: $1 is not installed"; exit 77; }; }

case $case_name in
  statuses)
    # Pass, Fail and Crash (malformed scene, malformed OBJ, missing file) in one run that goes on.
    run conformance "$fixtures" tests/data/no_such_scene.json --softraster-fma "$other_fma"
    expect_status 1
    expect_out '^Fail +depth_slope: (.*; )?depth_pixels_over [0-9]+ > 0 \(depth max \|Δ\| [0-9.e+-]+, threshold 0\)'
    expect_out '^Pass +flat_triangle  \(soft [0-9.]+ ms, vulkan [0-9.]+ ms\)$'
    expect_out '^Crash +malformed: tests/data/conformance/malformed.json: parse error at line 3'
    expect_out "^Crash +broken_obj: tests/data/conformance/broken_obj.json: /draws/0/obj: .*malformed.obj:3: face corner '7': position index 7 refers to no position"
    expect_out '^Crash +no_such_scene: tests/data/no_such_scene.json: cannot open scene file: file not found$'
    expect_out '^Failures \(4\):$'
    expect_out '^Slowest scenes:$'
    expect_last_line "1 passed, 4 failed"
    ;;
  expectations)
    # Every failure known: ExpectedFail for Fail and Crash, Skip not run; exit 0.
    run conformance "$fixtures" --softraster-fma "$other_fma" --expectations "$expectations/all_known.txt"
    expect_status 0
    expect_out '^ExpectedFail +depth_slope: (.*; )?depth_pixels_over [0-9]+ > 0 .*\[depths differ in the last bits'
    expect_out '^ExpectedFail +malformed: .*parse error'
    expect_out '^ExpectedFail +broken_obj: '
    expect_out '^Skip +flat_triangle: skipped by expectations \[exercises Skip\]$'
    expect_out '^Expected failures and skips \(4\):$'
    expect_last_line "3 passed, 0 failed, 1 skipped"
    ;;
  unexpected_pass)
    run conformance "$fixtures/depth_slope.json" "$fixtures/flat_triangle.json" --expectations "$expectations/unexpected_pass.txt"
    expect_status 1
    expect_out '^UnexpectedPass +depth_slope: expected Fail \(line 3\), but passed \[only fails with the other fmuladd rounding\]'
    expect_last_line "1 passed, 1 failed"
    ;;
  unknown_scene_in_expectations)
    run conformance "$fixtures/flat_triangle.json" --expectations "$expectations/unknown_scene.txt"
    expect_status 0
    expect_err "^crosscheck: warning: $expectations/unknown_scene.txt:3: no scene named 'no_such_scene' in this suite$"
    expect_last_line "0 passed, 0 failed, 1 skipped"
    ;;
  bad_usage)
    # Each: exit 2 and one clear error line naming the file or option.
    check_usage() {
      local pattern=$1
      shift
      run "$@"
      expect_status 2
      expect_err "$pattern"
    }
    check_usage '--jobs' conformance --jobs 0 "$fixtures"
    check_usage '^crosscheck: --shard 0/3: needs 1 <= I <= N' conformance --shard 0/3 "$fixtures"
    check_usage '^crosscheck: --shard 4/3: needs 1 <= I <= N' conformance --shard 4/3 "$fixtures"
    check_usage '^crosscheck: --shard a/b: expected I/N' conformance --shard a/b "$fixtures"
    check_usage '^crosscheck: --chart-frames 0: expected a whole number from 1 to 1000$' report --chart-frames 0 -o "$artifacts/r" "$fixtures"
    check_usage '^crosscheck: --chart-frames x: expected a whole number from 1 to 1000$' report --chart-frames x -o "$artifacts/r" "$fixtures"
    check_usage '^crosscheck: --shard 2: expected I/N' conformance --shard 2 "$fixtures"
    check_usage "^crosscheck: $expectations/missing.txt: cannot read expectations file: file not found$" \
      conformance --expectations "$expectations/missing.txt" "$fixtures"
    expect_one_error_line
    check_usage "^crosscheck: $expectations: cannot read expectations file: is a directory, not a file$" \
      conformance --expectations "$expectations" "$fixtures"
    check_usage "^crosscheck: $expectations/malformed_line.txt:4: expected 'SCENE,STATUS # reason', got 'depth_slope Fail'$" \
      conformance --expectations "$expectations/malformed_line.txt" "$fixtures"
    expect_one_error_line
    check_usage "^crosscheck: $expectations/bad_status.txt:2: 'ExpectedFail' is not one of Pass, Fail, Crash, Timeout, Skip$" \
      conformance --expectations "$expectations/bad_status.txt" "$fixtures"
    mkdir -p "$artifacts/empty"
    check_usage "^crosscheck: $artifacts/empty: no \*.json scene files in this directory$" conformance "$artifacts/empty"
    check_usage "^crosscheck: scenez/: no such file or directory$" conformance scenez/
    touch "$artifacts/a_file"
    check_usage "^crosscheck: $artifacts/a_file/out: cannot create output directory" \
      conformance --out "$artifacts/a_file/out" "$fixtures/flat_triangle.json"
    expect_one_error_line
    check_usage "^crosscheck: $artifacts/a_file/report: cannot create output directory" \
      report -o "$artifacts/a_file/report" "$fixtures/flat_triangle.json"
    check_usage "^crosscheck: $artifacts/a_file/x.xml: cannot write this file$" \
      conformance --junit "$artifacts/a_file/x.xml" "$fixtures/flat_triangle.json"
    check_usage 'usage: crosscheck' report "$fixtures"   # -o is required
    mkdir -p "$artifacts/one" "$artifacts/two"
    cp "$fixtures/flat_triangle.json" "$artifacts/one/same.json"
    cp "$fixtures/flat_triangle.json" "$artifacts/two/same.json"
    check_usage "scene name 'same' is already used by" conformance "$artifacts/one" "$artifacts/two"
    # No argument and no scenes/ here: the default suite cannot be found.
    (cd "$artifacts" && "$crosscheck" conformance >out.txt 2>err.txt; echo $? >status.txt)
    [ "$(cat "$artifacts/status.txt")" -eq 2 ] || fail "default suite outside the repository: exit status not 2"
    expect_err '^crosscheck: scenes: no such directory \(run crosscheck from the repository root'
    ;;
  timeout)
    # A scene past --timeout is Timeout (counted as failed, <error type="Timeout"> in JUnit); the
    # worker is killed and the next scene still runs. 1 ms is less than opening a worker's
    # renderers, which counts against its first scene.
    need xmllint
    run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json" --timeout 0.001 --junit "$artifacts/run.xml"
    expect_status 1
    expect_out '^Timeout +depth_slope: no result within 0.001 s; worker killed \(--timeout\)$'
    expect_out '^Timeout +flat_triangle: no result within 0.001 s; worker killed \(--timeout\)$'
    expect_out '^Failures \(2\):$'
    expect_last_line "0 passed, 2 failed"
    [ "$(xpath_number "$artifacts/run.xml" 'count(//testcase/error[@type="Timeout"])')" = 2 ] || fail "not 2 <error type=Timeout>"
    [ "$(xpath_number "$artifacts/run.xml" '/testsuites/testsuite/@errors')" = 2 ] || fail "errors != 2"
    # Known: ExpectedFail, exit 0.
    printf 'flat_triangle,Timeout # hangs\ndepth_slope,Timeout # hangs\n' >"$artifacts/known.txt"
    run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json" --timeout 0.001 --expectations "$artifacts/known.txt"
    expect_status 0
    expect_out '^ExpectedFail +flat_triangle: no result within 0.001 s; worker killed \(--timeout\) \[hangs\]$'
    expect_last_line "2 passed, 0 failed"
    # A generous timeout and no memory limit change nothing.
    run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json" --timeout 600 --memory-limit 0 --jobs 2
    expect_status 0
    expect_last_line "2 passed, 0 failed"
    ;;
  bad_limits)
    # Bad --timeout and --memory-limit values: exit 2, one error line naming the option.
    for value in -1 abc nan inf 1e9 ''; do
      run conformance --timeout "$value" "$fixtures/flat_triangle.json"
      expect_status 2
      expect_err "^crosscheck: --timeout $value: expected a number of seconds from 0 \(none\) to 604800$"
      expect_one_error_line
    done
    for value in -5 x 1.5 99999999999; do
      run report -o "$artifacts/report" --memory-limit "$value" "$fixtures/flat_triangle.json"
      expect_status 2
      expect_err "^crosscheck: --memory-limit $value: expected a whole number from 0 to 67108864$"
      expect_one_error_line
    done
    ;;
  default_suite)
    # No argument: every scene in scenes/ and scenes/stability/ of the current directory, all passing.
    run conformance --jobs 2
    expect_status 0
    expected=$(ls scenes/*.json scenes/stability/*.json | wc -l)
    expect_out "^crosscheck conformance: $expected scenes, 2 jobs$"
    expect_last_line "$expected passed, 0 failed"
    ;;
  jobs_stable_order)
    # --jobs 1 and --jobs 3 give the same lines in the same order (timings aside).
    suite=(scenes "$fixtures" tests/data)
    run conformance "${suite[@]}" --jobs 1
    sed -E 's/  \(soft .*\)$//' "$artifacts/out.txt" | grep -vE '^(crosscheck conformance|ran |  )' >"$artifacts/jobs1.txt"
    run conformance "${suite[@]}" --jobs 3
    sed -E 's/  \(soft .*\)$//' "$artifacts/out.txt" | grep -vE '^(crosscheck conformance|ran |  )' >"$artifacts/jobs3.txt"
    diff "$artifacts/jobs1.txt" "$artifacts/jobs3.txt" || fail "--jobs 3 printed other results or another order than --jobs 1"
    [ "$(grep -cE '^(Pass|Crash) ' "$artifacts/jobs1.txt")" -ge 10 ] || fail "expected at least 10 scenes in the suite"
    ;;
  set_over_suite)
    # --set applies to every scene of the suite (the images have the overridden width), is named
    # in the run's header and in the report's reproduce command; a malformed --set is one error
    # line before anything runs (exit 2); a key no scene has makes each scene Crash naming it.
    two=("$fixtures/flat_triangle.json" "$fixtures/depth_slope.json")
    run conformance "${two[@]}" --set framebuffer.width=7 -o "$artifacts/set"
    expect_status 0
    expect_out '^  --set framebuffer.width=7 in every scene$'
    for scene in flat_triangle depth_slope; do
      width=$(od -An -tu1 -j16 -N4 "$artifacts/set/$scene/soft.png" | awk '{print $1*16777216 + $2*65536 + $3*256 + $4}')
      [ "$width" = 7 ] || fail "$scene was rendered $width pixels wide, not 7"
    done
    run report "${two[@]}" --set framebuffer.width=7 -o "$artifacts/report"
    expect_status 0
    grep -qF "crosscheck compare $fixtures/depth_slope.json --set framebuffer.width=7" "$artifacts/report/index.html" ||
      fail "the report's reproduce command lacks the --set"
    run conformance "${two[@]}" --set =3
    expect_status 2
    expect_one_error_line
    expect_err '^crosscheck: --set =3: expected KEY.PATH=VALUE$'
    run conformance "${two[@]}" --set no_such_key=1
    expect_status 1
    [ "$(grep -cE '^Crash +(flat_triangle|depth_slope): .*no_such_key.*unknown field' "$artifacts/out.txt")" = 2 ] ||
      fail "an unknown key did not make both scenes Crash naming it"
    ;;
  jobs_past_suite)
    # More jobs than scenes: the run says how many ran, and why.
    run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json" --jobs 8
    expect_status 0
    expect_out '^crosscheck conformance: 2 scenes, 2 jobs \(--jobs 8: no more jobs than scenes to run\)$'
    expect_out '^ran 2 scenes in [0-9.]+ s with 2 jobs$'
    ;;
  sharding)
    # For N in 1..3 the shards' union is the whole suite and no scene runs twice. The suite is
    # the fixtures (passing, failing and crashing scenes): the property does not depend on which
    # scenes, and seven runs of scenes/ took over two minutes in the sanitizer job
    # (default_suite and jobs_stable_order run scenes/ whole).
    need xmllint
    suite=("$fixtures" tests/data)
    run conformance "${suite[@]}" --junit "$artifacts/all.xml"
    junit_names "$artifacts/all.xml" >"$artifacts/all.txt"
    total=$(wc -l <"$artifacts/all.txt")
    [ "$total" -ge 10 ] || fail "expected at least 10 scenes, got $total"
    for n in 1 2 3; do
      : >"$artifacts/union.txt"
      for i in $(seq 1 "$n"); do
        run conformance "${suite[@]}" --shard "$i/$n" --junit "$artifacts/shard$i-of-$n.xml"
        if [ "$n" -gt 1 ]; then expect_out "\\(shard $i/$n of $total\\)"; fi
        junit_names "$artifacts/shard$i-of-$n.xml" >>"$artifacts/union.txt"
        size=$(junit_names "$artifacts/shard$i-of-$n.xml" | wc -l)
        [ "$size" -ge $((total / n)) ] && [ "$size" -le $(((total + n - 1) / n)) ] || fail "shard $i/$n has $size of $total scenes"
      done
      [ -z "$(sort "$artifacts/union.txt" | uniq -d)" ] || fail "with $n shards a scene ran twice: $(sort "$artifacts/union.txt" | uniq -d)"
      sort "$artifacts/union.txt" | diff - "$artifacts/all.txt" || fail "the union of $n shards is not the whole suite"
    done
    # Test identity does not depend on the shard: one suite name and classname everywhere, the
    # shard a property.
    for xml in "$artifacts"/shard*-of-3.xml "$artifacts/all.xml"; do
      [ "$(xmllint --xpath 'string(/testsuites/testsuite/@name)' "$xml")" = crosscheck.conformance ] || fail "$xml: suite name"
      [ "$(xpath_number "$xml" 'count(//testcase[@classname!="crosscheck.conformance"])')" = 0 ] || fail "$xml: a classname differs"
    done
    [ "$(xmllint --xpath 'string(//property[@name="shard"]/@value)' "$artifacts/shard2-of-3.xml")" = 2/3 ] || fail "no shard property"
    [ "$(xpath_number "$artifacts/all.xml" 'count(//property)')" = 0 ] || fail "an unsharded run has a shard property"
    ;;
  results_json)
    # conformance -o DIR and report -o DIR write DIR/results.json: every scene, paths relative to DIR.
    run conformance "$fixtures" tests/data/bad_enum.json --softraster-fma "$other_fma" \
      --expectations "$expectations/unknown_scene.txt" --junit "$artifacts/run.xml" --out "$artifacts/images"
    expect_status 1
    expect_out "^results: $artifacts/images/results.json$"
    file=$artifacts/images/results.json
    [ -s "$file" ] || fail "no results.json"
    grep -qx ' "format": 1,' "$file" || fail "no format version"
    grep -qx ' "junit_file": "../run.xml",' "$file" || fail "the JUnit path is not relative to the folder"
    [ "$(grep -c '"image_root": "."' "$file")" = 1 ] || fail "not one scene (depth_slope) with images in this folder"
    [ "$(grep -c '"step_milliseconds": {' "$file")" = 5 ] || fail "not five scenes with their step timings"
    [ "$(grep -c '"outcome": "Crash"' "$file")" = 3 ] || fail "not three crashes"
    grep -q '"outcome": "Skip"' "$file" || fail "no skipped scene"
    grep -q '"file": "depth_slope/diff.png"' "$file" || fail "image paths are not relative to the image root"
    grep -q '"error": "tests/data/bad_enum.json: ' "$file" || fail "no error line"
    run report "$fixtures/flat_triangle.json" -o "$artifacts/report"
    expect_status 0
    grep -q '"file": "flat_triangle/preview.png"' "$artifacts/report/results.json" || fail "report wrote no results.json"
    # A results.json that cannot be written is an error naming it, exit 2.
    mkdir -p "$artifacts/blocked/results.json"
    run conformance "$fixtures/flat_triangle.json" -o "$artifacts/blocked"
    expect_status 2
    expect_err "^crosscheck: $artifacts/blocked/results.json: cannot write results file: "
    ;;
  slowest_steps)
    # The slowest scenes say where their time went.
    run conformance "$fixtures/flat_triangle.json" "$fixtures/malformed.json" -o "$artifacts/images"
    expect_status 1
    expect_out '^  flat_triangle +[0-9.]+ ms: load [0-9.]+, softraster [0-9.]+ \(draw [0-9.]+\), vulkan [0-9.]+ \(submit [0-9.]+\), compare [0-9.]+, images [0-9.]+$'
    expect_out '^  malformed +[0-9.]+ ms: load [0-9.]+, softraster 0.00, vulkan 0.00, compare 0.00, images 0.00$'
    ;;
  bad_baseline)
    # report --baseline DIR that holds no readable results.json: one error line naming the file,
    # exit 2, before any scene runs.
    run report "$fixtures/flat_triangle.json" --baseline "$artifacts/none" -o "$artifacts/r1"
    expect_status 2
    expect_one_error_line
    expect_err "^crosscheck: --baseline: $artifacts/none: cannot read results file: file not found$"
    mkdir -p "$artifacts/broken"
    echo '{"format": 1, "scenes": [' >"$artifacts/broken/results.json"
    run report "$fixtures/flat_triangle.json" --baseline "$artifacts/broken" -o "$artifacts/r2"
    expect_status 2
    expect_one_error_line
    expect_err "^crosscheck: --baseline: $artifacts/broken/results.json: "
    ;;
  merge_errors)
    # merge: one error line naming the file and the scene, exit 2, for shards that do not make up
    # one suite; the merged outputs otherwise (exit status as conformance), usable without the shards.
    for i in 1 2 3; do
      run conformance "$fixtures" --shard "$i/3" -o "$artifacts/s$i"
      run conformance "$fixtures" --shard "$i/3" -o "$artifacts/known$i" --softraster-fma "$other_fma" \
        --expectations "$expectations/all_known.txt"
      expect_status 0
    done
    check_merge() {
      local pattern=$1
      shift
      run merge "$@"
      expect_status 2
      expect_err "$pattern"
      expect_one_error_line
    }
    s=$artifacts/s
    check_merge "^crosscheck: ${s}1/results.json: scene 'flat_triangle' of the suite is in none of the 2 files \(missing\)$" \
      "${s}1" "${s}2/results.json" -o "$artifacts/m"
    check_merge "^crosscheck: ${s}2/results.json: scene 'depth_slope' is also in ${s}2/results.json \(duplicated\)$" \
      "${s}1" "${s}2" "${s}3" "${s}2" -o "$artifacts/m"
    run conformance "$fixtures/flat_triangle.json" -o "$artifacts/other"
    check_merge "^crosscheck: $artifacts/other/results.json: another suite than ${s}1/results.json: 1 scene, not 4$" \
      "${s}1" "$artifacts/other" -o "$artifacts/m"
    check_merge "^crosscheck: $artifacts/known3/results.json: other rendering options than ${s}1/results.json: '--softraster-fma $other_fma', not ''$" \
      "${s}1" "${s}2" "$artifacts/known3" -o "$artifacts/m"
    # The same options but another expectations file: a scene could be expected to fail in one shard only.
    run conformance "$fixtures" --shard 2/3 -o "$artifacts/expected2" --expectations "$expectations/all_known.txt"
    check_merge "^crosscheck: $artifacts/expected2/results.json: other expectations than ${s}1/results.json: applied '$expectations/all_known.txt', not none$" \
      "${s}1" "$artifacts/expected2" "${s}3" -o "$artifacts/m"
    check_merge "^crosscheck: $artifacts/nothing.json: cannot read results file: file not found$" "$artifacts/nothing.json" -o "$artifacts/m"
    check_merge "^crosscheck: $expectations/report.txt: not JSON: " "$expectations/report.txt" -o "$artifacts/m"
    sed 's/^ "format": 1,$/ "format": 7,/' "${s}1/results.json" >"$artifacts/format7.json"
    check_merge "^crosscheck: $artifacts/format7.json: results JSON: /format: version 7, but this crosscheck reads version 1$" \
      "$artifacts/format7.json" "${s}2" "${s}3" -o "$artifacts/m"
    run merge "${s}1"
    expect_status 2
    expect_err 'usage: crosscheck'
    [ ! -e "$artifacts/m" ] || fail "a failed merge wrote $artifacts/m"
    # Two crashes (broken_obj, malformed): exit 1, the outputs, and the images copied.
    run merge "${s}3" "${s}1" "${s}2" -o "$artifacts/m"
    expect_status 1
    expect_out '^crosscheck merge: 4 scenes from 3 files$'
    expect_out "^report: $artifacts/m/index.html$"
    expect_last_line "2 passed, 2 failed"
    rm -rf "${s}1" "${s}2" "${s}3"
    for f in index.html junit.xml results.json depth_slope/diff.png flat_triangle/vulkan.depth.png; do
      [ -s "$artifacts/m/$f" ] || fail "merge wrote no $f"
    done
    grep -q "image diff: $artifacts/m/depth_slope/diff.png" "$artifacts/m/junit.xml" || fail "JUnit does not name the copied images"
    # Every failure known: exit 0, and --junit puts JUnit elsewhere.
    run merge "$artifacts/known1" "$artifacts/known2" "$artifacts/known3" -o "$artifacts/mk" --junit "$artifacts/mk.xml"
    expect_status 0
    expect_last_line "3 passed, 0 failed, 1 skipped"
    [ -s "$artifacts/mk.xml" ] && [ ! -e "$artifacts/mk/junit.xml" ] || fail "--junit did not move the JUnit file"
    ;;
  junit)
    # Well-formed JUnit with the right counts; Fail/UnexpectedPass as <failure>, Crash as <error>,
    # Skip and ExpectedFail as <skipped>, metrics and image paths in <system-out>.
    need xmllint
    run conformance "$fixtures" tests/data/bad_enum.json --softraster-fma "$other_fma" \
      --expectations "$expectations/unknown_scene.txt" --junit "$artifacts/run.xml" --out "$artifacts/images"
    expect_status 1
    xmllint --noout "$artifacts/run.xml" || fail "JUnit file is not well-formed XML"
    [ "$(xpath_number "$artifacts/run.xml" '/testsuites/testsuite/@tests')" = 5 ] || fail "tests != 5"
    [ "$(xpath_number "$artifacts/run.xml" '/testsuites/testsuite/@failures')" = 1 ] || fail "failures != 1"
    [ "$(xpath_number "$artifacts/run.xml" '/testsuites/testsuite/@errors')" = 3 ] || fail "errors != 3"
    [ "$(xpath_number "$artifacts/run.xml" '/testsuites/testsuite/@skipped')" = 1 ] || fail "skipped != 1"
    [ "$(xpath_number "$artifacts/run.xml" 'count(//testcase)')" = 5 ] || fail "not 5 testcases"
    [ "$(xpath_number "$artifacts/run.xml" 'count(//testcase[@name="depth_slope"]/failure[@type="Fail"])')" = 1 ] || fail "depth_slope has no <failure>"
    [ "$(xpath_number "$artifacts/run.xml" 'count(//testcase/error[@type="Crash"])')" = 3 ] || fail "not 3 <error>"
    [ "$(xpath_number "$artifacts/run.xml" 'count(//testcase[@name="flat_triangle"]/skipped)')" = 1 ] || fail "flat_triangle not <skipped>"
    xpath_number "$artifacts/run.xml" '//testcase[@name="depth_slope"]/system-out' >"$artifacts/depth_slope.out"
    grep -qE '^depth_pixels_over: [0-9]+ \(allowed 0\)$' "$artifacts/depth_slope.out" || fail "no metrics in <system-out>"
    grep -qE "^image diff: $artifacts/images/depth_slope/diff.png$" "$artifacts/depth_slope.out" || fail "no image path in <system-out>"
    [ -s "$artifacts/images/depth_slope/diff.png" ] || fail "--out wrote no diff.png"
    time=$(xpath_number "$artifacts/run.xml" '//testcase[@name="depth_slope"]/@time')
    [[ "$time" =~ ^[0-9]+\.[0-9]{3}$ ]] && awk -v t="$time" 'BEGIN { exit !(t > 0 && t < 60) }' || fail "time '$time' is not in seconds"
    # Expected failures are <skipped> too.
    run conformance "$fixtures" --softraster-fma "$other_fma" --expectations "$expectations/all_known.txt" --junit "$artifacts/known.xml"
    expect_status 0
    xmllint --noout "$artifacts/known.xml" || fail "JUnit file is not well-formed XML"
    [ "$(xpath_number "$artifacts/known.xml" '/testsuites/testsuite/@skipped')" = 4 ] || fail "known: skipped != 4"
    [ "$(xpath_number "$artifacts/known.xml" '/testsuites/testsuite/@failures')" = 0 ] || fail "known: failures != 0"
    [ "$(xpath_number "$artifacts/known.xml" '/testsuites/testsuite/@errors')" = 0 ] || fail "known: errors != 0"
    xpath_number "$artifacts/known.xml" '//testcase[@name="depth_slope"]/skipped/@message' | grep -qE '^expected failure: (.*; )?depth_pixels_over' ||
      fail "ExpectedFail's <skipped> has no message"
    ;;
  progress)
    # The progress line goes to a terminal only.
    need script
    script -qefc "'$crosscheck' conformance $fixtures/flat_triangle.json $fixtures/depth_slope.json" "$artifacts/tty.txt" >/dev/null
    grep -qE $'\r\\[1/2\\] failures: 0 elapsed: [0-9]+\\.[0-9]s' "$artifacts/tty.txt" || fail "no progress line on a terminal"
    grep -qE $'\r\\[2/2\\] failures: 0 elapsed: ' "$artifacts/tty.txt" || fail "no final progress line on a terminal"
    # The last line before script(1)'s own trailer.
    grep -av '^Script ' "$artifacts/tty.txt" | tr -d '\r' | sed '/^$/d' | tail -n 1 | grep -qx "2 passed, 0 failed" ||
      fail "last line on a terminal is not the counts"
    run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json"
    expect_status 0
    ! grep -q 'elapsed:' "$artifacts/err.txt" "$artifacts/out.txt" || fail "progress line printed when not on a terminal"
    ;;
  no_vulkan_driver)
    # Without a driver every scene is a Crash with the one-line error; the run still ends.
    VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json \
      run conformance "$fixtures/flat_triangle.json" "$fixtures/depth_slope.json"
    expect_status 1
    expect_out '^Crash +flat_triangle: vulkan: no Vulkan driver found'
    expect_out '^Crash +depth_slope: vulkan: no Vulkan driver found'
    expect_last_line "0 passed, 2 failed"
    ;;
  *)
    echo "unknown case $case_name"
    exit 1
    ;;
esac
echo "passed: $case_name"
