#!/usr/bin/env bash
# The sanitizer job (.ci/run runs it after the tests): builds everything with AddressSanitizer,
# LeakSanitizer and UndefinedBehaviorSanitizer, no recovery (-DSOFTRASTER_SANITIZE=ON), into its
# own folder (default build-sanitize/), then runs the whole test suite under them: the unit tests,
# every scene cross-checked, and the conformance suite in worker processes (conformance.cli.*).
# Leaks inside the Vulkan driver are suppressed by tests/sanitizers/lsan.supp (its libraries
# only); any other leak, overflow or undefined behaviour fails the test that hit it.
#   bash scripts/sanitize.sh [BUILD_DIR]
# Deliberately no package installation: run scripts/setup.sh (or scripts/test.sh) first.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-sanitize}

# -O1, as the sanitizers' documentation suggests: the shading-model tables compile in a fraction
# of -O2's time and the tests still run fast; asserts stay on (no NDEBUG). -g1: line tables, all
# the sanitizers' stack traces read (no locals or types for a debugger): 13% less compile time
# than -g on a shading-model file.
# No softraster_benchmarks (benchmarks/): no test runs it, and the test job keeps it compiling.
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DSOFTRASTER_SANITIZE=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON >/dev/null
cmake --build "$build" -j"$(nproc)"

export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0
cd "$build"
# Left out: the tests that only run the compiler over the installed package or over shader
# interface mistakes (install.*, softraster.shader_errors*). They execute none of our code under
# the sanitizers, the test job runs them, and here they cost ~9 of the job's minutes (a
# sanitized consumer build of every shading model).
ctest --output-on-failure -j"$(nproc)" -E '^(install\.|softraster\.shader_errors)'

