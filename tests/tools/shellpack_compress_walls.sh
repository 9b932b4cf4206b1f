#!/usr/bin/env bash
# shellpack compress --walls (the rigid box of Fig. 4.5): 16 shells of 162 vertices spread to a
# dilute start and swept inward by rigid walls until the walls carry load.
# `shellpack_compress_walls.sh --list` prints the cases; `shellpack_compress_walls.sh CASE` runs
# one (ctest registers each). Needs CMP_BIN.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
if [ "${1:-}" != --list ]; then
  case $bin in /*) ;; *) bin="$PWD/$bin" ;; esac
fi
shellpack="$bin/shellpack"
rndmesh="$bin/rndmesh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=shellpack
source "$(dirname "${BASH_SOURCE[0]}")/../support/compress_start.sh"
enter_scratch_dir

# Coarse steps and a looser force tolerance keep each run to seconds.
walls() { "$shellpack" compress "${at:-.}/jammed.xyz" --mesh "${at:-.}/cell.off" --contact hertz-vertices --walls --step 0.1 --ftol 1e-4 -q "$@"; }
# row CSV PHI COLUMN: the value of COLUMN in the row at phi PHI.
row() { paste -d, <(col "$1" phi) <(col "$1" "$3") | awk -F, -v p="$2" '$1 == p { print $2 }'; }

case_walls_sweep_to_load() {
  make_start
  walls --phi 0.3,0.4 -o 'w_{phi}.off' >w.csv || fail "compress --walls"
  grep -q "^step,phi,.*,energy_hertz-walls_Ed3,energy_hertz-vertices_Ed3,wall_pressure_E,coverage,wall_pressure_over_coverage_E,residual,iterations,volume_updates,stop$" w.csv ||
    fail "header: $(grep -v '^#' w.csv | head -1)"
  [ "$(key w.csv walls)" = rigid ] && [ "$(key w.csv phi_start)" = 0.08 ] || fail "walls/phi_start lines"
  [ "$(col w.csv stop | sort -u)" = converged ] || fail "not converged: $(col w.csv stop)"
  # The dilute start, phi only grows, constant volume after every step.
  col w.csv phi | head -1 | awk '{ exit !($1 > 0.08 - 1e-12 && $1 < 0.08 + 1e-12) }' || fail "start phi $(col w.csv phi | head -1)"
  col w.csv phi | awk 'NR > 1 && $1 <= prev { exit 1 } { prev = $1 }' || fail "phi does not grow"
  col w.csv volume_error | awk '$1 > 1e-3 { exit 1 }' || fail "volume not held: $(col w.csv volume_error)"
  # The dilute approach is cheap: no FIRE iteration while the walls sweep shells that touch nothing.
  [ "$(col w.csv iterations | sed -n 3p)" -eq 0 ] || fail "iterations of step 2: $(col w.csv iterations | sed -n 3p)"
  for phi in 0.3 0.4; do
    f=w_$phi.off
    [ -s "$f" ] || fail "$f not written"
    grep -q "^# periodic 0 0 0$" "$f" && grep -q "^# shells 16 162 " "$f" || fail "$f: packing lines"
    [ "$(key "$f" walls)" = rigid ] || fail "$f: walls="
    for k in D0 phi E nu thickness vertex_radius P0 bending turgor volume0; do
      [ -n "$(key "$f" $k)" ] || fail "$f lacks # $k="
    done
    # Every vertex centre inside the walls (a vertex sphere presses into a wall by less than R_v).
    awk '/^# box/ { for (a = 0; a < 3; a++) L[a] = $(3 + a); next } /^#/ || /^OFF/ || NF == 0 { next }
         !n { n = $1; next }
         c < n { for (a = 0; a < 3; a++) if ($(a + 1) < 0 || $(a + 1) > L[a]) bad++; c++ }
         END { exit bad > 0 || c != 16 * 162 }' "$f" || fail "$f: a vertex outside the walls"
  done
  # The walls carry load at 0.4, and P / Theta is of the order of the mean turgor (Fig. 4.5b).
  P=$(row w.csv 0.4 wall_pressure_E); T=$(row w.csv 0.4 coverage); R=$(row w.csv 0.4 wall_pressure_over_coverage_E)
  Pi=$(row w.csv 0.4 turgor_mean_P0)
  awk -v p="$P" -v t="$T" -v r="$R" -v pi="$Pi" 'BEGIN { m = pi * 0.0025; exit !(p > 0 && t > 0.02 && r > 0.5 * m && r < 2 * m) }' ||
    fail "at phi 0.4: P $P, Theta $T, P/Theta $R, <Pi>/Pi0 $Pi"
  # shellpack analyze finds the same wall load in the packing OFF (one definition, lib/shell/wall_load).
  "$shellpack" analyze w_0.4.off -q >a.csv 2>/dev/null || fail "analyze w_0.4.off"
  [ "$(col a.csv wall_pressure_P)" = "$P" ] && [ "$(col a.csv coverage)" = "$T" ] ||
    fail "analyze: P $(col a.csv wall_pressure_P), Theta $(col a.csv coverage); compress: $P, $T"
}

# One run on 1 thread against a run stopped after 9 box steps and resumed on 2 threads.
case_walls_resume_and_threads_same_bytes() {
  make_start
  mkdir -p whole parts
  (cd whole && at=.. walls --phi 0.3 -o 'p_{phi}.off' --checkpoint run.chk --threads 1 >c.csv) || fail "uninterrupted run"
  (cd parts && at=.. walls --phi 0.3 -o 'p_{phi}.off' --checkpoint run.chk --threads 1 --stop-after-steps 9 >/dev/null) ||
    fail "first part"
  [ -s parts/run.chk ] && [ ! -e parts/p_0.3.off ] || fail "the first part should stop before the first target"
  (cd parts && "$shellpack" compress --resume run.chk --threads 2 -q >c.csv) || fail "resume"
  cmp -s whole/c.csv parts/c.csv || fail "CSV differs after resuming: $(diff whole/c.csv parts/c.csv | head -5)"
  for f in p_0.3.off; do cmp -s whole/$f parts/$f || fail "$f differs after resuming"; done
  cmp -s whole/run.chk parts/run.chk || fail "final checkpoints differ"
}

# A resume that names a target the checkpoint has passed skips it (not a box that grows).
case_walls_resume_with_other_targets() {
  make_start
  walls --phi 0.3 --checkpoint run.chk --stop-after-steps 9 >first.csv || fail "first part"
  p9=$(col first.csv phi | tail -1)
  "$shellpack" compress --resume run.chk --phi 0.2,0.3 -o 'q_{phi}.off' -q >c.csv || fail "resume with --phi 0.2,0.3"
  [ ! -e q_0.2.off ] && [ -s q_0.3.off ] || fail "packings: $(ls q_*)"
  col c.csv phi | awk 'NR > 1 && $1 <= prev { exit 1 } { prev = $1 }' || fail "phi does not grow after $p9"
}

case_walls_bad_start() {
  make_start
  expect_error 2 "--phi-start: must lie in (0, 1)" walls --phi 0.5 --phi-start 0
  expect_error 2 "--phi-start: must lie in (0, 1)" walls --phi 0.5 --phi-start -0.1
  expect_error 2 "--phi: the targets must lie above --phi-start" walls --phi 0.05,0.5 -o 'o_{phi}.off'
  expect_error 2 "--wall-modulus: needs --walls" "$shellpack" compress jammed.xyz --mesh cell.off --phi 0.7 --wall-modulus 10
  # Above what the jammed shells allow: refused after the inflation, before any output.
  expect_error 2 "--phi-start 0.7.* must lie below the volume fraction of the inflated jammed shells" \
    walls --phi 0.8 --phi-start 0.7 -o o.off --csv o.csv
  [ ! -e o.off ] && [ ! -e o.csv ] || fail "output after a refused start"
}

run_cases "$@"
