#!/usr/bin/env bash
# The main job: set up, then cross-check every scene in scenes/ (softraster against Vulkan on
# lavapipe) and print each result. Images go to out/<scene>/. Exit 1 if any scene is outside
# its tolerance.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
passed=0 failed=0
for scene in scenes/*.json; do
  name=$(basename "$scene" .json)
  if build/bin/crosscheck compare "$scene" --out "out/$name"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
  fi
done
echo "images in out/<scene>/ (soft.png, vulkan.png, diff.png, *.depth.png)"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
