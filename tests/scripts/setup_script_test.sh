#!/usr/bin/env bash
# scripts/setup.sh's failure paths, with stand-ins for the system tools on a PATH of their own
# (nothing is installed, nothing built): packages missing and neither root nor sudo; apt-get
# failing (its error must be shown, with the packages); an unknown job. A case prints "ok: NAME".
# Usage: setup_script_test.sh SOURCE_DIR
set -uo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

# A PATH with only the tools setup.sh runs before it builds, plus the stand-ins.
make_path() {
  local bin=$work/$1
  mkdir -p "$bin"
  for tool in bash dirname grep mktemp cat rm; do ln -sf "$(command -v $tool)" "$bin/$tool"; done
  printf '#!/bin/sh\nexit 1\n' >"$bin/dpkg-query"           # every package missing
  printf '#!/bin/sh\necho 1000\n' >"$bin/id"                  # not root
  printf '#!/bin/sh\necho "cmake must not run" >&2\nexit 3\n' >"$bin/cmake"
  chmod +x "$bin"/*
  echo "$bin"
}

run_setup() {  # PATH JOB: runs setup.sh, output in $out, status in $status
  out=$(PATH=$1 "$1/bash" "$source_dir/scripts/setup.sh" $2 2>&1)
  status=$?
}

# Not root and no sudo: one line naming the packages, exit 1, apt-get never run.
bin=$(make_path nosudo)
printf '#!/bin/sh\necho "apt-get must not run" >&2\nexit 3\n' >"$bin/apt-get"; chmod +x "$bin/apt-get"
run_setup "$bin" tests
if [ $status -ne 1 ]; then fail "no sudo: exit $status, expected 1: $out"
elif ! grep -q "needs root or sudo (neither is available): .*libgtest-dev" <<<"$out"; then fail "no sudo: message: $out"
elif grep -q "must not run" <<<"$out"; then fail "no sudo: ran a tool it should not: $out"
else echo "ok: no_root_no_sudo"; fi

# The main job asks only for its own packages (no test tools).
run_setup "$bin" main
if grep -q "libgtest-dev\|chromium" <<<"$out"; then fail "main job: asked for the tests' packages: $out"
elif ! grep -q "mesa-vulkan-drivers" <<<"$out"; then fail "main job: message: $out"
else echo "ok: main_job_packages"; fi

# apt-get fails: its own error is shown, then setup's line; cmake never runs.
bin=$(make_path aptfails)
printf '#!/bin/sh\n"$@"\n' >"$bin/sudo"
printf '#!/bin/sh\n[ "$1" = update ] && exit 0\necho "E: Unable to locate package chromium" >&2\nexit 100\n' >"$bin/apt-get"
chmod +x "$bin/sudo" "$bin/apt-get"
run_setup "$bin" tests
if [ $status -ne 1 ]; then fail "apt fails: exit $status, expected 1: $out"
elif ! grep -q "E: Unable to locate package chromium" <<<"$out"; then fail "apt fails: apt's error not shown: $out"
elif ! grep -q "setup: apt-get failed" <<<"$out"; then fail "apt fails: no setup line: $out"
elif grep -q "cmake must not run" <<<"$out"; then fail "apt fails: went on to build: $out"
else echo "ok: apt_error_shown"; fi

# An unknown job: exit 2, named.
run_setup "$bin" everything
if [ $status -ne 2 ] || ! grep -q "unknown job 'everything'" <<<"$out"; then fail "unknown job: exit $status: $out"
else echo "ok: unknown_job"; fi

[ $failures -eq 0 ] && echo "setup script: all cases pass"
exit $((failures > 0))
