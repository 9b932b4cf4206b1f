#!/usr/bin/env bash
# Issue 58 (reliability, third round), items 1, 3, 5 and 7: option values checked against what
# they mean (thread counts, scales), a finished table kept when a secondary output fails,
# degenerate fits refused, and output names (NAME_MAX, templates in folders) checked before
# any work. `reliability_round3.sh --list` prints the cases; `reliability_round3.sh CASE` runs
# one (ctest registers each). Needs CMP_BIN and CMP_SRC.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
lbflow="$bin/lbflow"
percolate="$bin/percolate"
shellpack="$bin/shellpack"
rndmesh="$bin/rndmesh"
kcfit="$bin/kcfit"
jam2d="$bin/jam2d"
sc="$src/data/percolate/simple_cubic_4x4x4.xyz"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/compress_start.sh"
export OMP_NUM_THREADS=1
enter_scratch_dir

# bounded TOOL STATUS PATTERN cmd...: within 20 s of CPU time and 300 MB, one line, no output left.
bounded() { expect_bounded 20 300000 "$@"; }
# rows CSV: its data rows (below the header).
rows() { grep -v '^#' "$1" | tail -n +2 | wc -l; }

# --- item 1: --threads against what the machine and OpenMP allow, before any work ---
case_threads_beyond_the_machine_refused() {
  local bound=$((64 * $(nproc)))
  # libgomp segfaulted at 100000 and failed "Thread creation failed" at 40000.
  for n in 100000 40000 2147483647; do
    bounded rndmesh 2 "--threads: must lie in \[0, [0-9]*\] (64 per core of this machine's [0-9]*), got '$n'" \
      "$rndmesh" random -n 20 -o out.off --threads "$n"
  done
  cluster_vtk
  printf 'porosity,permeability\n0.2,1\n0.3,2\n0.4,3\n0.5,5\n' >k.csv
  bounded percolate 2 "--threads: must lie in" "$percolate" "$sc" --delta 0.1 -o out.vtk --threads 100000
  bounded lbflow 2 "--threads: must lie in" "$lbflow" c.vtk -o out.csv --threads 100000
  bounded kcfit 2 "--threads: must lie in" "$kcfit" k.csv --model power -o out.csv --threads 100000
  bounded jam2d 2 "--threads: must lie in" "$jam2d" moduli x.xyz -o out.csv --threads 100000
  bounded shellpack 2 "--threads: must lie in" "$shellpack" jam -N 12 -o out.xyz --threads 100000
  bounded shellpack 2 "--threads: must lie in" "$shellpack" analyze x.off -o out.csv --threads 100000
  bounded rndmesh 2 "--threads: must lie in" "$rndmesh" stats x.off -o out.csv --threads 100000
  # The bound itself is accepted (a few threads more than cores is legitimate), and OpenMP's own
  # limit lowers it.
  "$rndmesh" random -n 20 --sweeps 1 --anneals 1 -o r.off -q --threads "$bound" || fail "--threads $bound refused"
  OMP_THREAD_LIMIT=3 bounded rndmesh 2 "--threads: must lie in \[0, 3\] (OpenMP's thread limit, OMP_THREAD_LIMIT=3), got '4'" \
    "$rndmesh" random -n 20 -o out.off --threads 4
}

# --- item 1: --scale whose spheres are larger than the box ---
case_scale_beyond_the_box_refused() {
  # 1e3 ran for minutes, 1e18 ended in std::bad_alloc (134), 1e20-1e100 wrote porosity 0.9999.
  for s in 1e3 1e18 1e20 1e100; do
    bounded percolate 2 "--scale $s: the largest sphere's radius would be .*, more than half the box's diagonal 3.464 (the sphere covers the whole box.*): at most 8.66 for .*simple_cubic_4x4x4.xyz" \
      "$percolate" "$sc" --delta 0.1 --scale "$s" --csv out.csv
  done
  bounded percolate 2 "--scale 8.7: " "$percolate" "$sc" --delta 0.1 --scale 1,8.7 --csv out.csv
  # lbflow's exact walls read the packing through the same reader: 1e30 wrote a porosity of 3.99e90.
  bounded lbflow 2 "--scale 1e+30: the largest sphere's radius would be" "$lbflow" "$sc" --delta 0.25 --scale 1e30 -o out.csv
  # The bound itself is a valid run: every voxel solid.
  "$percolate" "$sc" --delta 0.5 --scale 8.66 -q >p.csv 2>/dev/null || fail "scale 8.66"
  [ "$(col p.csv porosity_voxels)" = 0 ] || fail "not solid: $(cat p.csv)"
}

