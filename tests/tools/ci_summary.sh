#!/usr/bin/env bash
# scripts/ci/run_tests.sh's last line, which CI reads: "tests: N passed, N failed, N skipped".
# A ctest entry that exits with its SKIP_RETURN_CODE (77) did not test anything: ctest counts
# it among the passed ones, the summary must not. Each case runs the script on a ctest project
# of its own (a hand-written CTestTestfile.cmake: nothing to configure or build).
set -uo pipefail
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
enter_scratch_dir

# project DIR ENTRY...: a ctest project whose entries are pass (true), fail (false) or skip (exit 77).
project() {
  local dir=$1 i=0 kind; shift
  mkdir -p "$dir"
  for kind in "$@"; do
    i=$((i + 1))
    case $kind in
      pass) echo "add_test(pass_$i \"true\")" ;;
      fail) echo "add_test(fail_$i \"false\")" ;;
      skip) echo "add_test(skip_$i \"sh\" \"-c\" \"exit 77\")"
            echo "set_tests_properties(skip_$i PROPERTIES SKIP_RETURN_CODE 77)" ;;
    esac
  done >"$dir/CTestTestfile.cmake"
}
# summary DIR WANT_STATUS WANT_LINE: run_tests.sh on DIR exits as said and its last line is WANT_LINE.
summary() {
  local dir=$1 want_status=$2 want=$3
  bash "$src/scripts/ci/run_tests.sh" "$dir" >out.txt 2>&1
  local got=$?
  [ "$got" -eq "$want_status" ] || [ "$want_status" -ne 0 -a "$got" -ne 0 ] ||
    fail "exit $got, expected $want_status: $(tail -5 out.txt)"
  [ "$(tail -1 out.txt)" = "$want" ] || fail "last line '$(tail -1 out.txt)', expected '$want'"
}

case_skipped_counted_apart() {
  project p pass skip pass skip skip
  summary p 0 "tests: 2 passed, 0 failed, 3 skipped"
}
case_failed_and_skipped() {
  project p pass skip fail
  summary p 1 "tests: 1 passed, 1 failed, 1 skipped"
}
case_nothing_skipped() {
  project p pass pass
  summary p 0 "tests: 2 passed, 0 failed, 0 skipped"
}
case_no_tests_run() {
  # A build folder without tests: no ctest summary at all, reported as a failure.
  mkdir empty
  summary empty 1 "tests: 0 passed, 1 failed, 0 skipped"
}

run_cases "$@"
