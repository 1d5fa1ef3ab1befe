#!/usr/bin/env bash
# Hostile use of `crosscheck render` and `crosscheck compare`, one case per ctest test:
#   hostile_cli_test.sh CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR
# The exit statuses the README documents (0 within tolerance, 1 outside, 2 for anything that kept
# the comparison from happening) and one error line naming the file for each kind of mistake;
# nothing hangs (every run is under `timeout`). Exit 0: passed, 1: failed (with a message).
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
cli_case_begin hostile-cli "$@"

# run ARGS...: crosscheck with a 60 s limit; stdout to out.txt, stderr to err.txt, status to $status.
run() {
  timeout 60 "$crosscheck" "$@" >"$artifacts/out.txt" 2>"$artifacts/err.txt"
  status=$?
  [ "$status" -ne 124 ] || fail "crosscheck $* did not finish within 60 s"
}
# expect_error REGEX: exactly one line on stderr, matching REGEX; nothing on stdout.
expect_error() {
  [ "$(wc -l <"$artifacts/err.txt")" -eq 1 ] || fail "expected exactly one error line"
  grep -qE -- "$1" "$artifacts/err.txt" || fail "the error line does not match: $1"
  [ ! -s "$artifacts/out.txt" ] || fail "expected nothing on stdout"
}

room=scenes/room.json

