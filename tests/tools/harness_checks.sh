#!/usr/bin/env bash
# The shared checks of tests/support/cli_harness.sh fail when they should: a negative check
# (lacks) on the output of a program that crashed and wrote nothing, a comparison (same_lines)
# of two missing or two empty files.
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
run_cases "$@"
