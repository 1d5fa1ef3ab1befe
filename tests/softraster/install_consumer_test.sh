#!/usr/bin/env bash
# Installs softraster from the build tree into a scratch prefix, then configures, builds and runs
# an outside project that finds it with find_package(softraster).
set -euo pipefail
build_dir=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/softraster/pipeline.hpp"
cmake -S "$source_dir/tests/softraster/consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >/dev/null
"$work/build/consumer"
