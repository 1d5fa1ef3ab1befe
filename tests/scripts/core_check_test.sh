#!/usr/bin/env bash
# scripts/core_check.sh: its failure paths, each one line on stderr naming the problem (wrong
# arguments, bad ROUNDS or MIN_TIME, a binary that is not there, a filter that selects none or
# several benchmarks: exit 2; a build whose run fails: exit 1), and one short run of the real
# softraster_benchmarks: a line of times per CPU this process may use, the run all at once, and
# the two ratios. Times nothing: the numbers are only checked to be numbers.
#   core_check_test.sh SOURCE_DIR SOFTRASTER_BENCHMARKS
set -uo pipefail
source_dir=$1
benchmarks=$2
script="$source_dir/scripts/core_check.sh"
source "$(dirname "${BASH_SOURCE[0]}")/script_case.sh"

quick='^FullScreenQuad/threads:1/'
expect_error "no arguments" 2 "^usage: core_check.sh SOFTRASTER_BENCHMARKS \\[FILTER\\]$"
expect_error "three arguments" 2 "^usage:" "$benchmarks" x y
expect_error "missing binary" 2 "^core_check: /nonexistent/softraster_benchmarks: not an executable file$" /nonexistent/softraster_benchmarks
expect_error "a directory" 2 "^core_check: /tmp: not an executable file$" /tmp
ROUNDS=0 expect_error "zero rounds" 2 "^core_check: ROUNDS \\(0\\) must be a positive whole number and MIN_TIME \\(1\\) a number of seconds$" "$benchmarks"
MIN_TIME=soon expect_error "min time not a number" 2 "^core_check: ROUNDS \\(3\\) .* MIN_TIME \\(soon\\)" "$benchmarks"
expect_error "no match" 2 "^core_check: 'NoSuchBenchmark' selects 0 benchmarks, not one$" "$benchmarks" NoSuchBenchmark
expect_error "several" 2 "^core_check: '\\^FullScreenQuad/' selects [2-9][0-9]* benchmarks, not one$" "$benchmarks" '^FullScreenQuad/'
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# A build that lists the benchmark but fails when run.
printf '#!/usr/bin/env bash\ncase "$*" in *--benchmark_list_tests*) exec "%s" "$@" ;; esac\nexit 3\n' "$benchmarks" >"$scratch/failing"
chmod +x "$scratch/failing"
ROUNDS=1 expect_error "failing run" 1 "^core_check: the benchmark failed on CPU [0-9]+$" "$scratch/failing" "$quick"

out=$(ROUNDS=2 MIN_TIME=0.01 bash "$script" "$benchmarks" "$quick" 2>&1)
rc=$?
[ "$rc" -eq 0 ] || fail "run: exit $rc: $out"
number='[0-9.e+-]+'
[[ "$(head -n 1 <<<"$out")" =~ ^FullScreenQuad/threads:1/.*,\ pinned,\ ms:$ ]] || fail "run: first line: $out"
[ "$(grep -cE "^  CPU [0-9]+ alone: $number $number$" <<<"$out")" -ge 1 ] || fail "run: no CPU lines: $out"
grep -qE "^  all at once:( CPU [0-9]+ $number)+$" <<<"$out" || fail "run: no line all at once: $out"
grep -qE "^slowest CPU's median over the fastest's, alone: $number \\($number to $number ms\\)$" <<<"$out" || fail "run: no ratio alone: $out"
grep -qE "^all at once, the slowest CPU over the fastest's median alone: $number$" <<<"$out" || fail "run: no ratio all at once: $out"
# One line per CPU this process may use (nproc counts the affinity list, as the script reads it).
[ "$(grep -c '^  CPU ' <<<"$out")" -eq "$(nproc)" ] || fail "run: not one line per CPU ($(nproc)): $out"

finish core_check
