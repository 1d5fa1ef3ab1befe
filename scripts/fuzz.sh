#!/usr/bin/env bash
# The fuzz job (.ci/run runs it last): builds the libFuzzer targets of tests/fuzz/ with clang,
# ASan and UBSan (-DSOFTRASTER_FUZZ=ON) into their own folder (build-fuzz/), then runs each for
# FUZZ_SECONDS (default 60) from its checked-in corpus, tests/fuzz/corpus/TARGET/ (and its
# dictionary tests/fuzz/TARGET.dict, if there is one). New inputs go
# to a scratch folder (the checked-in corpus is not rewritten); an input that crashes, hangs
# (over 10 s) or runs out of memory (over 2 GB) is saved as tests/fuzz/regressions/TARGET/crash-*
# (or timeout-*, oom-*), which the default build's ctest then replays, and the job fails.
# Prints one line per target: runs, coverage (edges, features), corpus size, seconds.
#   FUZZ_SECONDS=300 bash scripts/fuzz.sh [TARGET...]
# Installs clang and its runtime libraries (libFuzzer) when missing, as scripts/setup.sh does.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
targets=("$@")
((${#targets[@]})) || targets=(scene obj expectations draw)

missing=()
for p in clang libclang-rt-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo=sudo
  echo "fuzz: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi

build=build-fuzz
cmake -S . -B "$build" -DSOFTRASTER_FUZZ=ON -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j"$(nproc)" --target "${targets[@]/%/_fuzzer}"

export ASAN_OPTIONS=detect_leaks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failed=0
for target in "${targets[@]}"; do
  work=$(mktemp -d)
  log=$build/fuzz-$target.log
  mkdir -p "tests/fuzz/regressions/$target"
  dict=()
  [ -f "tests/fuzz/$target.dict" ] && dict=(-dict="tests/fuzz/$target.dict")
  status=0
  start=$SECONDS
  "$build/bin/${target}_fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 "${dict[@]}" \
    -artifact_prefix="tests/fuzz/regressions/$target/" "$work" "tests/fuzz/corpus/$target" >"$log" 2>&1 || status=$?
  rm -rf "$work"
  done_line=$(grep -E '^#[0-9]+[[:space:]]+DONE' "$log" | tail -n 1 || true)
  runs=$(grep -oE 'stat::number_of_executed_units: [0-9]+' "$log" | grep -oE '[0-9]+$' || echo '?')
  took=$((SECONDS - start))
  cov=$(grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[a-zA-Z]*' <<<"$done_line" || true)
  if [ "$status" -eq 0 ]; then
    echo "fuzz: $target: clean, $runs runs in ${took} s, ${cov:-no DONE line}"
  else
    echo "fuzz: $target: FAILED (exit $status), $runs runs, ${cov:-no DONE line}; log $log:"
    grep -E '^(==[0-9]+==|SUMMARY|fuzz: property|artifact_prefix|Test unit written)|runtime error' "$log" | head -n 20
    failed=1
  fi
done
exit "$failed"
