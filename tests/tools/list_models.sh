#!/usr/bin/env bash
# Every program that has styles lists them one way (lib/core/registry.hpp): `--list-models`
# prints CSV whose first columns are kind,name,description, one row per registered style, and
# an unknown style name is refused with "unknown <kind> '<name>' (known: ...)".
set -uo pipefail
bin=${CMP_BIN:-build/bin}
bin=$(cd "$bin" && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
enter_scratch_dir

# check_listing FILE KIND NAME...: FILE reads as CSV with that header and lists every NAME under KIND.
check_listing() {
  /usr/bin/python3 - "$@" <<'PY' || fail "listing $1"
import csv, sys
path, kind, names = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = list(csv.reader(open(path)))
assert rows[0][:3] == ["kind", "name", "description"], rows[0]
assert all(len(r) == len(rows[0]) for r in rows), "ragged rows"
listed = {(r[0], r[1]) for r in rows[1:]}
missing = [n for n in names if (kind, n) not in listed]
assert not missing, f"{path}: {kind} lacks {missing}"
assert all(r[2] and "\n" not in r[2] for r in rows[1:]), "an empty or multi-line description"
PY
}

case_shellpack() {
  "$bin/shellpack" shell --list-models >list.csv || fail "shellpack --list-models"
  check_listing list.csv contact hertz-vertices hertz-faces hertz-walls
  check_listing list.csv stretching svk springs-kot
  cli_tool=shellpack expect_error 2 "unknown stretching model 'fem' (known: .*svk" "$bin/shellpack" shell --mesh x.off --model fem -o out.off
}
case_jam2d() {
  "$bin/jam2d" --list-models >list.csv || fail "jam2d --list-models"
  check_listing list.csv contact harmonic hertz
  cli_tool=jam2d expect_error 2 "--contact: unknown contact law 'lj' (known: harmonic, hertz, sticky)" "$bin/jam2d" grow --box 4 --contact lj -o out.xyz --csv out.csv
  cli_tool=jam2d expect_error 2 "a subcommand is required" "$bin/jam2d"
}
case_lbflow() {
  "$bin/lbflow" --list-models >list.csv || fail "lbflow --list-models"
  check_listing list.csv collision mrt mrt-dh trt bgk
}
case_kcfit() {
  "$bin/kcfit" --list-models >list.csv || fail "kcfit --list-models"
  check_listing list.csv model kc-classical kc-percolation power sigmoid tortuosity
  grep -q "gamma + 0.76" list.csv || fail "Eq. 5.8's formula missing"
}

run_cases "$@"