case $case_name in
  exit_statuses)
    run compare tests/data/conformance/flat_triangle.json
    expect_status 0
    run compare tests/data/conformance/depth_slope.json --softraster-fma "$other_fma"
    expect_status 1
    run compare tests/data/no_such_scene.json
    expect_status 2
    expect_error '^crosscheck: tests/data/no_such_scene.json: cannot open scene file: file not found$'
    run compare tests/data/malformed_syntax.json
    expect_status 2
    expect_error '^crosscheck: tests/data/malformed_syntax.json: parse error'
    run compare "$room" --set framebuffer.width=4294967297
    expect_status 2
    expect_error '^crosscheck: scenes/room.json: /framebuffer/width: 4294967297 is more than 8192$'
    run compare "$room" --set nonsense
    expect_status 2
    expect_error '^crosscheck: scenes/room.json: --set nonsense: expected KEY.PATH=VALUE$'
    run compare "$room" --out /proc/no_such_folder
    expect_status 2
    expect_error 'no_such_folder'
    run render tests/data/malformed_obj.json --renderer soft -o "$artifacts/x.png"
    expect_status 2
    expect_error '^crosscheck: tests/data/malformed_obj.json: /draws/0/obj: .*malformed.obj'
    run render "$room" --renderer vulkan -o /proc/no_such_folder/x.png
    expect_status 2
    ;;
  not_regular_files)
    mkdir -p "$artifacts/folder.json"
    run compare "$artifacts/folder.json"
    expect_status 2
    expect_error 'folder.json: cannot open scene file: is a directory, not a file$'
    mkfifo "$artifacts/fifo.json"
    run render "$artifacts/fifo.json" --renderer soft -o "$artifacts/x.png"
    expect_status 2
    expect_error 'fifo.json: cannot open scene file: is not a regular file'
    ln -s loop2.json "$artifacts/loop1.json"
    ln -s loop1.json "$artifacts/loop2.json"
    run compare "$artifacts/loop1.json"
    expect_status 2
    expect_error 'loop1.json: cannot open scene file: cannot be read: Too many levels of symbolic links$'
    ;;
  bad_arguments)
    run frobnicate scenes/room.json
    expect_status 2
    grep -qE "^crosscheck: unknown subcommand 'frobnicate' \(expected render, compare, conformance, report, merge, bench, chart, stability or view\)$" \
      "$artifacts/err.txt" || fail "unknown subcommand not named"
    run render "$room" --renderer soft -o "$artifacts/x.png" --depth-out "$artifacts/d.png" --depth-range nan nan
    expect_status 2
    expect_error '^crosscheck: --depth-range nan nan: expected two finite numbers LO < HI$'
    run render "$room" --renderer soft -o "$artifacts/x.png" --depth-out "$artifacts/d.png" --depth-range 0.9 0.1
    expect_status 2
    run render "$room" --renderer soft -o "$artifacts/x.png" --depth-out "$artifacts/d.png" --depth-range 0.1 0.9
    expect_status 0
    ;;
  renderer_errors_name_the_file)
    # A state the loader accepts but softraster cannot draw (the course's 1/z depth buffer with
    # 4x MSAA): the renderer's error comes with the scene file in front.
    run render scenes/msaa_triangles.json --renderer soft --softraster-depth inverse-z -o "$artifacts/x.png"
    expect_status 2
    expect_error '^crosscheck: scenes/msaa_triangles.json: .*the 1/z depth buffer takes one sample per pixel'
    ;;
  vocabulary)
    # -o/--output on every subcommand that writes (--out and bench's --json still work); render
    # says which renderer drew the scene and what it wrote.
    run render "$room" --renderer soft --threads 1 -o "$artifacts/r.png" --depth-out "$artifacts/r.depth.png"
    expect_status 0
    grep -qxF "rendered $room with softraster (exact, 1 thread): wrote $artifacts/r.png and $artifacts/r.depth.png" \
      "$artifacts/out.txt" || fail "render did not say what it used and wrote"
    run render "$room" --renderer vulkan -o "$artifacts/v.png"
    expect_status 0
    grep -qE "^rendered $room with Vulkan \(.*llvmpipe.*\): wrote $artifacts/v.png$" "$artifacts/out.txt" || fail "render (vulkan)"
    run render --help
    grep -qE -- '--renderer .*=soft' "$artifacts/out.txt" || fail "render's usage does not show the default renderer"
    for option in -o --output --out; do
      rm -rf "$artifacts/c"
      run compare tests/data/conformance/flat_triangle.json "$option" "$artifacts/c"
      expect_status 0
      [ -s "$artifacts/c/soft.png" ] || fail "compare $option wrote no images"
      rm -rf "$artifacts/k"
      run conformance tests/data/conformance/flat_triangle.json "$option" "$artifacts/k"
      expect_status 0
      [ -s "$artifacts/k/flat_triangle/soft.png" ] || fail "conformance $option wrote no images"
    done
    # One spelling of each metric everywhere: Pass; |Δ|; "allowed" for counts; PSNR of identical
    # images "inf"; a depth threshold of 2^-24 as the scene files write it, 5.9604645e-08.
    run compare tests/data/conformance/flat_triangle.json
    expect_status 0
    for line in "tests/data/conformance/flat_triangle.json: Pass" "  coverage mismatches  0 (allowed 0)" \
                "  PSNR (RGB, dB)       inf" "  depth max |Δ|        0 (threshold 5.9604645e-08)"; do
      grep -qxF "$line" "$artifacts/out.txt" || fail "compare text lacks '$line'"
    done
    rm -rf "$artifacts/v"
    run report tests/data/conformance/flat_triangle.json --junit "$artifacts/v.xml" -o "$artifacts/v"
    expect_status 0
    grep -qxF "psnr: inf" "$artifacts/v.xml" || fail "JUnit PSNR is not 'inf'"
    grep -qF "depth_max_delta: 0 (threshold 5.9604645e-08)" "$artifacts/v.xml" || fail "JUnit depth threshold spelling"
    grep -qF ">inf</td>" "$artifacts/v/index.html" || fail "report PSNR is not 'inf'"
    grep -qF "threshold 5.9604645e-08" "$artifacts/v/index.html" || fail "report depth threshold spelling"
    if grep -qF -e '|d|' -e '(max ' -e $'\xE2\x88\x9E' -e 'PASS' "$artifacts/out.txt" "$artifacts/v.xml" "$artifacts/v/index.html"; then
      fail "an old spelling (|d|, (max N), ∞, PASS) is still written"
    fi
    ;;
  *)
    fail "unknown case $case_name"
    ;;
esac
echo "passed: $case_name"
