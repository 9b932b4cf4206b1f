#!/usr/bin/env bash
# The goldens of tests/tools/golden_outputs.sh are only read by the test: no variable of the
# environment (GOLDEN_RECORD=1 used to) makes a run of the test rewrite tests/data/golden and
# pass; they are recorded only by `make golden-record`, which refuses under CI (CI=true). Each
# case runs golden_outputs.sh on a copy of the checkout's tests/data/golden (CMP_SRC pointing at
# a scratch tree with links to the rest), so nothing here can touch the committed goldens.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
bin=$(cd "$bin" && pwd)
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
enter_scratch_dir
golden="$src/tests/tools/golden_outputs.sh"

# fake_src: ./src, a checkout whose tests/data/golden is a copy (kcfit's last hash made wrong).
fake_src() {
  mkdir -p src/tests/data
  ln -s "$src/data" src/data
  ln -s "$src/tests/support" src/tests/support
  cp -r "$src/tests/data/golden" src/tests/data/golden
  sed -i '$s/ [0-9a-f]*$/ 0000000000000000/' src/tests/data/golden/kcfit.txt
  cmp -s src/tests/data/golden/kcfit.txt "$src/tests/data/golden/kcfit.txt" && fail "the wrong golden is not wrong"
  cp src/tests/data/golden/kcfit.txt wrong.txt
}

case_wrong_golden_fails() {
  fake_src
  CMP_SRC="$PWD/src" bash "$golden" kcfit >out.txt 2>&1 && fail "a wrong golden passed: $(cat out.txt)"
  grep -q "kcfit: outputs differ from the recorded ones" out.txt || fail "not the golden's failure: $(cat out.txt)"
  grep -q "^< [a-z_]*\.csv 0000000000000000$" out.txt || fail "the diff does not show the wrong line: $(cat out.txt)"
}
case_record_variable_ignored() {
  # GOLDEN_RECORD=1 in the environment (ctest passes the caller's through): still a failure,
  # and the golden is left as it was.
  fake_src
  GOLDEN_RECORD=1 CMP_SRC="$PWD/src" bash "$golden" kcfit >out.txt 2>&1 && fail "GOLDEN_RECORD=1 made a wrong golden pass: $(cat out.txt)"
  cmp -s wrong.txt src/tests/data/golden/kcfit.txt || fail "the test rewrote the golden: $(diff wrong.txt src/tests/data/golden/kcfit.txt)"
}
case_record_refused_under_ci() {
  fake_src
  CI=true CMP_SRC="$PWD/src" bash "$golden" --record kcfit rec.txt >out.txt 2>&1 && fail "recorded under CI"
  grep -q "not recorded under CI" out.txt || fail "stderr: $(cat out.txt)"
  [ ! -e rec.txt ] || fail "wrote rec.txt under CI"
  # make golden-record refuses before it builds or runs anything.
  CI=true make -s -C "$src" golden-record BUILD="$PWD/nobuild" >out.txt 2>&1
  local got=$?
  [ "$got" -eq 2 ] || fail "make golden-record under CI exited $got: $(cat out.txt)"
  grep -q "make golden-record: not under CI" out.txt || fail "make golden-record under CI: $(cat out.txt)"
  [ ! -e nobuild ] || fail "make golden-record under CI configured a build"
}
case_record_writes_only_where_told() {
  # The recording mode writes the hashes to the file it is given, and they are the committed ones.
  env -u CI bash "$golden" --record kcfit rec.txt >out.txt 2>&1 || fail "--record: $(cat out.txt)"
  cmp -s rec.txt "$src/tests/data/golden/kcfit.txt" || fail "recorded hashes differ: $(diff rec.txt "$src/tests/data/golden/kcfit.txt")"
}

run_cases "$@"
