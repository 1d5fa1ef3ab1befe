# The harness the crosscheck command-line tests (*_cli_test.sh) share: sourced, not run. Each
# test script is called as SCRIPT CASE CROSSCHECK SOURCE_DIR ARTIFACTS_DIR [MORE...] and starts
#   source "$(dirname "${BASH_SOURCE[0]}")/cli_case.sh"
#   cli_case_begin SUBDIR "$@"
# which sets case_name, crosscheck, src and artifacts (ARTIFACTS_DIR/SUBDIR/CASE, emptied) and
# enters SOURCE_DIR. Then:
#   run ARGS...        crosscheck ARGS, stdout to out.txt and stderr to err.txt in $artifacts,
#                      the exit status to $status (a script may define its own run after sourcing)
#   fail MESSAGE       prints the message and both files, exits 1 (stderr_lines=N: only its
#                      last N lines, for commands that log a lot)
#   expect_status N, expect_out REGEX, expect_err REGEX, expect_last_line TEXT,
#   expect_one_error_line (exactly one line on stderr and nothing on stdout)
#   other_fma          the fmuladd rounding lavapipe does NOT use on this CPU (softraster's
#                      cpuHasFma): with it, depth_slope's depths differ in their last bits
# Deliberately nothing case-specific: each script keeps its cases and its own helpers.

cli_case_begin() {
  local subdir=$1
  case_name=$2
  crosscheck=$3
  src=$4
  artifacts=$5/$subdir/$case_name
  rm -rf "$artifacts"
  mkdir -p "$artifacts"
  cd "$src" || exit 1
}

stderr_lines=
fail() {
  echo "FAILED: $*"
  [ -f "$artifacts/out.txt" ] && { echo "--- stdout"; cat "$artifacts/out.txt"; }
  if [ -f "$artifacts/err.txt" ]; then
    echo "--- stderr"
    if [ -n "$stderr_lines" ]; then tail -n "$stderr_lines" "$artifacts/err.txt"; else cat "$artifacts/err.txt"; fi
  fi
  exit 1
}

run() {
  "$crosscheck" "$@" >"$artifacts/out.txt" 2>"$artifacts/err.txt"
  status=$?
}

expect_status() { [ "$status" -eq "$1" ] || fail "exit status $status, expected $1"; }
expect_out() { grep -qE -- "$1" "$artifacts/out.txt" || fail "stdout has no line matching: $1"; }
expect_err() { grep -qE -- "$1" "$artifacts/err.txt" || fail "stderr has no line matching: $1"; }
expect_last_line() {
  local last
  last=$(tail -n 1 "$artifacts/out.txt")
  [ "$last" = "$1" ] || fail "last line is '$last', expected '$1'"
}
expect_one_error_line() {
  [ "$(wc -l <"$artifacts/err.txt")" -eq 1 ] || fail "expected exactly one error line"
  [ ! -s "$artifacts/out.txt" ] || fail "expected nothing on stdout"
}

case "$(uname -m)" in
  x86_64 | i?86) if grep -qw fma /proc/cpuinfo 2>/dev/null; then other_fma=separate; else other_fma=fused; fi ;;
  aarch64 | arm64) other_fma=separate ;;
  *) other_fma=fused ;;
esac
