#!/usr/bin/env bash
# Compares two builds of softraster_benchmarks (A and B) on this noisy, shared host: copies each
# binary to a fresh file first, then runs them in alternating rounds (A, B, A, B, ...), each
# round the medians of REPS repetitions of the benchmarks FILTER selects (with REPS=1, the one
# run's time), and prints one line per binary per round (real time in ms, in the order Google
# Benchmark runs them).
#   ROUNDS=4 REPS=3 bash scripts/ab_bench.sh A B 'regex'
# e.g. bash scripts/ab_bench.sh /tmp/old/softraster_benchmarks build/bin/softraster_benchmarks \
#        '^(SmallTrianglesInAPass|Sphere100kColdInAPass)/threads:2/'
# Why the copies: two byte-identical binaries (cmp found no difference) ran Sphere100kColdInAPass
# at 16-19 ms and at 9-11 ms, round after round, until the slow one's page-cache pages were
# dropped (posix_fadvise DONTNEED), after which it ran at 9.4 ms too: where a binary's pages lie
# can cost more than the change being measured. A fresh copy lands elsewhere; a difference that
# does not hold in every round is noise. Does not build anything, and judges nothing: read the rounds.
# Errors (one line on stderr): wrong arguments, a binary that is not an executable file, a filter
# that selects nothing or not the same benchmarks in both (exit 2); a run that fails (exit 1).
set -euo pipefail
if (($# != 3)); then
  echo "usage: ab_bench.sh BINARY_A BINARY_B FILTER" >&2
  exit 2
fi
rounds=${ROUNDS:-4}
reps=${REPS:-3}
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ && "$reps" =~ ^[1-9][0-9]*$ ]]; then
  echo "ab_bench: ROUNDS ($rounds) and REPS ($reps) must be positive whole numbers" >&2
  exit 2
fi
declare -A binaries=([A]=$1 [B]=$2)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for side in A B; do
  source_binary=${binaries[$side]}
  if [ ! -f "$source_binary" ] || [ ! -x "$source_binary" ]; then
    echo "ab_bench: $source_binary: not an executable file" >&2
    exit 2
  fi
  cp "$source_binary" "$scratch/$side"
done
filter=$3
names=$("$scratch/A" --benchmark_list_tests --benchmark_filter="$filter" 2>/dev/null || true)
if [ -z "$names" ]; then
  echo "ab_bench: no benchmark matches '$filter'" >&2
  exit 2
fi
if [ "$("$scratch/B" --benchmark_list_tests --benchmark_filter="$filter" 2>/dev/null || true)" != "$names" ]; then
  echo "ab_bench: ${binaries[A]} and ${binaries[B]} do not select the same benchmarks with '$filter'" >&2
  exit 2
fi
echo "benchmarks (columns: real-time medians, in each benchmark's unit, ms for all of ours):"
while IFS= read -r name; do echo "  $name"; done <<<"$names"
for ((round = 1; round <= rounds; ++round)); do
  for side in A B; do
    # With one repetition Google Benchmark reports the run itself and no aggregates.
    if ! csv=$("$scratch/$side" --benchmark_filter="$filter" --benchmark_repetitions="$reps" \
      --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null); then
      echo "ab_bench: binary $side (${binaries[$side]}) failed in round $round" >&2
      exit 1
    fi
    medians=$(awk -F, -v reps="$reps" 'NR > 1 && (reps == 1 || $1 ~ /_median"?$/) { printf "%.3g ", $3 }' <<<"$csv")
    echo "round $round $side: $medians"
  done
done