# --- item 1: steps an option implies, and messages that blame the option ---
case_jam2d_steps_bounded_before_any_work() {
  # both ran without end
  bounded jam2d 2 "--mobility: 1e+12 with --time 0.2 implies .* time steps of .* (the integrator's stability limit / (20 mobility)): more than 1e+10; lower --time or --mobility" \
    "$jam2d" chamber --time 0.2 --mobility 1e12 --csv out.csv
  bounded jam2d 2 "--dt: 1e-12 with --time 200 implies 2e+14 time steps" "$jam2d" chamber --time 200 --dt 1e-12 --csv out.csv
  bounded jam2d 2 "--dt0: must lie in (0, 0.1\] (a step grows each cell by dt_0 gamma_0 of its size), got '1e308'" \
    "$jam2d" grow --box 4 --dt0 1e308 -o out.xyz
}
case_shell_pressure_and_analyze_d0_name_the_option() {
  "$rndmesh" icosa --level 2 -o cell.off -q || fail "rndmesh"
  # said "FIRE: mass must be positive"
  bounded shellpack 2 "--pressure: must be at most Young's modulus E = 1 in magnitude .*, got '1e+308'" \
    "$shellpack" shell --mesh cell.off --pressure 1e308 -o out.off
  # said "shells 0 and 1 have the same centre (a duplicated shell)"
  bounded shellpack 2 "--d0 1e+308: larger than the box of .*octahedron_packing.off" \
    "$shellpack" analyze "$src/tests/data/io/octahedron_packing.off" --d0 1e308 -o out.csv
}

# --- item 3: a finished table kept when a secondary output fails ---
case_percolate_table_kept_when_the_image_fails() {
  [ -w /dev/full ] || fail "no /dev/full"
  "$percolate" "$sc" --delta 0.1 --csv pf.csv -o /dev/full -q 2>err.txt
  local status=$?
  [ "$status" -eq 2 ] || fail "exit $status: $(cat err.txt)"
  grep -q "^percolate: /dev/full: write error: No space left on device (the table was written: pf.csv)$" err.txt ||
    fail "message: $(cat err.txt)"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "not one line: $(cat err.txt)"
  [ "$(rows pf.csv)" -eq 1 ] || fail "the table was lost: $(ls -a)"
  # every run's row, each image tried
  ln -s /dev/full c_0.1.vtk && ln -s /dev/full c_0.2.vtk
  "$percolate" "$sc" --delta 0.1,0.2 --csv pf2.csv -o 'c_{delta}.vtk' -q 2>err.txt
  [ $? -eq 2 ] && grep -q "(the table was written: pf2.csv; 1 more output failed)" err.txt || fail "two: $(cat err.txt)"
  [ "$(rows pf2.csv)" -eq 2 ] || fail "rows lost with two deltas"
}
case_compress_table_kept_when_a_packing_fails() {
  [ -w /dev/full ] || fail "no /dev/full"
  make_start
  "$shellpack" compress jammed.xyz --mesh cell.off --contact hertz-vertices --step 0.1 --ftol 1e-4 -q \
    --phi 0.5 --csv cf.csv -o /dev/full 2>err.txt
  local status=$?
  [ "$status" -eq 2 ] || fail "exit $status: $(cat err.txt)"
  grep -q "^shellpack: /dev/full: write error: .* (the table was written: cf.csv)$" err.txt || fail "message: $(cat err.txt)"
  [ "$(rows cf.csv)" -ge 1 ] || fail "the table was lost: $(ls -a)"
}
case_shell_and_jam_tables_kept_when_the_other_output_fails() {
  [ -w /dev/full ] || fail "no /dev/full"
  "$rndmesh" icosa --level 2 -o cell.off -q || fail "rndmesh"
  "$shellpack" shell --mesh cell.off --pressure 0.01 --steps 2 --csv sh.csv -o /dev/full -q 2>err.txt
  [ $? -eq 2 ] && grep -q "/dev/full: write error.*(the table was written: sh.csv)" err.txt || fail "shell: $(cat err.txt)"
  [ "$(rows sh.csv)" -ge 1 ] || fail "shell: the table was lost"
  "$shellpack" jam -N 12 -o /dev/full --csv jam.csv -q 2>err.txt
  [ $? -eq 2 ] && grep -q "/dev/full: write error.*(the table was written: jam.csv)" err.txt || fail "jam: $(cat err.txt)"
  [ "$(rows jam.csv)" -eq 1 ] || fail "jam: the table was lost"
}

