#!/usr/bin/env bash
# Tells whether this host's cores are steady enough to judge a multi-thread time: runs one
# benchmark of softraster_benchmarks (1 thread) pinned to each CPU this process may use, in turn,
# ROUNDS times, then on all of them at once, and prints each CPU's real times, the slowest CPU's
# median over the fastest's, and the same for the run all at once. Sessions measured the host's two
# vCPUs at 34-35 ms and 59-60 ms on the same frame, pinned (docs/architecture.md, Timing): a
# 2-thread ratio taken then says as much about the host as about the renderer.
#   ROUNDS=3 MIN_TIME=1 bash scripts/core_check.sh build/bin/softraster_benchmarks [FILTER]
# FILTER must select one benchmark; the default, '^Sphere1MCulled/threads:1/', is a million small
# triangles: memory-heavy, as the small-primitive frames whose 2-thread ratios move most are.
# MIN_TIME: each run's --benchmark_min_time, in seconds. Judges nothing and builds nothing.
# Errors (one line on stderr): wrong arguments, a binary that is not an executable file, a filter
# that selects not exactly one benchmark, bad ROUNDS or MIN_TIME, no taskset (exit 2); a run that
# fails (exit 1).
set -euo pipefail
if (($# < 1 || $# > 2)); then
  echo "usage: core_check.sh SOFTRASTER_BENCHMARKS [FILTER]" >&2
  exit 2
fi
binary=$1
filter=${2:-'^Sphere1MCulled/threads:1/'}
rounds=${ROUNDS:-3}
min_time=${MIN_TIME:-1}
if ! [[ "$rounds" =~ ^[1-9][0-9]*$ ]] || ! [[ "$min_time" =~ ^([0-9]+\.?[0-9]*|\.[0-9]+)$ ]]; then
  echo "core_check: ROUNDS ($rounds) must be a positive whole number and MIN_TIME ($min_time) a number of seconds" >&2
  exit 2
fi
if [ ! -f "$binary" ] || [ ! -x "$binary" ]; then
  echo "core_check: $binary: not an executable file" >&2
  exit 2
fi
if ! command -v taskset >/dev/null; then
  echo "core_check: taskset is not installed (Debian's util-linux)" >&2
  exit 2
fi
selected=$("$binary" --benchmark_list_tests --benchmark_filter="$filter" 2>/dev/null | grep -c . || true)
if [ "$selected" -ne 1 ]; then
  echo "core_check: '$filter' selects $selected benchmarks, not one" >&2
  exit 2
fi

# The CPUs this process may run on, from its affinity list (e.g. "0-3,6").
cpus=()
IFS=, read -ra parts <<<"$(taskset -cp $$ | sed 's/.*: //')"
for part in "${parts[@]}"; do
  if [[ "$part" =~ ^([0-9]+)-([0-9]+)$ ]]; then
    for ((cpu = BASH_REMATCH[1]; cpu <= BASH_REMATCH[2]; ++cpu)); do cpus+=("$cpu"); done
  else
    cpus+=("$part")
  fi
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# run_on CPU OUT: the benchmark's real time (ms, as the benchmark reports it) pinned to CPU, in OUT.
run_on() {
  local csv
  if ! csv=$(taskset -c "$1" "$binary" --benchmark_filter="$filter" --benchmark_min_time="$min_time" \
    --benchmark_format=csv 2>/dev/null); then
    echo "core_check: the benchmark failed on CPU $1" >&2
    return 1
  fi
  awk -F, 'NR > 1 { printf "%.3g\n", $3 }' <<<"$csv" >"$2"
}

# median VALUES...
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { printf "%.3g\n", (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
# ratio SLOWEST FASTEST
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }

echo "$("$binary" --benchmark_list_tests --benchmark_filter="$filter" 2>/dev/null), pinned, ms:"
medians=()
for cpu in "${cpus[@]}"; do
  times=()
  for ((round = 1; round <= rounds; ++round)); do
    run_on "$cpu" "$scratch/alone" || exit 1
    times+=("$(cat "$scratch/alone")")
  done
  medians+=("$(median "${times[@]}")")
  echo "  CPU $cpu alone: ${times[*]}"
done
together=()
pids=()
for cpu in "${cpus[@]}"; do
  run_on "$cpu" "$scratch/together.$cpu" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid" || exit 1; done
line="  all at once:"
for cpu in "${cpus[@]}"; do
  together+=("$(cat "$scratch/together.$cpu")")
  line+=" CPU $cpu ${together[-1]}"
done
echo "$line"
fastest=$(printf '%s\n' "${medians[@]}" | sort -g | head -n 1)
slowest=$(printf '%s\n' "${medians[@]}" | sort -g | tail -n 1)
slowest_together=$(printf '%s\n' "${together[@]}" | sort -g | tail -n 1)
echo "slowest CPU's median over the fastest's, alone: $(ratio "$slowest" "$fastest") ($fastest to $slowest ms)"
echo "all at once, the slowest CPU over the fastest's median alone: $(ratio "$slowest_together" "$fastest")"
