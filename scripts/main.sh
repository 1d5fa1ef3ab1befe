#!/usr/bin/env bash
# The main job: set up, then run the conformance suite (every scene in scenes/, softraster against
# Vulkan on lavapipe, known failures from scenes/expectations.txt) and write the HTML report to
# out/report/index.html and JUnit XML to out/conformance.junit.xml. Prints one line per scene,
# the summary and, last, "N passed, N failed". Exit 1 if anything unexpected happened.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh main
exec build/bin/crosscheck report --jobs "$(nproc)" --expectations scenes/expectations.txt \
  --junit out/conformance.junit.xml -o out/report
