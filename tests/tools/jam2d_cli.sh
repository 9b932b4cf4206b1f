#!/usr/bin/env bash
# jam2d as a user runs it. `jam2d_cli.sh --list` prints the cases; `jam2d_cli.sh CASE` runs one
# (ctest registers each). Needs CMP_BIN (the built programs).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
jam2d="$bin/jam2d"
if [ "${1:-}" != --list ]; then
  case $bin in /*) ;; *) jam2d="$PWD/$jam2d" ;; esac
fi
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=jam2d
enter_scratch_dir

# A hand-made packing of two cells in a box of 5 sigma (mother radius 1/2, tangent buds).
good_packing() {
  cat <<'XYZ'
4
Lattice="5 0 0 0 5 0 0 0 1" Properties=species:S:1:pos:R:3:radius:R:1:cell:I:1:lobe:I:1 pbc="T T F"
X 1 1 0 0.5 0 0
X 1.75 1 0 0.25 0 1
X 3 3 0 0.5 1 0
X 3 3.6 0 0.1 1 1
XYZ
}

case_help() {
  "$jam2d" --help >help.txt || fail "--help"
  for sub in grow moduli sweep chamber; do grep -q "$sub" help.txt || fail "--help lacks $sub"; done
  "$jam2d" grow --help >grow.txt || fail "grow --help"
  for opt in --box --seed --dphi --P0 --packing --csv --trajectory --every --contact --dt0 --fixed-step; do
    grep -q -- "$opt" grow.txt || fail "grow --help lacks $opt"
  done
  "$jam2d" sweep --help >sweep.txt || fail "sweep --help"
  for opt in --box --seeds --dphi --P0 --threads; do grep -q -- "$opt" sweep.txt || fail "sweep --help lacks $opt"; done
  "$jam2d" --version | grep -Eq "^jam2d [0-9]" || fail "--version"
}

case_grow_writes_table_and_packing() {
  "$jam2d" grow --box 4 --seed 3 -o jammed.xyz -q >growth.csv || fail "grow"
  grep -q "^step,time,dt,cells,phi,pressure,Z,f_u,rattlers,mean_rate,energy_per_cell,rejected,fire_iterations$" growth.csv ||
    fail "growth header: $(grep -v '^#' growth.csv | head -1)"
  grep -q "^# units=lengths sigma" growth.csv || fail "units line"
  grep -q '^# provenance=jam2d ' growth.csv || fail "provenance"
  head -2 jammed.xyz | tail -1 | grep >/dev/null 'pbc="T T F"' || fail "pbc"
  head -2 jammed.xyz | tail -1 | grep >/dev/null 'Properties=species:S:1:pos:R:3:radius:R:1:cell:I:1:lobe:I:1:orientation:R:1:pressure:R:1:contacts:I:1' ||
    fail "properties: $(head -2 jammed.xyz | tail -1)"
  cells=$(grep -v '^#' growth.csv | tail -1 | cut -d, -f4)
  [ "$(head -1 jammed.xyz)" -eq $((2 * cells)) ] || fail "one row per lobe"
  # The last row is jammed: tol <= V/(kN) <= 2 tol.
  grep -v '^#' growth.csv | tail -1 | awk -F, '{ exit !($11 >= 1e-16 && $11 <= 2e-16) }' || fail "not in the jamming window"
}

case_ase_reads_packing() {
  "$jam2d" grow --box 4 --seed 2 -o jammed.xyz -q --csv '' || fail "grow"
  /usr/bin/python3 - <<'PY' || fail "ASE"
import ase.io
a = ase.io.read("jammed.xyz")
assert list(a.pbc) == [True, True, False], a.pbc
assert abs(a.cell[0][0] - 4) < 1e-12
assert set(a.arrays["lobe"]) <= {0, 1}
assert len(a) == 2 * (max(a.arrays["cell"]) + 1)
PY
}

case_moduli_of_grown_packing() {
  "$jam2d" grow --box 4.5 --seed 7 --dphi 0.01 -o pack.xyz -q --csv '' || fail "grow"
  "$jam2d" moduli pack.xyz -o moduli.csv || fail "moduli"
  grep -q "^file,frame,cells,box,phi,pressure,pressure_xx,pressure_yy,pressure_xy,B,G,Z,Z_iso,f_u,rattlers,contacts,energy_per_cell,relaxed$" moduli.csv ||
    fail "moduli header"
  grep -v '^#' moduli.csv | tail -1 | awk -F, '{ exit !($10 > 0 && $6 > 0 && $12 >= $13 - 1e-9) }' || fail "B, P, Z: $(tail -1 moduli.csv)"
  "$jam2d" moduli - <pack.xyz >again.csv || fail "moduli from stdin"
  diff <(grep -v '^#' moduli.csv | cut -d, -f3-) <(grep -v '^#' again.csv | cut -d, -f3-) || fail "stdin differs"
}

case_sweep_same_on_one_and_two_threads() {
  "$jam2d" sweep --box 4 --seeds 1:4 --dphi 0,0.01 --P0 inf,0.001 -q --threads 1 >one.csv || fail "1 thread"
  "$jam2d" sweep --box 4 --seeds 1:4 --dphi 0,0.01 --P0 inf,0.001 -q --threads 2 >two.csv || fail "2 threads"
  same_lines "thread count changes the table" '^# provenance' one.csv two.csv
  [ "$(grep -vc '^#' one.csv)" -eq 17 ] || fail "one row per seed, P0 and dphi (+ header)"
}

# Fig. 3.3 in miniature: without feedback the seed means of Z - Z_J and G rise with P, as a power
# between 0.3 and 0.8 from dphi = 0.01 to 0.1 (4 packings of 8 sigma; the README's fit at 15 sigma
# over 100 packings gives 1/2 within 0.1). Catches G or Z - Z_J constant or linear in P.
case_sweep_dZ_and_G_rise_about_as_sqrt_P() {
  "$jam2d" sweep --box 8 --seeds 1:4 --dphi 0,0.01,0.1 --P0 inf -q >s.csv || fail "sweep"
  head -7 s.csv | grep >/dev/null '^seed,P0,dphi,phi_J,cells,box,phi,pressure,.*,B,G,Z,' || fail "columns moved: $(grep ^seed s.csv)"
  local slopes
  slopes=$(awk -F, '/^#/ || $1 == "seed" { next }
    $3 == 0 { zj[$1] = $14; next }
    { k = ($3 < 0.05) ? 1 : 2; P[k] += $8; dZ[k] += $14 - zj[$1]; G[k] += $13 }
    END { if (P[1] > 0 && dZ[1] > 0 && G[1] > 0 && P[2] > P[1]) { l = log(P[2] / P[1]); print log(dZ[2] / dZ[1]) / l, log(G[2] / G[1]) / l } }' s.csv)
  [ -n "$slopes" ] || fail "non-positive means at dphi = 0.01 or P not rising"
  echo "$slopes" | awk '{ exit !($1 >= 0.3 && $1 <= 0.8 && $2 >= 0.3 && $2 <= 0.8) }' ||
    fail "log-log slopes of Z - Z_J and G against P: $slopes (expected 0.3-0.8)"
}

case_bad_packing_lobe_missing() {
  good_packing | sed '5d; 1s/4/3/' >p.xyz
  expect_error 2 "p.xyz:5: cell 1 has a bud row but no mother row" "$jam2d" moduli p.xyz -o out.csv
}
case_bad_packing_cell_three_times() {
  { good_packing | sed '1s/4/5/'; echo "X 1 1 0 0.5 0 0"; } >p.xyz
  expect_error 2 "p.xyz:7: cell 0 appears again as a mother" "$jam2d" moduli p.xyz -o out.csv
}
case_bad_packing_bud_larger_than_mother() {
  good_packing | sed 's/^X 1.75 1 0 0.25 0 1$/X 2.25 1 0 0.75 0 1/' >p.xyz
  expect_error 2 "p.xyz:4: bud radius must lie in \[0, 1/2\] (not larger than its mother), got 0.75" "$jam2d" moduli p.xyz -o out.csv
}
case_bad_packing_box() {
  good_packing | sed 's/Lattice="5 0 0 0 5/Lattice="0 0 0 0 0/' >p.xyz
  expect_error 2 "p.xyz:2: the box must have positive sides" "$jam2d" moduli p.xyz -o out.csv
}
case_bad_box_option() {
  expect_error 2 "--box: must be positive, got '-3'" "$jam2d" grow --box -3 -o out.xyz --csv out.csv
}
case_bad_P0() {
  expect_error 2 "--P0: P0 must be positive (inf for no feedback), got '0'" "$jam2d" grow --box 4 --P0 0 -o out.xyz --csv out.csv
  expect_error 2 "--P0: P0 must be positive" "$jam2d" sweep --box 4 --seeds 1:2 --P0 inf,-0.1 -o out.csv
}
case_chamber_writes_series_and_frames() {
  "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --time 3 --every 0.5 --frame-every 1 --seed 2 -q \
    -o run.xyz >series.csv || fail "chamber"
  grep -q "^time,steps,cells,chamber_cells,left,pressure_walls,pressure_virial,growth_rate,c_P,energy,max_force$" series.csv ||
    fail "chamber columns"
  [ "$(grep -vc '^#' series.csv)" = 8 ] || fail "7 rows (t = 0, 0.5, ..., 3) and the header"
  grep -q "^# mobility=2000$" series.csv || fail "parameters in the meta lines"
  /usr/bin/python3 - <<'PY' || fail "ASE reads the chamber's frames"
import ase.io
frames = ase.io.read("run.xyz", index=":")
assert len(frames) == 4, len(frames)  # t = 0, 1, 2, 3
a = frames[-1]
assert list(a.pbc) == [False, False, False], a.pbc
assert abs(a.cell[0][0] - 4) < 1e-12 and abs(a.cell[1][1] - 7) < 1e-12  # width, height + channel
for column in ("radius", "cell", "lobe", "orientation", "force", "pressure", "contacts"):
    assert column in a.arrays, column
assert len(a) == 2 * (max(a.arrays["cell"]) + 1)
assert len(frames[-1]) > len(frames[0])
PY
  # Same seed, same bytes (the provenance line aside), on one thread or two.
  OMP_NUM_THREADS=1 "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --time 3 --every 0.5 --seed 2 -q >one.csv ||
    fail "one thread"
  OMP_NUM_THREADS=2 "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --time 3 --every 0.5 --seed 2 -q >two.csv ||
    fail "two threads"
  same_lines "same seed, other bytes" provenance series.csv one.csv
  cmp one.csv two.csv || fail "one thread and two give other bytes"
}
case_chamber_bad_options_all_at_once() {
  "$jam2d" chamber --width 4 --outlet 5 --mobility -1 --csv out.csv 2>stderr.txt
  [ $? = 2 ] || fail "two bad options: exit status"
  grep -q "^jam2d: --outlet: must be narrower than the chamber's wall (--width)$" stderr.txt || fail "--outlet"
  grep -q "^jam2d: --mobility: must be positive$" stderr.txt || fail "--mobility, in the same run"
  expect_error 2 "--height: must be at least 1 sigma" "$jam2d" chamber --height 0 --csv out.csv
  expect_error 2 "--dt: must be at most 0.546 / mobility" "$jam2d" chamber --dt 1e-3 --csv out.csv
  expect_error 2 "--integrator: unknown integrator 'rk4'" "$jam2d" chamber --integrator rk4 --csv out.csv
  [ ! -e out.csv ] || fail "a refused run wrote out.csv"
}
case_chamber_resumed_run_is_byte_identical() {
  local args="chamber --width 4 --height 5 --mobility 2e3 --every 0.1 --seed 2 -o run.xyz --csv run.csv --checkpoint run.ckpt"
  mkdir whole stopped longer
  (cd whole && "$jam2d" $args --time 3 -q) || fail "whole run"
  (cd stopped && "$jam2d" $args --time 3 --stop-after 1.45 -q) || fail "stopped run"
  [ -e stopped/run.ckpt ] && [ ! -e stopped/run.csv ] || fail "a stopped run leaves its checkpoint and no outputs"
  (cd stopped && "$jam2d" $args --time 3 --resume run.ckpt -q) || fail "resume"
  cmp whole/run.csv stopped/run.csv || fail "resumed series differs"
  cmp whole/run.xyz stopped/run.xyz || fail "resumed frames differ"
  # A finished run continues to a longer --time as if it had been asked for at once.
  (cd longer && "$jam2d" $args --time 4 -q) || fail "longer run"
  (cd whole && "$jam2d" $args --time 4 --resume run.ckpt -q) || fail "continue"
  same_lines "continued series differs" provenance whole/run.csv longer/run.csv
  # Another geometry, a changed byte: one line, exit 2, nothing written.
  cd stopped
  expect_error 2 "run.ckpt: the checkpoint is of another run: width=4 there, 4.5 here" \
    "$jam2d" chamber --width 4.5 --height 5 --mobility 2e3 --every 0.1 --seed 2 --time 3 --csv out.csv --checkpoint run.ckpt --resume run.ckpt
  printf 'x' | dd of=run.ckpt bs=1 seek=3000 conv=notrunc 2>/dev/null
  expect_error 2 "run.ckpt: checkpoint damaged" \
    "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --every 0.1 --seed 2 --time 3 --csv out.csv --checkpoint run.ckpt --resume run.ckpt
}
case_avalanches_of_a_chamber_run() {
  "$jam2d" chamber --width 4 --height 5 --mobility 2e3 --time 6 --every 0.02 --seed 4 -q >series.csv || fail "chamber"
  "$jam2d" avalanches series.csv --distribution dist.csv >drops.csv || fail "avalanches"
  grep -q "^event,start,end,peak_time,peak,base_time,base,drop,rise_rate,drop_rate,cells$" drops.csv || fail "columns"
  for key in mean_pressure events mean_drop drop_over_rise_rate tail_scale_over_mean_drop mobility; do
    grep -q "^# $key=" drops.csv || fail "no $key"
  done
  /usr/bin/python3 - <<'PY' || fail "events add up"
import csv
rows = [r for r in csv.DictReader(l for l in open("drops.csv") if not l.startswith("#"))]
series = [r for r in csv.DictReader(l for l in open("series.csv") if not l.startswith("#"))]
assert len(rows) >= 3, len(rows)
assert all(float(r["drop"]) >= 0 and float(r["peak"]) >= float(r["base"]) for r in rows)
# Every cell that left after the first outflow belongs to one event.
assert sum(int(r["cells"]) for r in rows) == int(series[-1]["left"]), (sum(int(r["cells"]) for r in rows), series[-1]["left"])
PY
  # From stdin too.
  "$jam2d" avalanches - <series.csv >stdin.csv || fail "stdin"
  same_lines "stdin gives other events" '^# \(provenance\|input\)=' drops.csv stdin.csv
}
case_avalanches_bad_series() {
  printf 'time,left,pressure_walls\n0,0,0.1\n0.5,1,0.2\n0.5,2,0.1\n' >s.csv
  expect_error 2 "s.csv:4: time must increase" "$jam2d" avalanches s.csv -o out.csv
  printf 'time,left\n0,0\n' >t.csv
  expect_error 2 "t.csv:1: .*pressure_walls" "$jam2d" avalanches t.csv -o out.csv
}
case_unknown_option() {
  expect_error 2 "--frobnicate" "$jam2d" grow --box 4 --frobnicate -o out.xyz --csv out.csv
}

run_cases "$@"
