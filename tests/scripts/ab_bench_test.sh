#!/usr/bin/env bash
# scripts/ab_bench.sh: its failure paths, each one line on stderr naming the problem (wrong
# arguments, bad ROUNDS or REPS, a binary that is not there or is a directory, a filter that
# selects nothing or not the same benchmarks in both builds: exit 2; a build whose run fails:
# exit 1; a summary file that is missing or holds no rounds: exit 2), the paired summary's
# arithmetic on a saved output with known times (--summary), and one short run of the real
# softraster_benchmarks against itself: a line per binary per round, with one time per selected
# benchmark, and a summary line per benchmark. Times nothing: the measured numbers are only
# checked to be numbers.
#   ab_bench_test.sh SOURCE_DIR SOFTRASTER_BENCHMARKS
set -uo pipefail
source_dir=$1
benchmarks=$2
script="$source_dir/scripts/ab_bench.sh"
source "$(dirname "${BASH_SOURCE[0]}")/script_case.sh"

expect_error "no arguments" 2 "^usage: ab_bench.sh BINARY_A BINARY_B FILTER \\| ab_bench.sh --summary FILE$"
expect_error "two arguments" 2 "^usage:" "$benchmarks" "$benchmarks"
expect_error "missing binary" 2 "^ab_bench: /nonexistent/softraster_benchmarks: not an executable file$" \
  "$benchmarks" /nonexistent/softraster_benchmarks '^FullScreenQuad/threads:1/'
ROUNDS=0 expect_error "zero rounds" 2 "^ab_bench: ROUNDS \\(0\\) and REPS \\(3\\) must be positive whole numbers$" "$benchmarks" "$benchmarks" x
REPS=two expect_error "reps not a number" 2 "^ab_bench: ROUNDS \\(4\\) and REPS \\(two\\)" "$benchmarks" "$benchmarks" x
expect_error "a directory" 2 "^ab_bench: /tmp: not an executable file$" "$benchmarks" /tmp x
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A build that lists the same benchmarks but fails when run, and one that lists none of them.
printf '#!/usr/bin/env bash\ncase "$*" in *--benchmark_list_tests*) exec "%s" "$@" ;; esac\nexit 3\n' "$benchmarks" >"$scratch/failing"
printf '#!/usr/bin/env bash\nexit 0\n' >"$scratch/empty"
chmod +x "$scratch/failing" "$scratch/empty"
expect_error "different benchmarks" 2 "^ab_bench: .* and $scratch/empty do not select the same benchmarks with 'FullScreenQuad/threads:1/'$" \
  "$benchmarks" "$scratch/empty" 'FullScreenQuad/threads:1/'
err=$(ROUNDS=1 REPS=1 bash "$script" "$benchmarks" "$scratch/failing" '^FullScreenQuad/threads:1/' 2>&1 >/dev/null)
rc=$?
[ "$rc" -eq 1 ] || fail "failing run: exit $rc, expected 1"
[ "$err" = "ab_bench: binary B ($scratch/failing) failed in round 1" ] || fail "failing run: stderr '$err'"
expect_error "no match" 2 "^ab_bench: no benchmark matches 'NoSuchBenchmark'$" "$benchmarks" "$benchmarks" NoSuchBenchmark
expect_error "summary of a missing file" 2 "^ab_bench: /nonexistent/ab.txt: not a readable file$" --summary /nonexistent/ab.txt
printf 'benchmarks (columns: ...):\n  X/threads:1\n' >"$scratch/no_rounds.txt"
expect_error "summary without rounds" 2 "^ab_bench: $scratch/no_rounds.txt: no rounds to summarize$" --summary "$scratch/no_rounds.txt"

# Known times: X's B/A by round 0.5, 1.0, 1.2; Y's 1.5, 0.5, 1.0 (B faster only where below 1).
cat >"$scratch/saved.txt" <<'SAVED'
benchmarks (columns: real-time medians, in each benchmark's unit, ms for all of ours):
  X/threads:1/process_time/real_time
  Y/threads:2/process_time/real_time
round 1 A: 10 2 
round 1 B: 5 3 
round 2 A: 20 4 
round 2 B: 20 2 
round 3 A: 10 4 
round 3 B: 12 4 
SAVED
expected='paired summary (B/A round by round; below 1: B faster):
  X/threads:1/process_time/real_time: A 10, B 12 (medians of 3 rounds); B/A 1.00 (0.50-1.20), B faster in 1 of 3
  Y/threads:2/process_time/real_time: A 4, B 3 (medians of 3 rounds); B/A 1.00 (0.50-1.50), B faster in 1 of 3'
summary=$(bash "$script" --summary "$scratch/saved.txt" 2>&1)
rc=$?
[ "$rc" -eq 0 ] || fail "summary: exit $rc: $summary"
[ "$summary" = "$expected" ] || fail "summary of known times: got
$summary"

out=$(ROUNDS=2 REPS=1 bash "$script" "$benchmarks" "$benchmarks" '^(FullScreenQuad|SmallTrianglesOneDraw)/threads:1/' 2>&1)
rc=$?
[ "$rc" -eq 0 ] || fail "run: exit $rc: $out"
for round in 1 2; do
  for side in A B; do
    line=$(grep -E "^round $round $side: " <<<"$out")
    [[ "$line" =~ ^round\ $round\ $side:\ [0-9.e+-]+\ [0-9.e+-]+\ $ ]] || fail "run: round $round $side: '$line'"
  done
done
[ "$(grep -c '^round ' <<<"$out")" -eq 4 ] || fail "run: not four round lines: $out"
grep -q '^  FullScreenQuad/threads:1/' <<<"$out" || fail "run: the benchmarks are not listed: $out"
for name in FullScreenQuad SmallTrianglesOneDraw; do
  grep -qE "^  $name/threads:1/[^ ]*: A [0-9.e+-]+, B [0-9.e+-]+ \(medians of 2 rounds\); B/A [0-9.]+ \([0-9.]+-[0-9.]+\), B faster in [0-2] of 2$" <<<"$out" ||
    fail "run: no summary line for $name: $out"
done

finish ab_bench
