#!/usr/bin/env bash
# shellpack analyze as a user runs it: packing OFFs of icosphere shells on lattices (written
# here), their summary, tables, warnings and refusals. `shellpack_analyze.sh --list` prints the
# cases; `shellpack_analyze.sh CASE` runs one (ctest registers each). Needs CMP_BIN (and
# CMP_SRC, else the sources around this script).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
if [ "${1:-}" != --list ]; then
  case $bin in /*) ;; *) bin="$PWD/$bin" ;; esac
fi
shellpack="$bin/shellpack"
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
rndmesh="$bin/rndmesh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=shellpack
enter_scratch_dir

# pack OUT N A sc|fcc[-wrapped] "PERIODIC FLAGS" [KEY=VALUE lines...]: N^3 cubic cells of side
# A, one icosphere (42 vertices, radius 0.55) per lattice site, as a packing OFF (-wrapped:
# every vertex wrapped into the box, so shells are cut by its faces).
pack() {
  [ -f cell.off ] || "$rndmesh" icosa --level 2 -r 0.55 -o cell.off -q || fail "rndmesh"
  python3 - cell.off "$@" <<'PY' || fail "writing $1"
import sys, itertools
cell, out, n, a, kind, periodic = sys.argv[1:7]
extra = sys.argv[7:]
n, a = int(n), float(a)
lines = [l for l in open(cell) if l.strip() and not l.startswith('#')]
nv, nf = map(int, lines[1].split()[:2])
V = [list(map(float, l.split())) for l in lines[2:2 + nv]]
F = [list(map(int, l.split()[1:4])) for l in lines[2 + nv:2 + nv + nf]]
wrap = kind.endswith('-wrapped')  # vertices wrapped into the box: shells cut by its faces
kind = kind.replace('-wrapped', '')
basis = [(0, 0, 0)] if kind == 'sc' else [(0, 0, 0), (.5, .5, 0), (.5, 0, .5), (0, .5, .5)]
sites = [tuple(a * (c + b + .25) for c, b in zip(ijk, bb)) for ijk in itertools.product(range(n), repeat=3) for bb in basis]
L = n * a
with open(out, 'w') as o:
    o.write('OFF\n# box %r %r %r\n# periodic %s\n# shells %d %s\n' % (L, L, L, periodic, len(sites), ' '.join([str(nv)] * len(sites))))
    for e in extra: o.write('# %s\n' % e.replace('{K}', ' '.join(['0.5'] * len(sites))))
    o.write('%d %d 0\n' % (nv * len(sites), nf * len(sites)))
    for s in sites:
        for v in V: o.write('%r %r %r\n' % tuple((x + c) % L if wrap else x + c for x, c in zip(v, s)))
    for k in range(len(sites)):
        for f in F: o.write('3 %d %d %d\n' % tuple(i + k * nv for i in f))
PY
}
keys=("vertex_radius=0.06" "E=1" "nu=0.5" "P0=0.25" "turgor={K}" "bending=none")
run() { "$shellpack" analyze -q "$@"; }
col() { awk -F, -v c="$2" '/^#/ { next } !h { for (i = 1; i <= NF; i++) if ($i == c) k = i; h = 1; next } { print $k }' "$1"; }

case_help() {
  "$shellpack" analyze --help >help.txt || fail "--help"
  for opt in -o --rdf --shells --contacts --youngs-modulus --poisson-ratio --vertex-radius --d0 --p0 --wall-modulus --bin \
    --rmax --threads; do
    grep -q -- "$opt" help.txt || fail "--help lacks $opt"
  done
}
case_simple_cubic() {
  pack sc.off 3 1.0 sc "1 1 1" "${keys[@]}"
  run sc.off >out.csv 2>err.txt || fail "analyze: $(cat err.txt)"
  [ ! -s err.txt ] || fail "warnings on a complete packing: $(cat err.txt)"
  grep -q "^# provenance=shellpack .*analyze" out.csv || fail "provenance"
  grep -q "^file,particles,phi,phi_source,d0,d0_source,bending,contacts,Z,dZ,turgor_mean_P,turgor_mean_P0,turgor_cv,asphericity_mean_d02,delta_eps_mean,force_normal_mean_F,force_normal_cv,force_tangential_mean_F,mu_eff,wall_pressure_P,coverage,wall_pressure_over_coverage_P,voronoi_faces_mean$" out.csv || fail "header: $(cat out.csv)"
  [ "$(col out.csv particles)" = 27 ] || fail "particles"
  [ "$(col out.csv contacts)" = 81 ] || fail "contacts: $(col out.csv contacts)"
  [ "$(col out.csv Z)" = 6 ] || fail "Z: $(col out.csv Z)"
  [ "$(col out.csv voronoi_faces_mean)" = 6 ] || fail "Voronoi: $(col out.csv voronoi_faces_mean)"
  [ "$(col out.csv turgor_mean_P0)" = 2 ] || fail "turgor/P0: $(col out.csv turgor_mean_P0)"
  [ "$(col out.csv phi_source)" = shell_volumes ] || fail "phi_source"
  [ "$(col out.csv bending)" = none ] || fail "bending"
  [ -z "$(col out.csv wall_pressure_P)" ] || fail "a wall pressure without walls"
  awk -v f="$(col out.csv force_normal_mean_F)" 'BEGIN { exit !(f > 0) }' || fail "normal force"
}
case_wrapped_shells() {
  # Shells cut by the periodic faces are unwrapped along their edges (as percolate does): the
  # same numbers as when written whole.
  pack whole.off 2 1.4142135623730951 fcc "1 1 1" "${keys[@]}" "vertex_radius=0.1"
  pack cut.off 2 1.4142135623730951 fcc-wrapped "1 1 1" "${keys[@]}" "vertex_radius=0.1"
  run whole.off -o out_whole.csv && run cut.off -o out_cut.csv || fail "analyze"
  [ "$(col out_cut.csv Z)" = 12 ] || fail "Z of the cut shells: $(col out_cut.csv Z)"
  for c in phi Z force_normal_mean_F asphericity_mean_d02 voronoi_faces_mean; do
    awk -v a="$(col out_whole.csv $c)" -v b="$(col out_cut.csv $c)" \
      'BEGIN { d = a - b; if (d < 0) d = -d; s = a < 0 ? -a : a; exit !(d <= 1e-9 * s + 1e-15) }' ||
      fail "$c: $(col out_whole.csv $c) whole, $(col out_cut.csv $c) cut"
  done
}
case_tables() {
  pack fcc.off 2 1.4142135623730951 fcc "1 1 1" "${keys[@]}" "vertex_radius=0.1" "volume0={K}"  # the last R_v counts
  run fcc.off -o out.csv --rdf out_rdf.csv --shells out_shells.csv --contacts out_contacts.csv || fail "analyze"
  [ "$(col out.csv Z)" = 12 ] || fail "FCC Z: $(col out.csv Z)"
  [ "$(col out.csv voronoi_faces_mean)" = 12 ] || fail "FCC Voronoi: $(col out.csv voronoi_faces_mean)"
  [ "$(col out.csv phi_source)" = volume0 ] || fail "phi_source volume0"
  [ "$(col out.csv d0_source)" = volume0 ] || fail "d0_source volume0"
  [ "$(col out_shells.csv shell | wc -l)" = 32 ] || fail "shells rows"
  [ "$(col out_shells.csv contacts | sort -u)" = 12 ] || fail "contacts per shell"
  [ "$(col out_contacts.csv m | wc -l)" = 384 ] || fail "contact rows (both directions): $(col out_contacts.csv m | wc -l)"
  grep -q "^file,m,n,image_x,image_y,image_z,vertex_pairs,force_x_F,force_y_F,force_z_F,force_normal_F,force_tangential_F$" out_contacts.csv || fail "contacts header"
  grep -q "^file,r_d0,g,pairs$" out_rdf.csv || fail "rdf header"
  [ "$(col out_rdf.csv r_d0 | wc -l)" -gt 100 ] || fail "rdf rows"
}
case_several_files_and_threads() {
  pack a.off 2 1.0 sc "1 1 1" "${keys[@]}"
  pack b.off 2 1.4142135623730951 fcc "1 1 1" "${keys[@]}"
  run a.off b.off --threads 1 -o out1.csv --contacts out_c1.csv || fail "1 thread"
  run a.off b.off --threads 2 -o out2.csv --contacts out_c2.csv || fail "2 threads"
  [ "$(col out1.csv file | tr '\n' ' ')" = "a.off b.off " ] || fail "one row per file, in order"
  same_lines "1 and 2 threads differ" '^# provenance' out1.csv out2.csv
  same_lines "contacts differ" '^# provenance' out_c1.csv out_c2.csv
}
case_walls() {
  # Walls on x and y at 0 and L (z periodic): the outer shells press on them.
  pack walls.off 2 1.0 sc "0 0 1" "${keys[@]}"
  run walls.off >out.csv 2>err.txt || fail "analyze"
  awk -v p="$(col out.csv wall_pressure_P)" -v c="$(col out.csv coverage)" 'BEGIN { exit !(p > 0 && c > 0) }' ||
    fail "wall pressure and coverage: $(cat out.csv)"
  [ -z "$(col out.csv voronoi_faces_mean)" ] || fail "Voronoi columns in a walled box"
  [ "$(grep -c 'warning: walls.off: not periodic on every axis' err.txt)" = 1 ] || fail "one warning: $(cat err.txt)"
  expect_error 2 "walls.off: not periodic on every axis: no g(r) for --rdf" run walls.off -o out.csv --rdf out_rdf.csv
}
case_plates_pressure_over_coverage_near_turgor() {
  # Fig. 4.5b on one shell (scripts/tables/analyze_plates.sh, there at 2562 vertices): a
  # 642-vertex membrane squeezed between plates by shellpack shell; P / Theta (the mean
  # stress on the contact patch) is near Pi.
  "$rndmesh" icosa --level 4 -r 1 -o c4.off -q || fail "rndmesh"
  "$shellpack" shell --mesh c4.off -E 1 --nu 0.5 -t 0.02 --pressure 0.0025 --pressure-model volume --walls 2.1 \
    --squeeze 0.3 --squeeze-steps 3 -q -o squeezed.off >squeezed.csv || fail "shellpack shell"
  python3 "$src/scripts/data/plates_to_packing.py" squeezed.off squeezed.csv plates.off E=1 nu=0.5 vertex_radius=0.02 ||
    fail "packing"
  run plates.off >out.csv 2>/dev/null || fail "analyze"
  awk -v q="$(col out.csv wall_pressure_over_coverage_P)" -v t="$(col out.csv turgor_mean_P)" \
    'BEGIN { exit !(q > t && q < 1.1 * t) }' || fail "P/Theta not within 10 % above Pi: $(cat out.csv)"
}
case_missing_keys_warn() {
  pack bare.off 2 1.0 sc "1 1 1"
  run bare.off >out.csv 2>err.txt || fail "analyze"
  grep -q "warning: bare.off: no turgor= line" err.txt || fail "turgor warning: $(cat err.txt)"
  grep -q "warning: bare.off: no vertex_radius= or thickness= line" err.txt || fail "R_v warning: $(cat err.txt)"
  [ "$(wc -l <err.txt)" = 2 ] || fail "one line per missing thing: $(cat err.txt)"
  [ -z "$(col out.csv Z)$(col out.csv turgor_cv)" ] || fail "columns not empty"
  # Options fill in what the file lacks.
  run bare.off --vertex-radius 0.06 -E 1 >out.csv 2>err.txt || fail "with options"
  [ "$(col out.csv Z)" = 6 ] || fail "Z with --vertex-radius"
  expect_error 2 "bare.off: no vertex_radius= or thickness= line: give --vertex-radius for --contacts" \
    run bare.off -o out.csv --contacts out_c.csv
}
case_bad_input() {
  pack good.off 2 1.0 sc "1 1 1" "${keys[@]}"
  grep -v '^# box' good.off >nobox.off
  expect_error 2 "nobox.off:1: no '# box Lx Ly Lz' line: not a packing OFF" run nobox.off -o out.csv
  sed 's/^# E=1$/# E=abc/' good.off >badkey.off
  expect_error 2 "badkey.off:6: expected E= as a number, got 'abc'" run badkey.off -o out.csv
  sed 's/^# turgor=.*/# turgor=1 2/' good.off >badturgor.off
  expect_error 2 "badturgor.off:9: turgor= needs one number per shell (8), got 2" run badturgor.off -o out.csv
  printf '1\nLattice="2 0 0 0 2 0 0 0 2" Properties=species:S:1:pos:R:3:radius:R:1\nX 0 0 0 0.5\n' >s.xyz
  expect_error 2 "s.xyz:.*a packing OFF of shells" run s.xyz -o out.csv
  printf 'hello\n' >junk.txt
  expect_error 2 "junk.txt" run junk.txt -o out.csv
  expect_error 2 "at most one of them may be '-'" run good.off --rdf -
  expect_error 2 "good.off: R_v = 0.6: .*periodic box side .* is shorter than" run good.off --vertex-radius 0.6 -o out.csv
  # A bad file among good ones: nothing written.
  expect_error 2 "badkey.off:6:" run good.off badkey.off -o out.csv
}

run_cases "$@"
