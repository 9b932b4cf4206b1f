#!/usr/bin/env bash
# The shared checks of tests/support/cli_harness.sh fail when they should: a negative check
# (lacks) on the output of a program that crashed and wrote nothing, a comparison (same_lines)
# of two missing or two empty files, an interrupted run whose program never starts its work.
# Each case runs the check in a subshell (fail exits) and expects its status.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
enter_scratch_dir

# refused WHAT cmd...: cmd (a harness check, in a subshell) fails.
refused() { local what=$1; shift; ( "$@" ) 2>>refused.log && fail "$what passed"; true; }
# accepted WHAT cmd...: cmd passes.
accepted() { local what=$1; shift; ( "$@" ) 2>>accepted.log || fail "$what failed: $(tail -1 accepted.log)"; }

case_lacks() {
  # A program killed by a signal before writing: the old `grep -q warning err.txt && fail` passed.
  { sh -c 'kill -SEGV $$' 2>err.txt; } 2>/dev/null
  refused "lacks on a crashed program's empty stderr" lacks "warned" warning err.txt
  refused "lacks on a missing file" lacks "warned" warning missing.txt
  printf 'kcfit: fit\nkcfit: warning: x\n' >w.txt
  refused "lacks on a file that holds the pattern" lacks "warned" warning w.txt
  refused "lacks -i" lacks -i "warned" WARNING w.txt
  printf 'kcfit: fit\n' >ok.txt
  accepted "lacks on a file without the pattern" lacks "warned" warning ok.txt
  refused "lacks over several files, one missing" lacks "warned" warning ok.txt missing.txt
  grep -q "missing or empty" refused.log || fail "not said why: $(cat refused.log)"
}
case_same_lines() {
  refused "two missing files" same_lines "same" '^#' a.csv b.csv
  : >a.csv; : >b.csv
  refused "two empty files" same_lines "same" '^#' a.csv b.csv
  printf '# provenance=1\n' >a.csv; printf '# provenance=2\n' >b.csv
  refused "two files of dropped lines only" same_lines "same" '^#' a.csv b.csv
  printf '# provenance=1\nx,y\n1,2\n' >a.csv; printf '# provenance=2\nx,y\n1,3\n' >b.csv
  refused "two different files" same_lines "same" '^# provenance' a.csv b.csv
  printf '# provenance=2\nx,y\n1,2\n' >b.csv
  accepted "the same lines" same_lines "same" '^# provenance' a.csv b.csv
  [ -z "$(ls -A | grep '^\.same_')" ] || fail "temporaries left: $(ls -A)"
}
case_interrupt_run_waits_for_work() {
  # A program that never announces its work (CMP_READY_FILE) and ends: the signal test fails
  # instead of signalling nothing.
  refused "interrupt_run of a program that never starts its work" interrupt_run INT true
  # One that announces it, then works until the signal: interrupted, by that signal.
  # shellcheck disable=SC2016
  interrupt_run TERM sh -c 'trap "exit 143" TERM; : >"$CMP_READY_FILE"; while :; do sleep 0.01; done'
  local got=$?
  [ "$got" -eq 143 ] || fail "exit $got after SIGTERM"
}

run_cases "$@"
