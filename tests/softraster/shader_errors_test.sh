#!/usr/bin/env bash
# The shader interface's compile errors stay readable: every shader_errors/*.cpp is a shader with
# one common mistake, drawn with Context::draw; it must fail to compile, with the message named on
# its first line ("// expect: TEXT"), as its only error and in at most 40 lines of diagnostics
# (the pipeline's templates are not instantiated for a type that is not a shader).
# Usage: shader_errors_test.sh CXX INCLUDE_DIR CASES_DIR
set -uo pipefail
cxx=$1
include=$2
cases=$3
failed=0
for f in "$cases"/*.cpp; do
  expect=$(sed -n '1s|^// expect: ||p' "$f")
  if output=$("$cxx" -std=c++20 -fsyntax-only -I"$include" "$f" 2>&1); then
    echo "$(basename "$f"): compiled, but must not"
    failed=1
    continue
  fi
  lines=$(wc -l <<<"$output")
  errors=$(grep -c 'error:' <<<"$output")
  if ! grep -qF -- "$expect" <<<"$output"; then
    echo "$(basename "$f"): the error does not say '$expect':"
    echo "$output" | head -20
    failed=1
  elif [ "$errors" -ne 1 ]; then
    echo "$(basename "$f"): $errors errors (one expected)"
    failed=1
  elif [ "$lines" -gt 40 ]; then
    echo "$(basename "$f"): $lines lines of diagnostics (at most 40)"
    failed=1
  else
    echo "$(basename "$f"): $lines lines, says '$expect'"
  fi
done
exit $failed
