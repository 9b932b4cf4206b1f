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
  "$shellpack" --help | grep >/dev/null "jam" || fail "help lacks jam"
  "$shellpack" jam --help | grep >/dev/null -- "--pmin" || fail "jam --help lacks --pmin"
  "$shellpack" jam --help | grep >/dev/null "1e-15" || fail "jam --help lacks the thesis tolerance"
  "$shellpack" structure --help | grep >/dev/null -- "--forces" || fail "structure --help lacks --forces"
  "$shellpack" --version | grep -Eq "^shellpack [0-9]" || fail "--version"
}
case_jam_one() {
  "$shellpack" jam -N 24 --seed 3 -o out.xyz >out.csv 2>err.txt || fail "jam: $(cat err.txt)"
  [ "$(column contacts out.csv)" = 70 ] || fail "contacts $(column contacts out.csv), expected 3N-2 = 70"
  [ "$(column contacts_isostatic out.csv)" = 70 ] || fail "contacts_isostatic"
  grep -q "^# provenance=shellpack" out.csv || fail "no provenance in CSV"
  head -1 out.xyz | grep >/dev/null -x 24 || fail "atom count"
  sed -n 2p out.xyz | grep >/dev/null 'Properties=species:S:1:pos:R:3:radius:R:1:contacts:I:1' || fail "properties"
  sed -n 2p out.xyz | grep >/dev/null 'pbc="T T T"' || fail "pbc"
  sed -n 2p out.xyz | grep >/dev/null 'tool="shellpack' || fail "provenance in XYZ"
  # every sphere carries at least 4 contacts (no rattlers), and they sum to twice 70
  awk 'NR > 2 { s += $6; if ($6 < 4) bad = 1 } END { exit !(s == 140 && !bad) }' out.xyz || fail "contact column"
}
case_jam_reproducible_any_threads() {
  "$shellpack" jam -N 16 --seeds 1:4 --threads 1 -o 'one_{seed}.xyz' --csv one.csv -q || fail "1 thread"
  "$shellpack" jam -N 16 --seeds 1:4 --threads 2 -o 'two_{seed}.xyz' --csv two.csv -q || fail "2 threads"
  for s in 1 2 3 4; do
    diff <(sed 2d one_$s.xyz) <(sed 2d two_$s.xyz) >/dev/null || fail "seed $s differs between thread counts"
  done
  same_lines "CSV differs" '^#' one.csv two.csv
  [ "$(grep -vc '^#' one.csv)" = 5 ] || fail "expected a header and 4 rows"
  ! cmp -s one_1.xyz one_2.xyz || fail "two seeds gave one packing"
}
case_jam_polydisperse() {
  "$shellpack" jam -N 20 --seed 5 --polydispersity 0.2 -o poly.xyz >poly.csv 2>err.txt || fail "jam: $(cat err.txt)"
  grep -q '^# polydispersity=0.2' poly.csv || fail "no polydispersity line"
  [ "$(column contacts poly.csv)" = 58 ] || fail "contacts $(column contacts poly.csv), expected 3N-2 = 58"
  # radii differ, their relative spread is of the order asked
  awk 'NR > 2 { r[NR] = $5; s += $5; n++ } END { m = s / n; for (i in r) v += (r[i] - m)^2; cv = sqrt(v / n) / m
       exit !(cv > 0.1 && cv < 0.3) }' poly.xyz || fail "radius spread"
  expect_error 2 "polydispersity" "$shellpack" jam -N 20 --polydispersity 0.4 -o no.xyz
  [ ! -e no.xyz ] || fail "output written on bad option"
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
  expect_error 2 "--resume: needs -o with {seed}" "$shellpack" jam -N 16 --seeds 1:3 -o out.xyz --resume
  expect_error 2 "--pmin: must be positive, got '-1'" "$shellpack" jam -N 16 --pmin -1 -o out.xyz
  expect_error 2 "--fire-f-dec: must lie in (0, 1), got '2'" "$shellpack" jam -N 16 --fire-f-dec 2 -o out.xyz
  expect_error 2 "--spheres: '20x' is not an integer" "$shellpack" jam -N 20x -o out.xyz
  expect_error 2 "unknown subcommand 'squash'" "$shellpack" squash -o out.xyz
  expect_error 2 "missing.xyz" "$shellpack" structure missing.xyz -o out.csv
  xyz_packing dup.xyz "4 0 0 0 4 0 0 0 4" "0 0 0 0.5" "1 1 1 0.5" "1 1 1 0.5"
  expect_error 2 "dup.xyz:5: .*duplicates" "$shellpack" structure dup.xyz -o out.csv
  xyz_packing tilted.xyz "4 0 0 1 4 0 0 0 4" "0 0 0 0.5"
  expect_error 2 "tilted.xyz:1: .*orthorhombic" "$shellpack" structure tilted.xyz -o out.csv
  printf '1\nLattice="4 0 0 0 4 0 0 0 4" pbc="T T T"\nX 0 0 0\n' >noradius.xyz
  expect_error 2 "noradius.xyz:1: .*radius" "$shellpack" structure noradius.xyz -o out.csv
  printf '2\nLattice="4 0 0 0 4 0 0 0 4" Properties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 0.5\n' >short.xyz
  expect_error 2 "short.xyz" "$shellpack" structure short.xyz -o out.csv
  expect_error 2 "--bin: must be positive" "$shellpack" structure dup.xyz --bin 0 -o out.csv
  expect_error 2 "at most one of them may be '-'" "$shellpack" structure dup.xyz --forces - -o -
  expect_error 1 "no acceptable" "$shellpack" jam -N 16 --max-tries 1 --fire-max-iterations 3 -o out.xyz
}

