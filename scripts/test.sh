#!/usr/bin/env bash
# The test job: set up, then run the whole test suite with ctest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh tests
cd build
ctest --output-on-failure -j"$(nproc)"
