#!/usr/bin/env bash
# Compares two builds of softraster_benchmarks (A and B) on this noisy, shared host: copies each
# binary to a fresh file first, then runs them in alternating rounds (A, B, A, B, ...), each
# round the medians of REPS repetitions of the benchmarks FILTER selects (with REPS=1, the one
# run's time), and prints one line per binary per round (real time in ms, in the order Google
# Benchmark runs them), then a paired summary per benchmark: each side's median over the rounds,
# and the median and range of B/A taken round by round (A and B of a round run minutes apart at
# most, so a slow spell of the host tends to hit both), with how many rounds B was faster in.
#   ROUNDS=4 REPS=3 bash scripts/ab_bench.sh A B 'regex'
#   bash scripts/ab_bench.sh --summary FILE   (the summary of an earlier run's output, saved)
# e.g. bash scripts/ab_bench.sh /tmp/old/softraster_benchmarks build/bin/softraster_benchmarks \
#        '^(SmallTrianglesInAPass|Sphere100kColdInAPass)/threads:2/'
# Why the copies: two byte-identical binaries (cmp found no difference) ran Sphere100kColdInAPass
# at 16-19 ms and at 9-11 ms, round after round, until the slow one's page-cache pages were
# dropped (posix_fadvise DONTNEED), after which it ran at 9.4 ms too: where a binary's pages lie
# can cost more than the change being measured. A fresh copy lands elsewhere; a difference that
# does not hold in every round is noise. Does not build anything, and judges nothing: the summary
# says how the rounds fell, not whether a change is real.
# Errors (one line on stderr): wrong arguments, a binary that is not an executable file, a filter
# that selects nothing or not the same benchmarks in both, a summary file that cannot be read or
# holds no rounds (exit 2); a run that fails (exit 1).
set -euo pipefail

# The paired summary of an ab_bench output (the benchmark list, then the round lines) on stdin.
# mawk (Debian's awk) has no sort, so the medians sort by insertion.
summarize() {
  awk '
    function median(v, n,    i, j, x) {
      for (i = 2; i <= n; ++i) {
        x = v[i]
        for (j = i - 1; j >= 1 && v[j] > x; --j) v[j + 1] = v[j]
        v[j + 1] = x
      }
      return n % 2 ? v[(n + 1) / 2] : (v[n / 2] + v[n / 2 + 1]) / 2
    }
    /^  [^ ]/ { names[++count] = substr($0, 3); next }
    /^round [0-9]+ [AB]: / {
      round = $2 + 0
      side = substr($3, 1, 1)
      for (k = 4; k <= NF; ++k) time[side, round, k - 3] = $k
      if (round > rounds) rounds = round
    }
    END {
      if (rounds == 0) exit 1
      print "paired summary (B/A round by round; below 1: B faster):"
      for (b = 1; b <= count; ++b) {
        n = 0
        faster = 0
        for (r = 1; r <= rounds; ++r) {
          if (!((("A", r, b) in time) && (("B", r, b) in time)) || time["A", r, b] <= 0) continue
          ++n
          a[n] = time["A", r, b]
          bb[n] = time["B", r, b]
          ratio[n] = time["B", r, b] / time["A", r, b]
          if (ratio[n] < 1) ++faster
        }
        if (n == 0) continue
        lo = ratio[1]
        hi = ratio[1]
        for (k = 2; k <= n; ++k) {
          if (ratio[k] < lo) lo = ratio[k]
          if (ratio[k] > hi) hi = ratio[k]
        }
        printf "  %s: A %.3g, B %.3g (medians of %d rounds); B/A %.2f (%.2f-%.2f), B faster in %d of %d\n",
               names[b], median(a, n), median(bb, n), n, median(ratio, n), lo, hi, faster, n
      }
    }'
}

if (($# == 2)) && [ "$1" = "--summary" ]; then
  if [ ! -f "$2" ] || [ ! -r "$2" ]; then
    echo "ab_bench: $2: not a readable file" >&2
    exit 2
  fi
  if ! summarize <"$2"; then
    echo "ab_bench: $2: no rounds to summarize" >&2
    exit 2
  fi
  exit 0
fi
if (($# != 3)); then
  echo "usage: ab_bench.sh BINARY_A BINARY_B FILTER | ab_bench.sh --summary FILE" >&2
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
output=$scratch/output
echo "benchmarks (columns: real-time medians, in each benchmark's unit, ms for all of ours):" | tee "$output"
while IFS= read -r name; do echo "  $name"; done <<<"$names" | tee -a "$output"
for ((round = 1; round <= rounds; ++round)); do
  for side in A B; do
    # With one repetition Google Benchmark reports the run itself and no aggregates.
    if ! csv=$("$scratch/$side" --benchmark_filter="$filter" --benchmark_repetitions="$reps" \
      --benchmark_report_aggregates_only=true --benchmark_format=csv 2>/dev/null); then
      echo "ab_bench: binary $side (${binaries[$side]}) failed in round $round" >&2
      exit 1
    fi
    medians=$(awk -F, -v reps="$reps" 'NR > 1 && (reps == 1 || $1 ~ /_median"?$/) { printf "%.3g ", $3 }' <<<"$csv")
    echo "round $round $side: $medians" | tee -a "$output"
  done
done
summarize <"$output"
