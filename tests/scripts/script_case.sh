# The harness the script tests here (ab_bench_test.sh, core_check_test.sh) share: sourced, not run,
# after `script` is set to the script under test. Cases go on after a failure; the last line says
# how they went (ctest matches it).
#   fail MESSAGE                          counts a failed case
#   expect_error NAME STATUS PATTERN ARGS...
#                                         bash $script ARGS exits STATUS, and stderr is one line
#                                         matching PATTERN
#   finish NAME                           "NAME script: all cases pass", or the count of failures
#                                         and exit 1
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

expect_error() {
  local name=$1 want=$2 pattern=$3
  shift 3
  local err rc
  err=$(bash "$script" "$@" 2>&1 >/dev/null)
  rc=$?
  [ "$rc" -eq "$want" ] || fail "$name: exit $rc, expected $want"
  [ "$(printf '%s\n' "$err" | wc -l)" -eq 1 ] || fail "$name: stderr is not one line: $err"
  [[ "$err" =~ $pattern ]] || fail "$name: stderr '$err' does not match '$pattern'"
}

finish() {
  if ((failures)); then
    echo "$1 script: $failures case(s) failed"
    exit 1
  fi
  echo "$1 script: all cases pass"
}