case_bad_options_all_at_once() {
  "$shellpack" jam -N 20 --pmin -1 --fire-dt -1 --youngs-modulus -3 -o out.xyz 2>stderr.txt; [ $? = 2 ] || fail "status"
  diff - stderr.txt <<'EOT' || fail "messages"
shellpack: --pmin: must be positive, got '-1'
shellpack: --youngs-modulus: must be positive, got '-3'
shellpack: --fire-dt: must be positive, got '-1'
shellpack: run 'shellpack jam --help' for the options
EOT
  "$shellpack" jam --help | grep -Eq -- "-N,--spheres INT REQUIRED( |$)" || fail "help: $("$shellpack" jam --help | grep spheres)"
}
case_pipe_jam_to_structure() {
  # -o - alone sends only the packing down the pipe (the CSV goes to stdout only when the
  # packing does not, or to --csv FILE).
  "$shellpack" jam -N 20 --seed 2 -o - 2>err.txt | "$shellpack" structure - --summary s.csv -q >rdf.csv ||
    fail "pipe: $(cat err.txt)"
  grep -q '^# packings=1' rdf.csv || fail "rdf: $(head -3 rdf.csv)"
  [ "$(column Z s.csv)" = 5.8 ] || fail "Z through the pipe: $(cat s.csv)"
  "$shellpack" -q jam -N 20 --seed 2 -o - --csv j.csv | "$shellpack" structure - -q >/dev/null || fail "with --csv"
  [ "$(grep -vc '^#' j.csv)" = 2 ] || fail "--csv j.csv: $(cat j.csv)"
  expect_error 2 "--csv: the packing already goes to stdout" "$shellpack" jam -N 20 -o - --csv -
  # --seeds with -o - (or a file without {seed}): every packing is a frame of one XYZ, in seed
  # order, the same atoms as one file per seed; structure pools the frames.
  "$shellpack" jam -N 20 --seeds 1:3 -q -o - >all.xyz || fail "--seeds -o -"
  "$shellpack" jam -N 20 --seeds 1:3 -q -o 'one_{seed}.xyz' --csv /dev/null || fail "--seeds -o {seed}"
  [ "$(grep -c Lattice= all.xyz)" = 3 ] || fail "not 3 frames: $(grep -c Lattice= all.xyz)"
  cat one_1.xyz one_2.xyz one_3.xyz | grep -v Lattice= >per_seed.txt
  grep -v Lattice= all.xyz | cmp -s - per_seed.txt || fail "frames differ from the per-seed files"
  "$shellpack" jam -N 20 --seeds 1:3 -q -o - | "$shellpack" structure - -q >rdf3.csv || fail "3 frames | structure"
  grep -q '^# packings=3' rdf3.csv || fail "structure of 3 frames: $(head -3 rdf3.csv)"
}
case_seeds_summary() {
  "$shellpack" jam -N 12 --seeds 1:3 --csv out.csv 2>err.txt || fail "run: $(cat err.txt)"
  grep -Eq "^shellpack: 3 packings of N = 12: phi_J = 0\.[0-9]+ \(sd [0-9.]+\), Z = [0-9.]+, [0-9]+ tries \([0-9]+ rejected: .*\)" err.txt ||
    fail "no closing summary: $(cat err.txt)"
  "$shellpack" jam -N 12 --seeds 1:3 --csv out2.csv -q 2>err.txt; [ ! -s err.txt ] || fail "-q printed: $(cat err.txt)"
}
case_progress_shows_tries_and_rejections() {
  # seed 1 at N = 12 is rejected a few times before a packing is accepted; on a terminal the
  # bar says so, and the summary starts on its own line.
  on_terminal tty.txt "$shellpack" jam -N 12 --seed 1 --csv j.csv || fail "run: $(cat -v tty.txt)"
  grep -aq "jamming \[.*try [0-9]*, rejected: " tty.txt || fail "no tries in the bar: $(cat -v tty.txt)"
  grep -aEq "rejected: [0-9]+ (not isostatic|rattlers)" tty.txt || fail "no reason counts: $(cat -v tty.txt)"
  tr '\r' '\n' <tty.txt | grep -aq "^\(.\[K\)\?shellpack: N = 12" || fail "summary glued: $(cat -v tty.txt)"
}
case_warns_when_packings_are_rare() {
  # The warning is said under -q too, before the run (here made to fail at once).
  "$shellpack" jam -N 256 -q --max-tries 1 --fire-max-iterations 3 -o out.xyz 2>err.txt; [ $? = 1 ] || fail "status"
  grep -q "^shellpack: warning: at N = 256 only about 1 try in [0-9]* ends rattler-free and isostatic" err.txt ||
    fail "no warning: $(cat err.txt)"
  "$shellpack" jam -N 20 -q --csv out.csv 2>err.txt || fail "N = 20"
  [ ! -s err.txt ] || fail "warned at N = 20: $(cat err.txt)"
}
interrupted_case() {  # interrupted_case SIGNAL STATUS
  interrupt_run "$1" "$shellpack" jam -N 200 --seeds 1:2 -o 'out_{seed}.xyz' --csv out.csv
  local got=$?
  [ "$got" = "$2" ] || fail "exit $got after SIG$1, expected $2: $(cat interrupt.err)"
  [ "$(grep -v warning interrupt.err)" = "shellpack: interrupted" ] || fail "stderr: $(cat interrupt.err)"
  [ -z "$(ls -A | grep -v '^interrupt.err$')" ] || fail "left files: $(ls -A)"
}
case_interrupt_sigint() { interrupted_case INT 130; }
case_interrupt_sigterm() { interrupted_case TERM 143; }
case_seeds_resume() {
  "$shellpack" jam -N 12 --seeds 1:3 -o 'p_{seed}.xyz' --csv 'j_{seed}.csv' -q || fail "first run"
  rm p_2.xyz
  touch -d '2001-01-01' p_1.xyz j_1.csv p_3.xyz j_3.csv
  "$shellpack" jam -N 12 --seeds 1:3 -o 'p_{seed}.xyz' --csv 'j_{seed}.csv' --resume 2>err.txt || fail "resume"
  grep -q "shellpack: --resume: 2 of 3 seeds already done" err.txt || fail "stderr: $(cat err.txt)"
  [ -z "$(find p_1.xyz j_1.csv p_3.xyz j_3.csv -newer p_2.xyz)" ] || fail "a complete seed was redone"
  [ "$(grep -vc '^#' j_2.csv)" = 2 ] || fail "j_2.csv"
  expect_error 2 "--resume: needs --csv with {seed}" "$shellpack" jam -N 12 --seeds 1:3 -o 'out_{seed}.xyz' --resume
}
case_same_seed_same_bytes() {
  # XYZ, CSV and the structure tables of a seeded run: the same bytes on every run and with
  # 1 or 2 threads, the provenance (tool="..." in XYZ, # provenance= in CSV) aside. Each run
  # in its own folder, so that the file names the tables quote are the same.
  for run in a1 a2 b1 b2; do
    mkdir $run && (cd $run && t=${run#?} &&
      "$shellpack" jam -N 16 --seeds 1:2 --threads $t -o 'p_{seed}.xyz' --csv jam.csv -q &&
      "$shellpack" structure p_1.xyz p_2.xyz --threads $t -o rdf.csv --forces f.csv --summary s.csv -q) ||
      fail "run $run"
  done
  strip() { sed -e 's/ tool="[^"]*"//' -e '/^# provenance=/d' "$1"; }
  for f in jam.csv p_1.xyz p_2.xyz rdf.csv f.csv s.csv; do
    for other in a2 b1 b2; do
      cmp <(strip a1/$f) <(strip $other/$f) || fail "$other/$f differs from a1/$f"
    done
  done
  ! grep -q seconds a1/jam.csv || fail "wall time in the CSV by default"
  "$shellpack" jam -N 12 --timings --csv t.csv -q && grep -q ',seconds$' t.csv || fail "--timings"
}

run_cases "$@"
