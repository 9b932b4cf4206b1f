#!/usr/bin/env bash
# shellpack shell and bench-mechanics as a user runs them. `shellpack_shell_cli.sh --list`
# prints the cases; `shellpack_shell_cli.sh CASE` runs one (ctest registers each). Needs CMP_BIN.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
if [ "${1:-}" != --list ]; then
  case $bin in /*) ;; *) bin="$PWD/$bin" ;; esac
fi
shellpack="$bin/shellpack"
rndmesh="$bin/rndmesh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=shellpack
enter_scratch_dir

# A small outward icosahedral sphere of radius 1 (162 vertices), and variants of it.
make_cell() { "$rndmesh" icosa --level 3 -r 1 -o cell.off -q || fail "rndmesh"; }
# off_edit SCRIPT IN OUT: rewrite the face lines of an OFF with a python expression over
# V (list of [x, y, z]) and F (list of [i, j, k]).
off_edit() {
  python3 - "$1" "$2" "$3" <<'PY'
import sys
script, src, dst = sys.argv[1:]
lines = [l for l in open(src) if l.strip() and not l.startswith('#')]
nv, nf = map(int, lines[1].split()[:2])
V = [list(map(float, l.split())) for l in lines[2:2 + nv]]
F = [list(map(int, l.split()[1:4])) for l in lines[2 + nv:2 + nv + nf]]
exec(script)
with open(dst, 'w') as o:
    o.write('OFF\n%d %d 0\n' % (len(V), len(F)))
    for v in V: o.write('%r %r %r\n' % tuple(v))
    for f in F: o.write('3 %d %d %d\n' % tuple(f))
PY
}
run() { "$shellpack" shell -q -E 25 --nu 0.3 -t 0.05 "$@"; }
col() { awk -F, -v c="$2" '/^#/ { next } !h { for (i = 1; i <= NF; i++) if ($i == c) k = i; h = 1; next } { print $k }' "$1"; }

case_help() {
  "$shellpack" shell --help >help.txt || fail "--help"
  for opt in --mesh --model --bending --pressure-model -E --nu -t --pressure --steps --walls --squeeze --vertex-radius \
    --ftol --list-models -o --csv --threads; do
    grep -q -- "$opt" help.txt || fail "--help lacks $opt"
  done
  "$shellpack" bench-mechanics --help | grep >/dev/null "plates-contact" || fail "bench-mechanics --help"
}
case_list_models() {
  "$shellpack" shell --list-models >models.csv || fail "--list-models"
  for m in stretching,svk stretching,springs-kot stretching,springs-van-gelder stretching,springs-seung-nelson \
    bending,hinge bending,hinge-uniform pressure,turgor pressure,volume contact,hertz-walls contact,hertz-vertices; do
    grep -q "^$m," models.csv || fail "--list-models lacks $m"
  done
}
case_inflate() {
  make_cell
  run --mesh cell.off --pressure 0.1 --steps 3 -o out.off >inflate.csv || fail "inflate"
  [ "$(grep -vc '^#' inflate.csv)" -eq 4 ] || fail "3 rows expected: $(cat inflate.csv)"
  grep -q "^step,stage,pressure_P,turgor_P,gap_u,volume_u3,area_u2,.*,energy_svk_W,energy_turgor_W,iterations,volume_updates,stop,residual," inflate.csv || fail "header"
  grep -q "^# units=" inflate.csv || fail "units line"
  [ "$(col inflate.csv stop | sort -u)" = converged ] || fail "not converged: $(col inflate.csv stop)"
  col inflate.csv volume_u3 | awk 'NR > 1 && $1 <= prev { exit 1 } { prev = $1 }' || fail "volume does not grow"
  head -1 out.off | grep >/dev/null '^OFF' || fail "no OFF written"
  grep -q "^# shellpack .*shell" out.off || fail "OFF lacks provenance"
  # The mesh out goes back in: inflating the inflated shell again by nothing changes nothing.
  run --mesh out.off --pressure 0 >again.csv || fail "rerun on the output"
}
case_squeeze() {
  make_cell
  run --mesh cell.off --pressure 0.1 --walls 2.3 --squeeze 0.3 --squeeze-steps 3 --pressure-model volume >sq.csv || fail "squeeze"
  [ "$(col sq.csv stage | grep -c squeeze)" -eq 4 ] || fail "4 squeeze rows expected"
  col sq.csv wall_force_F | tail -3 | awk '$1 <= prev { exit 1 } { prev = $1 }' || fail "wall force does not grow: $(col sq.csv wall_force_F)"
  col sq.csv volume_error | tail -4 | awk '$1 > 1e-3 { exit 1 }' || fail "volume not held"
}
case_bad_mesh_open() {
  make_cell
  off_edit 'F.pop()' cell.off open.off
  expect_error 2 "open.off: a pressurised shell needs a closed manifold mesh" run --mesh open.off -o out.off
}
case_bad_mesh_nonmanifold() {
  make_cell
  off_edit 'V.append([5.0, 5.0, 5.0]); F.append([F[0][0], F[0][1], len(V) - 1])' cell.off nm.off
  expect_error 2 "nm.off: a pressurised shell needs a closed manifold" run --mesh nm.off -o out.off
}
case_bad_mesh_orientation() {
  make_cell
  off_edit 'F[0] = [F[0][0], F[0][2], F[0][1]]' cell.off flip.off
  expect_error 2 "flip.off: the faces are not consistently oriented" run --mesh flip.off -o out.off
  off_edit 'F[:] = [[f[0], f[2], f[1]] for f in F]' cell.off inward.off
  expect_error 2 "inward.off: the faces of shell 0 are oriented inward" run --mesh inward.off -o out.off
}
case_bad_mesh_degenerate() {
  make_cell
  off_edit 'V[F[0][1]] = list(V[F[0][0]])' cell.off degenerate.off
  expect_error 2 "degenerate.off: rest triangle 0 is degenerate" run --mesh degenerate.off -o out.off
}
case_bad_mesh_unreadable() {
  printf 'OFF\n3 1 0\n0 0 0\n1 x 0\n' >junk.off
  expect_error 2 "junk.off:4: " run --mesh junk.off -o out.off
  expect_error 2 "missing.off: cannot open" run --mesh missing.off -o out.off
}
case_bad_material() {
  make_cell
  expect_error 2 "--nu: must lie in (-1, 0.5\\], got '0.6'" run --mesh cell.off --nu 0.6 -o out.off
  expect_error 2 "--nu: must lie in (-1, 0.5\\], got '-1'" run --mesh cell.off --nu -1 -o out.off
  "$shellpack" shell -E 0 -t -1 --mesh cell.off -o out.off >stdout.txt 2>stderr.txt; [ $? -eq 2 ] || fail "E 0 accepted"
  grep -q "^shellpack: --youngs-modulus: must be positive" stderr.txt || fail "E: $(cat stderr.txt)"
  grep -q "^shellpack: --thickness: must be positive" stderr.txt || fail "t: $(cat stderr.txt)"
  ! ls out.* 2>/dev/null | grep >/dev/null . || fail "left output"
  expect_error 2 "unknown stretching model 'fem'" run --mesh cell.off --model fem -o out.off
  expect_error 2 "--squeeze: needs --walls" run --mesh cell.off --squeeze 0.2 -o out.off
}
case_bad_walls() {
  make_cell
  expect_error 2 "plates 1.5 apart cut the mesh" run --mesh cell.off --walls 1.5 --squeeze 0.2 -o out.off
}
case_inverting_pressure() {
  make_cell
  expect_error 1 "hinges folded over .*the load inverts elements" run --mesh cell.off --pressure -1 -o out.off --csv out.csv
}
case_bench_unknown() {
  expect_error 2 "unknown benchmark 'cube'" "$shellpack" bench-mechanics cube -o out.csv
}
case_bench_sphere() {
  "$shellpack" bench-mechanics sphere -q >sphere.csv || fail "sphere"
  grep -q "^model,dP_E,eps_r,eps_r_svk," sphere.csv || fail "header"
  awk -F, '!/^#/ && $1 == "svk" { e = $7; if (e < 0) e = -e; if (e > 0.01) exit 1 }' sphere.csv || fail "svk off: $(cat sphere.csv)"
}
case_bench_buckling() {
  "$shellpack" bench-mechanics buckling -q -o buckling.csv || fail "buckling"
  grep -q "^model,stretching,T_end,vertices,gamma,p_pc," buckling.csv || fail "header"
  # Every shell buckles below p_c, the T_end = 200 mesh lower than the icosahedral one.
  awk -F, '!/^#/ && $1 != "model" { p[$1 "," $5] = $6; if ($6 == "" || $6 <= 0.4 || $6 >= 1) exit 1 }
           END { if (!(p["icosa-L4,1000"] > p["rndmesh-T200,1000"] && p["icosa-L4,10000"] > p["rndmesh-T200,10000"])) exit 1 }' \
    buckling.csv || fail "buckling pressures: $(cat buckling.csv)"
}

run_cases "$@"
