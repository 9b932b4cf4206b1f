#!/usr/bin/env bash
# shellpack as a user runs it. `shellpack_cli.sh --list` prints the cases; `shellpack_cli.sh CASE`
# runs one (ctest registers each). Needs CMP_BIN (the built programs).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
shellpack="$bin/shellpack"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=shellpack
enter_scratch_dir
column() {  # column NAME FILE: the values of a CSV column (header by name, # lines skipped)
  awk -F, -v name="$1" '/^#/ { next } !h { for (i = 1; i <= NF; i++) if ($i == name) c = i; h = 1; next } { print $c }' "$2"
}
xyz_packing() {  # xyz_packing FILE LATTICE ROWS...: a small periodic sphere packing
  local file=$1 lattice=$2; shift 2
  { echo $#; echo "Lattice=\"$lattice\" Properties=species:S:1:pos:R:3:radius:R:1 pbc=\"T T T\""
    for row in "$@"; do echo "X $row"; done; } >"$file"
}

case_help() {
  "$shellpack" --help | grep -q "jam" || fail "help lacks jam"
  "$shellpack" jam --help | grep -q -- "--pmin" || fail "jam --help lacks --pmin"
  "$shellpack" jam --help | grep -q "1e-15" || fail "jam --help lacks the thesis tolerance"
  "$shellpack" structure --help | grep -q -- "--forces" || fail "structure --help lacks --forces"
  "$shellpack" --version | grep -Eq "^shellpack [0-9]" || fail "--version"
}
case_jam_one() {
  "$shellpack" jam -N 24 --seed 3 -o out.xyz >out.csv 2>err.txt || fail "jam: $(cat err.txt)"
  [ "$(column contacts out.csv)" = 70 ] || fail "contacts $(column contacts out.csv), expected 3N-2 = 70"
  [ "$(column contacts_isostatic out.csv)" = 70 ] || fail "contacts_isostatic"
  grep -q "^# provenance=shellpack" out.csv || fail "no provenance in CSV"
  head -1 out.xyz | grep -qx 24 || fail "atom count"
  sed -n 2p out.xyz | grep -q 'Properties=species:S:1:pos:R:3:radius:R:1:contacts:I:1' || fail "properties"
  sed -n 2p out.xyz | grep -q 'pbc="T T T"' || fail "pbc"
  sed -n 2p out.xyz | grep -q 'tool="shellpack' || fail "provenance in XYZ"
  # every sphere carries at least 4 contacts (no rattlers), and they sum to twice 70
  awk 'NR > 2 { s += $6; if ($6 < 4) bad = 1 } END { exit !(s == 140 && !bad) }' out.xyz || fail "contact column"
}
case_jam_reproducible_any_threads() {
  "$shellpack" jam -N 16 --seeds 1:4 --threads 1 -o 'one_{seed}.xyz' --csv one.csv -q || fail "1 thread"
  "$shellpack" jam -N 16 --seeds 1:4 --threads 2 -o 'two_{seed}.xyz' --csv two.csv -q || fail "2 threads"
  for s in 1 2 3 4; do
    diff <(sed 2d one_$s.xyz) <(sed 2d two_$s.xyz) >/dev/null || fail "seed $s differs between thread counts"
  done
  diff <(grep -v '^#' one.csv | cut -d, -f1-15) <(grep -v '^#' two.csv | cut -d, -f1-15) || fail "CSV differs"
  [ "$(grep -vc '^#' one.csv)" = 5 ] || fail "expected a header and 4 rows"
  ! cmp -s one_1.xyz one_2.xyz || fail "two seeds gave one packing"
}
case_structure() {
  "$shellpack" jam -N 20 --seeds 1:2 -o 'p_{seed}.xyz' -q >/dev/null || fail "jam"
  "$shellpack" structure p_1.xyz p_2.xyz --forces forces.csv --summary summary.csv >rdf.csv 2>err.txt || fail "structure: $(cat err.txt)"
  grep -q '^# packings=2' rdf.csv || fail "packings meta"
  grep -q '^# rattlers=0' rdf.csv || fail "rattlers meta"
  [ "$(column Z summary.csv | head -1)" = 5.8 ] || fail "Z = $(column Z summary.csv | head -1), expected 6 - 4/20"
  [ "$(grep -vc '^#' forces.csv)" = 41 ] || fail "force histogram rows"
  # the contact peak is the largest g, just below r = 1
  peak=$(grep -v '^#' rdf.csv | tail -n +2 | sort -t, -k2 -g | tail -1 | cut -d, -f1)
  awk -v r="$peak" 'BEGIN { exit !(r > 0.97 && r < 1.0) }' || fail "contact peak at $peak"
}
case_bad_input() {
  expect_error 2 "N" "$shellpack" jam -N 0 -o out.xyz
  expect_error 2 "too small" "$shellpack" jam -N 6 -o out.xyz
  expect_error 2 "seed" "$shellpack" jam -N 16 --seeds 1:3 -o out.xyz
  expect_error 2 "P_min" "$shellpack" jam -N 16 --pmin -1 -o out.xyz
  expect_error 2 "FIRE" "$shellpack" jam -N 16 --fire-f-dec 2 -o out.xyz
  expect_error 2 "missing.xyz" "$shellpack" structure missing.xyz -o out.csv
  xyz_packing dup.xyz "4 0 0 0 4 0 0 0 4" "0 0 0 0.5" "1 1 1 0.5" "1 1 1 0.5"
  expect_error 2 "dup.xyz:5: .*duplicates" "$shellpack" structure dup.xyz -o out.csv
  xyz_packing tilted.xyz "4 0 0 1 4 0 0 0 4" "0 0 0 0.5"
  expect_error 2 "tilted.xyz:1: .*orthorhombic" "$shellpack" structure tilted.xyz -o out.csv
  printf '1\nLattice="4 0 0 0 4 0 0 0 4" pbc="T T T"\nX 0 0 0\n' >noradius.xyz
  expect_error 2 "noradius.xyz:1: .*radius" "$shellpack" structure noradius.xyz -o out.csv
  printf '2\nLattice="4 0 0 0 4 0 0 0 4" Properties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 0.5\n' >short.xyz
  expect_error 2 "short.xyz" "$shellpack" structure short.xyz -o out.csv
  expect_error 2 "bin" "$shellpack" structure dup.xyz --bin 0 -o out.csv
  expect_error 1 "no acceptable" "$shellpack" jam -N 16 --max-tries 1 --fire-max-iterations 3 -o out.xyz
}

run_cases "$@"