# --- item 5: degenerate fits refused, exit 2 naming the reason; nothing non-finite written ---
case_kcfit_degenerate_fits_refused() {
  cli_tool=kcfit
  printf 'porosity,permeability\n0.2,1\n' >one.csv
  expect_error 2 "one.csv: 1 point for 3 free parameters of model kc-percolation: a fit needs at least 4" \
    "$kcfit" one.csv --model kc-percolation -o out.csv
  printf 'porosity,permeability\n0.2,1\n0.3,2\n0.4,3\n' >three.csv
  expect_error 2 "three.csv: 3 points for 3 free parameters" "$kcfit" three.csv --model kc-percolation -o out.csv
  printf 'porosity,permeability\n0.2,1\n0.3,1\n0.4,1\n0.5,1\n0.6,1\n' >flat.csv
  expect_error 2 "flat.csv: no spread in y: all 5 points have y = 1 (x: porosity, y: permeability)" \
    "$kcfit" flat.csv --model kc-percolation -o out.csv
  expect_error 2 "flat.csv: no spread in y" "$kcfit" flat.csv --model power -o out.csv
  printf 'porosity,permeability\n0.3,1\n0.3,2\n0.3,3\n0.3,4\n0.3,5\n' >samex.csv
  expect_error 2 "samex.csv: no spread in x: all 5 points have x = 0.3" "$kcfit" samex.csv --model kc-percolation -o out.csv
  # per group: the group is named
  printf 'delta,porosity,permeability\n1,0.2,1\n1,0.3,2\n1,0.4,3\n1,0.5,5\n2,0.2,1\n2,0.3,1\n2,0.4,1\n2,0.5,1\n' >g.csv
  expect_error 2 "g.csv: delta=2: no spread in y" "$kcfit" g.csv --model power --group-by delta -o out.csv
  # a fit that is refused writes nothing; one that is accepted writes only finite statistics
  printf 'porosity,permeability\n0.2,1\n0.3,2.1\n0.4,2.9\n0.5,4.2\n0.6,5\n' >ok.csv
  "$kcfit" ok.csv --model power -o fit.csv -q || fail "a good fit refused"
  ! grep -qi 'nan\|inf' <(grep '^# \(r2\|chi2_dof\|aic\|rss\)=' fit.csv) || fail "non-finite statistic: $(cat fit.csv)"
}
case_kcfit_sigmoid_outcomes_are_0_or_1() {
  cli_tool=kcfit
  printf 'porosity,percolates\n0.1,0\n0.2,0\n0.3,2\n0.25,1\n0.15,0\n0.35,1\n' >two.csv
  expect_error 2 "two.csv:4: percolates holds 0/1 outcomes (model sigmoid), got 2" "$kcfit" two.csv --model sigmoid -o out.csv
  printf 'porosity,probability\n0.1,0\n0.2,0.2\n0.3,1.5\n0.4,1\n' >p.csv
  expect_error 2 "p.csv:4: probability must lie in \[0, 1\] for model sigmoid (a probability), got 1.5" \
    "$kcfit" p.csv --model sigmoid -o out.csv
  printf 'porosity,percolates\n0.1,1\n0.2,1\n0.3,1\n' >ones.csv
  expect_error 2 "ones.csv: no spread in y: all 3 outcomes are 1" "$kcfit" ones.csv --model sigmoid -o out.csv
}

# --- item 7: output names ---
case_long_output_names_fit_name_max() {
  local max
  max=$(getconf NAME_MAX .)
  cluster_vtk
  # 251-255 bytes failed with "File name too long" (the temporary is 12 bytes longer), lbflow's
  # only after the flow.
  for n in 243 251 255; do
    local name
    name=$(printf 'a%.0s' $(seq 1 $((n - 4)))).off
    [ "${#name}" -eq "$n" ] || fail "name of ${#name}"
    "$rndmesh" icosa --level 1 -o "$name" -q || fail "rndmesh -o of $n bytes"
    [ -s "$name" ] || fail "not written: $n bytes"
    local csv=${name%.off}.csv
    "$lbflow" c.vtk --refine 1 -q -o "$csv" || fail "lbflow -o of $n bytes"
    [ -s "$csv" ] || fail "lbflow: not written"
    rm -f "$name" "$csv"
  done
  ! ls -a | grep -q '\.tmp\.' || fail "a temporary left: $(ls -a)"
  # beyond NAME_MAX: refused before any work, under the option
  local long
  long=$(printf 'a%.0s' $(seq 1 $((max - 3)))).off
  cli_tool=lbflow expect_error 2 "--output: a*\.off: cannot write: File name too long (the name has $((max + 1)) bytes, the folder allows $max)" \
    "$lbflow" c.vtk --refine 1 -q -o "$long"
}
case_templates_expanded_before_their_folders_are_checked() {
  mkdir s1 s2
  "$rndmesh" random -n 20 --sweeps 1 --anneals 1 --seeds 1:2 -o 's{seed}/r.off' -q || fail "s{seed}/r.off refused"
  [ -s s1/r.off ] && [ -s s2/r.off ] || fail "not written: $(ls s1 s2)"
  # a folder one of the seeds names that does not exist: refused before any work, naming it
  cli_tool=rndmesh expect_error 2 "--output: s3/r.off (from s{seed}/r.off): cannot write: No such file or directory" \
    "$rndmesh" random -n 20 --seeds 1:3 -o 's{seed}/r.off'
  [ ! -e s1/out.off ] || fail "written"
  "$shellpack" jam -N 12 --seeds 1:2 -o 's{seed}/j.xyz' -q >/dev/null || fail "shellpack jam s{seed}/j.xyz refused"
  [ -s s2/j.xyz ] || fail "jam: not written"
  # percolate's {delta} and {scale} in a folder
  mkdir d0.1 d0.2
  "$percolate" "$sc" --delta 0.1,0.2 -o 'd{delta}/c.vtk' -q >/dev/null || fail "percolate d{delta}/c.vtk refused"
  [ -s d0.2/c.vtk ] || fail "percolate: not written"
  cli_tool=percolate expect_error 2 "--output: d0.3/c.vtk (from d{delta}/c.vtk): cannot write" \
    "$percolate" "$sc" --delta 0.1,0.3 -o 'd{delta}/c.vtk'
}

run_cases "$@"
