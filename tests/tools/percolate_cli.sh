#!/usr/bin/env bash
# percolate as a user runs it. `percolate_cli.sh --list` prints the cases; `percolate_cli.sh
# CASE` runs one (ctest registers each). Needs CMP_BIN (the built programs) and CMP_SRC.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
percolate="$bin/percolate"
rndmesh="$bin/rndmesh"
sc="$src/data/percolate/simple_cubic_4x4x4.xyz"  # 4x4x4 spheres r = 0.4 on a = 1, D0 = 1
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=percolate
enter_scratch_dir
# field CSV COLUMN [ROW]: the value of COLUMN in data row ROW (default 1) of a percolate CSV.
field() {
  grep -v '^#' "$1" | awk -F, -v col="$2" -v row="${3:-1}" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == col) c = i; next }
    NR == row + 1 { print $c }'
}
# A packing OFF of one closed icosahedral shell (level 4, radius 1, edges ~0.19) centred in a
# periodic box of side 3: packing.off.
make_shell_packing() {
  "$rndmesh" icosa --level 4 -o sphere.off -q || fail "rndmesh"
  awk 'NR == 1 { print; print "# box 3 3 3"; print "# periodic 1 1 1"; print "# shells 1 642"; next }
       /^#/ { next }
       !counts { print; counts = 1; nv = $1; next }
       nv > 0 { printf "%.17g %.17g %.17g\n", $1 + 1.5, $2 + 1.5, $3 + 1.5; --nv; next }
       { print }' sphere.off > packing.off
}

case_help() {
  "$percolate" --help | grep >/dev/null -- "--delta" || fail "help lacks --delta"
  "$percolate" --help | grep >/dev/null -- "--periodic" || fail "help lacks --periodic"
  "$percolate" sweep --help | grep >/dev/null -- "--bins" || fail "sweep help lacks --bins"
  "$percolate" --version | grep -Eq "^percolate [0-9]" || fail "--version"
}
case_spheres_csv() {
  "$percolate" "$sc" --delta 0.05 -q > p.csv || fail "run"
  grep -q "^# provenance=percolate .*--delta 0.05" p.csv || fail "provenance: $(head -3 p.csv)"
  [ "$(field p.csv kind)" = spheres ] || fail "kind"
  [ "$(field p.csv nx)" = 80 ] || fail "nx $(field p.csv nx)"
  [ "$(field p.csv d0_source)" = file ] || fail "d0_source"
  [ "$(field p.csv marking)" = spheres-overlap ] || fail "marking"
  /usr/bin/python3 -c "import math,sys; p=float(sys.argv[1]); e=1-4*math.pi*0.4**3/3; assert abs(p-e)<1e-12, (p,e)" \
    "$(field p.csv porosity)" || fail "porosity"
  [ "$(field p.csv porosity_method)" = sphere_pair_lenses ] || fail "porosity_method"
  [ "$(field p.csv porosity_exact)" = 1 ] || fail "porosity_exact"
  [ "$(field p.csv percolates_x)$(field p.csv percolates_y)$(field p.csv percolates_z)" = 111 ] || fail "percolation"
  [ "$(field p.csv clusters)" = 1 ] || fail "clusters"
}
case_scale_closes_the_channels() {
  # The void of the simple cubic array percolates while r < a / sqrt 2 = 0.707; overlap marking
  # keeps it open at least while r < a / sqrt 2 - sqrt 3 delta: r = 0.64 percolates at
  # delta = 0.025, r = 0.72 never does.
  "$percolate" "$sc" --delta 0.025 --scale 1.6 -q > open.csv || fail "open"
  "$percolate" "$sc" --delta 0.025 --scale 1.8 -q > closed.csv || fail "closed"
  [ "$(field open.csv percolates)" = 1 ] || fail "r = 0.64 should percolate"
  [ "$(field closed.csv percolates)" = 0 ] || fail "r = 0.72 should not percolate"
  [ "$(field closed.csv scale)" = 1.8 ] || fail "scale column"
  [ "$(field closed.csv d0)" = 1 ] || fail "D0 from the file, not scaled"
}
case_vtk_cluster() {
  "$percolate" "$sc" --delta 0.1 --scale 1.2 -o cluster.vtk -q > p.csv || fail "run"
  [ "$(field p.csv percolates)" = 1 ] || fail "r = 0.48 should percolate"
  head -10 cluster.vtk | grep >/dev/null "^SPACING 0.1 0.1 0.1" || fail "spacing: $(head -10 cluster.vtk)"  # D0 = 1
  head -2 cluster.vtk | grep >/dev/null "^percolating cluster along x of .*scale=1.2 delta=0.1 D0=1 (file) marking=spheres-overlap .*| percolate " || fail "title: $(head -2 cluster.vtk)"
  /usr/bin/python3 - "$(field p.csv cluster_voxels)" <<'PY' || fail "VTK contents"
import sys, numpy as np
raw = open("cluster.vtk", "rb").read()
head, data = raw.split(b"LOOKUP_TABLE default\n", 1)
assert b"DIMENSIONS 40 40 40" in head and b"SCALARS cluster unsigned_char" in head, head
img = np.frombuffer(data[:40**3], dtype=np.uint8).reshape(40, 40, 40)
assert set(np.unique(img)) <= {0, 1}
assert img.sum() == int(sys.argv[1]), (img.sum(), sys.argv[1])
assert img[:, :, 0].any() and img[:, :, -1].any()  # touches both x faces (x is the last index)
PY
}
case_many_packings_and_deltas() {
  cp "$sc" a.xyz; cp "$sc" b.xyz
  "$percolate" a.xyz b.xyz --delta 0.1,0.2 -o 'c_{name}_{delta}.vtk' --threads 2 -q > p.csv || fail "run"
  [ "$(grep -vc '^#' p.csv)" = 5 ] || fail "rows: $(cat p.csv)"
  for f in c_a_0.1.vtk c_a_0.2.vtk c_b_0.1.vtk c_b_0.2.vtk; do [ -f $f ] || fail "$f missing"; done
  [ "$(field p.csv delta 2)" = 0.2 ] || fail "order: a 0.1, a 0.2, b 0.1, b 0.2"
  expect_error 2 "{name}" "$percolate" a.xyz b.xyz --delta 0.1 -o out.vtk
}
case_same_bytes() {
  # Same input, same bytes: two runs, and 1 against 2 threads, give the same CSV and VTK but for
  # the provenance line (and the VTK title, which quotes it); no wall-clock columns.
  run() { "$percolate" "$sc" --delta 0.04,0.1 --scale 1.6 --threads "$1" -o "$2_{delta}.vtk" -q > "$2.csv" || fail "run $2"; }
  run 1 one; run 1 again; run 2 two
  ! grep -v '^#' one.csv | head -1 | grep >/dev/null seconds || fail "timing columns: $(grep -v '^#' one.csv | head -1)"
  for b in again two; do
    same_lines "CSV differs: one vs $b" '^# provenance=' one.csv $b.csv
    for d in 0.04 0.1; do
      cmp -s <(sed 2d one_$d.vtk) <(sed 2d ${b}_$d.vtk) || fail "VTK differs: one_$d vs ${b}_$d"
    done
  done
  "$percolate" "$sc" --delta 0.1 --timings -q > t.csv 2> t.err || fail "--timings"
  grep -q "^percolate: .*marking [0-9.]* s, labelling [0-9.]* s" t.err || fail "--timings: $(cat t.err)"
  "$percolate" "$sc" --delta 0.1 -q > u.csv || fail "run"
  same_lines "--timings changed the CSV" '^# provenance=' t.csv u.csv
}
case_vtk_in_packing_units() {
  # With D0 = 2 length units, delta = 0.1 D0 is a spacing of 0.2: origin, spacing and the
  # points span the packing's box of 4 (not 2, as in D0 units), so the cluster overlays it.
  "$percolate" "$sc" --delta 0.1 --d0 2 --scale 1.2 -o c.vtk -q > p.csv || fail "run"
  /usr/bin/python3 - <<'PY' || fail "VTK geometry: $(head -10 c.vtk | grep -a -v LOOKUP)"
raw = open("c.vtk", "rb").read()
head = raw.split(b"FIELD FieldData", 1)[0].split(b"LOOKUP_TABLE default\n", 1)[0].decode()
lines = {l.split()[0]: [float(x) for x in l.split()[1:]] for l in head.splitlines()[2:] if l.split() and l.split()[0] in ("DIMENSIONS", "SPACING", "ORIGIN")}
dims, spacing, origin = lines["DIMENSIONS"], lines["SPACING"], lines["ORIGIN"]
assert dims == [20, 20, 20], dims
for a in range(3):
    assert abs(dims[a] * spacing[a] - 4.0) < 1e-12, (dims, spacing)
    assert abs(origin[a] - spacing[a] / 2) < 1e-12, (origin, spacing)
title = head.splitlines()[1]
assert "delta=0.1" in title and "D0=2" in title, title
PY
  [ "$(field p.csv nx)" = 20 ] || fail "nx"
  # VTK's own reader: the same geometry, and delta, d0 and scale as field data (what lbflow and
  # a ParaView user need to go back to D0 units).
  /usr/bin/python3 - <<'PY' || fail "VTK reader"
import vtk
r = vtk.vtkStructuredPointsReader()
r.SetFileName("c.vtk")
r.Update()
img = r.GetOutput()
assert img.GetDimensions() == (20, 20, 20), img.GetDimensions()
assert all(abs(s - 0.2) < 1e-12 for s in img.GetSpacing()), img.GetSpacing()
fd = img.GetFieldData()
values = {fd.GetArrayName(i): fd.GetArray(i).GetValue(0) for i in range(fd.GetNumberOfArrays())}
porosity = values.pop("porosity")
assert values == {"delta": 0.1, "d0": 2.0, "scale": 1.2}, values
assert 0 < porosity < 1, porosity
PY
}
case_frames_are_packings() {
  # Every frame of an extended XYZ is a packing: one row (and one VTK with {frame}) each.
  cat "$sc" "$sc" >two.xyz
  "$percolate" two.xyz --delta 0.2 -q >p.csv || fail "two frames"
  [ "$(grep -vc '^#' p.csv)" = 3 ] || fail "rows: $(cat p.csv)"
  [ "$(field p.csv frame 1) $(field p.csv frame 2)" = "0 1" ] || fail "frame column: $(cat p.csv)"
  "$percolate" two.xyz --delta 0.2 -q -o 'c_{frame}.vtk' >/dev/null && [ -f c_0.vtk ] && [ -f c_1.vtk ] || fail "{frame}"
  expect_error 2 "-o: an input holds several frames" "$percolate" two.xyz --delta 0.2 -o out.vtk
  expect_error 2 "'-' (standard input) given more than once" "$percolate" - - --delta 0.2
}
case_scale_list() {
  "$percolate" "$sc" --delta 0.1,0.2 --scale 1.0,1.1 -o 'c_{name}_{scale}_{delta}.vtk' -q > p.csv || fail "run"
  [ "$(grep -vc '^#' p.csv)" = 5 ] || fail "rows: $(cat p.csv)"
  [ "$(field p.csv scale 1),$(field p.csv delta 1) $(field p.csv scale 2),$(field p.csv delta 2) $(field p.csv scale 3),$(field p.csv delta 3) $(field p.csv scale 4),$(field p.csv delta 4)" = \
    "1,0.1 1,0.2 1.1,0.1 1.1,0.2" ] || fail "order: packings x scales x deltas: $(cat p.csv)"
  for f in c_simple_cubic_4x4x4_1.0_0.1.vtk c_simple_cubic_4x4x4_1.1_0.2.vtk; do [ -f $f ] || fail "$f missing: $(ls)"; done
  # a scale changes the radii: the porosity falls
  /usr/bin/python3 -c "import sys; assert float(sys.argv[1]) > float(sys.argv[2])" "$(field p.csv porosity 1)" \
    "$(field p.csv porosity 3)" || fail "porosity does not fall with the scale"
  expect_error 2 "{scale}" "$percolate" "$sc" --delta 0.1 --scale 1,1.1 -o out.vtk
  expect_error 2 "--scale: must be positive, got '-1'$" "$percolate" "$sc" --delta 0.1 --scale 1,-1 -o out.vtk
  make_shell_packing
  expect_error 2 "packing.off: --scale 1.1 applies to sphere packings" "$percolate" packing.off --delta 0.1 --scale 1.1 -o out.vtk
}
case_porosity_never_negative() {
  # r = 0.56: pairs overlap, no point is in three spheres: the lens-corrected porosity is exact
  "$percolate" "$sc" --delta 0.1 --scale 1.4 > p.csv 2> err.txt || fail "run"
  /usr/bin/python3 -c "import sys,math
r=0.56; s=2*r-1; lens=math.pi*s*s*(1+4*r+6*r*r-6*r*r)/12
e=1-(4*math.pi*r**3/3-3*lens); p=float(sys.argv[1]); assert abs(p-e)<1e-12, (p,e)" "$(field p.csv porosity)" || fail "porosity $(field p.csv porosity)"
  [ "$(field p.csv porosity_exact)" = 1 ] || fail "exact"
  ! grep -q warning err.txt || fail "warned: $(cat err.txt)"
  # r = 0.72 > 1/sqrt 2: three spheres share points; sum V / V_box = 1.56 > 1
  "$percolate" "$sc" --delta 0.1 --scale 1.8 -q > q.csv 2> err.txt || fail "run 1.8"
  [ "$(field q.csv porosity_exact)" = 0 ] || fail "exact at 1.8"
  grep -q "^percolate: warning: the pair-lens porosity is an upper bound.*simple_cubic_4x4x4.xyz at scale 1.8: [1-9][0-9]* triples" err.txt \
    || fail "no warning: $(cat err.txt)"
  /usr/bin/python3 -c "import sys; assert float(sys.argv[1]) > 1" "$(field q.csv particle_volume_fraction)" || fail "volume fraction"
  # no column named porosity* is negative
  grep -v '^#' q.csv | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i ~ /^porosity/) c[i] = $i; next }
    { for (i in c) if ($i + 0 < 0) { print c[i] "=" $i; bad = 1 } } END { exit bad }' || fail "negative porosity"
  # one sphere of r = 0.74 in a unit cell overlaps its own images (6 at distance 1, 12 at sqrt 2:
  # 9 pairs of images): sum V / V_box = 1.7
  printf '1\nLattice="1 0 0 0 1 0 0 0 1" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T" D0=1\nX 0 0 0 0.74\n' > one.xyz
  "$percolate" one.xyz --delta 0.05 > o.csv 2> err.txt || fail "run one sphere"
  [ "$(field o.csv porosity_exact)" = 0 ] || fail "exact for one sphere"
  grep -q "^percolate: warning: .*one.xyz at scale 1: 0 triples of spheres share a point, 9 spheres or pairs overlap through a periodic image" err.txt || fail "warning: $(cat err.txt)"
  /usr/bin/python3 -c "import sys; assert 0 <= float(sys.argv[1]) <= 1" "$(field o.csv porosity)" || fail "porosity $(field o.csv porosity)"
  "$percolate" "$sc" --delta 0.1 --scale 1.8 >/dev/null 2>err.txt || fail "scale 1.8 exited $?: $(cat err.txt)"
  grep -q "porosity" err.txt || fail "no summary: $(cat err.txt)"
  lacks "summary prints a negative porosity" "porosity -" err.txt
}
case_summary_on_a_terminal() {
  # The per-run summary goes to stderr on a terminal (after the progress bar) as when piped.
  command -v script >/dev/null || fail "script (util-linux) is needed to give percolate a terminal"
  script -qec "'$percolate' '$sc' --delta 0.1,0.2 --csv p.csv" /dev/null > tty.txt || fail "run on a terminal"
  [ "$(grep -ac 'percolate: .*simple_cubic_4x4x4.xyz scale=1 delta=0\.[12] .*porosity' tty.txt)" = 2 ] || fail "terminal: $(cat -v tty.txt)"
  "$percolate" "$sc" --delta 0.1,0.2 --csv p.csv 2> piped.txt || fail "piped"
  [ "$(grep -c 'percolate: .*scale=1 delta=0\.[12] .*porosity' piped.txt)" = 2 ] || fail "piped: $(cat piped.txt)"
  script -qec "'$percolate' '$sc' --delta 0.1 -q --csv p.csv" /dev/null > quiet.txt || fail "run -q"
  ! grep -aq 'porosity' quiet.txt || fail "-q: $(cat -v quiet.txt)"
}
case_shell_triangles_vs_vertices() {
  # The thesis's caveat: vertex marking leaks at delta below the edge length; triangles do not.
  make_shell_packing
  "$percolate" packing.off --delta 0.05 --d0 1 -q > tri.csv || fail "triangles"
  "$percolate" packing.off --delta 0.05 --d0 1 --marking vertices -q > vert.csv || fail "vertices"
  [ "$(field tri.csv clusters)" = 2 ] || fail "triangles: $(field tri.csv clusters) clusters, expected inside + outside"
  [ "$(field vert.csv clusters)" = 1 ] || fail "vertices: $(field vert.csv clusters) clusters, expected a leak"
  [ "$(field tri.csv marking)" = triangles ] || fail "marking column"
  [ "$(field tri.csv d0_source)" = option ] || fail "d0_source"
  "$percolate" packing.off --delta 0.05 --marking vertices --thickness 0.05 -q > thick.csv || fail "thickness"
  [ "$(field thick.csv clusters)" = 2 ] || fail "thickened vertices should close the shell"
  [ "$(field thick.csv d0_source)" = shell_volume ] || fail "D0 from the shell volume"
  [ "$(field thick.csv marking)" = vertices+0.05 ] || fail "marking column $(field thick.csv marking)"
  # porosity from the shell's enclosed volume: 1 - V / 27 with V a bit under 4 pi / 3
  /usr/bin/python3 -c "import sys,math; p=float(sys.argv[1]); assert 1-4*math.pi/3/27 < p < 1-0.99*4*math.pi/3/27, p" \
    "$(field tri.csv porosity)" || fail "porosity $(field tri.csv porosity)"
  [ "$(field tri.csv porosity_method)" = shell_volumes ] || fail "porosity_method"
}
case_d0_from_off_comment() {
  make_shell_packing
  sed '1a # D0=2' packing.off > d0.off
  "$percolate" d0.off --delta 0.05 -q > p.csv || fail "run"
  [ "$(field p.csv d0)" = 2 ] || fail "d0 $(field p.csv d0)"
  [ "$(field p.csv d0_source)" = file ] || fail "d0_source $(field p.csv d0_source)"
  [ "$(field p.csv nx)" = 30 ] || fail "nx: 3 / (0.05 * 2) = 30, got $(field p.csv nx)"
}
case_periodic_labelling() {
  # A shell packing percolates around the shell; --periodic changes the labelling only.
  make_shell_packing
  "$percolate" packing.off --delta 0.1 --periodic -q > per.csv || fail "periodic"
  grep -q "^# labelling=periodic" per.csv || fail "meta"
  [ "$(field per.csv percolates)" = 1 ] || fail "outside percolates"
  [ "$(field per.csv clusters)" = 2 ] || fail "clusters"
}
case_sweep() {
  for s in 1.0 1.2 1.7 1.8; do "$percolate" "$sc" --delta 0.1 --scale $s -q --csv r_$s.csv || fail "scale $s"; done
  "$percolate" sweep r_*.csv --bins 2 > prob.csv || fail "sweep"
  grep -qx "particles,delta,porosity,porosity_low,porosity_high,packings,percolating,probability,probability_error" prob.csv || fail "header: $(cat prob.csv)"
  grep -q "^# porosity_column=porosity$" prob.csv || fail "porosity column meta"
  grep -q "^# scales=1,1.2,1.7,1.8 " prob.csv || fail "scales meta: $(cat prob.csv)"
  [ "$(grep -vc '^#' prob.csv)" = 3 ] || fail "rows: $(cat prob.csv)"
  # low-porosity bin: scales 1.7 and 1.8, neither percolates at delta = 0.1; high bin: both percolate
  [ "$(grep -v '^#' prob.csv | sed -n 2p | cut -d, -f6-8)" = "2,0,0" ] || fail "low bin: $(cat prob.csv)"
  [ "$(grep -v '^#' prob.csv | sed -n 3p | cut -d, -f6-8)" = "2,2,1" ] || fail "high bin: $(cat prob.csv)"
  # the same from one run over a list of scales, read from stdin
  "$percolate" "$sc" --delta 0.1 --scale 1.0,1.2,1.7,1.8 -q | "$percolate" sweep - --bins 2 > prob2.csv || fail "sweep -"
  same_lines "stdin sweep differs: $(cat prob2.csv)" '^#' prob.csv prob2.csv
}
case_sweep_refuses_other_tables() {
  expect_error 2 "simple_cubic_4x4x4.xyz:[0-9]*: not a percolate CSV" "$percolate" sweep "$sc" -o out.csv
  printf 'particles,delta,porosity\n10,0.1,0.5\n' > three.csv
  expect_error 2 "three.csv:1: not a percolate CSV: no column 'percolates'" "$percolate" sweep three.csv -o out.csv
  printf 'particles,delta,porosity,percolates\n10,0.1,0.5,1\n1e300,0.1,0.4,0\n' > big.csv
  expect_error 2 "big.csv:3: expected a particle count" "$percolate" sweep big.csv -o out.csv
  printf 'particles,delta,porosity,percolates\n10.5,0.1,0.5,1\n' > frac.csv
  expect_error 2 "frac.csv:2: expected a particle count" "$percolate" sweep frac.csv -o out.csv
  printf 'particles,delta,porosity,percolates\n10,0.1,0.5,2\n' > two.csv
  expect_error 2 "two.csv:2: expected 0 or 1" "$percolate" sweep two.csv -o out.csv
  # groups are not mixed silently: a table given twice, or runs of different kinds
  "$percolate" "$sc" --delta 0.1 --scale 1,1.1 -q > a.csv || fail "run"
  expect_error 2 "a.csv:[0-9]*: the run of .*simple_cubic_4x4x4.xyz at scale 1 and delta 0.1 is also at a.csv" \
    "$percolate" sweep a.csv a.csv -o out.csv
  "$percolate" "$sc" --delta 0.1 --scale 1.2 --sphere-marking centre -q > c.csv || fail "run centre"
  expect_error 2 "c.csv:[0-9]*: marking 'spheres-centre' differs from 'spheres-overlap' at a.csv" \
    "$percolate" sweep a.csv c.csv -o out.csv
  "$percolate" "$sc" --delta 0.1 --scale 1.2 --connectivity 26 -q > n.csv || fail "run 26"
  expect_error 2 "n.csv:1: connectivity '26' differs" "$percolate" sweep a.csv n.csv -o out.csv
}
case_sweep_script() {
  # scripts/data/percolation_sweep.sh: the pipeline for shellpack's jammed packings, on the simple
  # cubic array: probability 1 at high porosity, 0 once the channels close (r > a/sqrt 2).
  cp "$sc" a.xyz
  bash "$src/scripts/data/percolation_sweep.sh" -b "$bin/.." -d 0.05,0.1 -s "1.0 1.3 1.75 1.8" -n 2 -o res a.xyz \
    2>/dev/null || fail "script"
  [ "$(grep -vc '^#' res/percolate.csv)" = 9 ] || fail "rows: $(cat res/percolate.csv)"
  [ "$(grep -v '^#' res/percolation_probability.csv | awk -F, 'NR > 1 { print $2, $8 }' | sort -u | tr '\n' ' ')" = \
    "0.05 0 0.05 1 0.1 0 0.1 1 " ] || fail "probabilities: $(cat res/percolation_probability.csv)"
}
case_bad_off_without_box() {
  printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > nobox.off
  expect_error 2 "nobox.off:1: .*box" "$percolate" nobox.off --delta 0.1 -o out.vtk
}
case_bad_shell_counts() {
  printf 'OFF\n# box 2 2 2\n# shells 2 3 3\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > bad.off
  expect_error 2 "bad.off:3: .*add up" "$percolate" bad.off --delta 0.1 -o out.vtk
}
case_bad_delta() {
  expect_error 2 "--delta: must be positive, got '0'$" "$percolate" "$sc" --delta 0 -o out.vtk
  expect_error 2 "--delta: must be positive, got '-1'$" "$percolate" "$sc" --delta 0.1,-1 -o out.vtk
  expect_error 2 "--delta: 'x' is not a finite number$" "$percolate" "$sc" --delta 0.1,x -o out.vtk
  expect_error 2 "simple_cubic_4x4x4.xyz: .*larger than the box" "$percolate" "$sc" --delta 5 -o out.vtk
  expect_error 2 "--delta: required" "$percolate" "$sc" -o out.vtk
  "$percolate" "$sc" --delta 0 --scale 0 --axis w -o out.vtk 2> all.txt && fail "bad options accepted"
  [ "$(grep -c . all.txt)" = 4 ] || fail "every bad option at once, then the --help hint: $(cat all.txt)"
}
case_bad_sphere_file_without_radii() {
  printf '1\nLattice="2 0 0 0 2 0 0 0 2" Properties=species:S:1:pos:R:3 pbc="T T T"\nX 1 1 1\n' > norad.xyz
  expect_error 2 "norad.xyz:[0-9]*: .*radius" "$percolate" norad.xyz --delta 0.1 -o out.vtk
}
case_bad_later_file_writes_nothing() {
  # The second file is bad: no VTK of the first one either, and no CSV.
  cp "$sc" good.xyz
  printf '1\nProperties=species:S:1:pos:R:3:radius:R:1\nX 1 1 1 0.5\n' > nolattice.xyz
  expect_error 2 "nolattice.xyz:.*Lattice" "$percolate" good.xyz nolattice.xyz --delta 0.1 -o 'out.{name}.vtk' --csv out.csv
}
case_bad_options() {
  expect_error 2 "--marking: must be 'vertices' or 'triangles', got 'faces'$" "$percolate" "$sc" --delta 0.1 --marking faces -o out.vtk
  expect_error 2 "--connectivity: must be 6, 18 or 26, got '8'$" "$percolate" "$sc" --delta 0.1 --connectivity 8 -o out.vtk
  expect_error 2 "--axis: must be x, y or z, got 'w'$" "$percolate" "$sc" --delta 0.1 --axis w -o out.vtk
  expect_error 2 "--scale: must be positive, got '-1'$" "$percolate" "$sc" --delta 0.1 --scale -1 -o out.vtk
  expect_error 2 "missing.xyz" "$percolate" missing.xyz --delta 0.1 -o out.vtk
}
case_bad_options_all_at_once() {
  # Every bad option in one run, each under its flag, numbers included (no CLI11 message
  # about the first one alone), then the --help hint; nothing written.
  "$percolate" "$sc" --delta -1 --scale abc --connectivity 7 --threads -2 --d0 x --thickness -0.5 \
    --sphere-marking middle -o out.vtk --csv out.csv 2>err.txt
  [ $? -eq 2 ] || fail "exit status"
  for p in "--delta: must be positive, got '-1'" "--scale: 'abc' is not a finite number" \
    "--connectivity: must be 6, 18 or 26, got '7'" "--threads: must lie in [0, $((64 * $(nproc)))] (64 per core of this machine's $(nproc)), got '-2'" \
    "--d0: 'x' is not a finite number" "--thickness: must not be negative, got '-0.5'" \
    "--sphere-marking: must be 'overlap' or 'centre', got 'middle'" "run 'percolate --help' for the options"; do
    grep -qxF -- "percolate: $p" err.txt || fail "lacks '$p': $(cat err.txt)"
  done
  [ "$(wc -l <err.txt)" -eq 8 ] || fail "not one line per problem: $(cat err.txt)"
  printf 'file,particles,delta,porosity,percolates\na,4,0.1,0.5,1\n' >runs.csv
  "$percolate" sweep runs.csv --bins abc 2>err.txt
  [ $? -eq 2 ] || fail "sweep exit status"
  [ "$(cat err.txt)" = "percolate: --bins: 'abc' is not an integer
percolate: run 'percolate sweep --help' for the options" ] || fail "sweep --bins abc: $(cat err.txt)"
  expect_error 2 "--bins: must be at least 1, got '0'$" "$percolate" sweep runs.csv --bins 0
  ! ls -a | grep >/dev/null '^out\.\|\.tmp' || fail "left a file: $(ls -a)"
}
case_interrupt_sigint() {
  # Ctrl-C during one long run: no CSV temporary exists while the analysis runs (it appears
  # with the first row, so even a SIGKILL there leaves nothing), and after the signal nothing
  # is left; exit 130, "interrupted".
  # The signal comes once percolate says that its work started (CMP_READY_FILE, outside this
  # folder); the run takes about 2 s (400^3 voxels, 26 neighbours).
  local ready
  ready=$(mktemp -u "${TMPDIR:-/tmp}/cmp_ready.XXXXXX")
  set -m
  CMP_READY_FILE=$ready "$percolate" "$sc" --delta 0.01 --connectivity 26 --periodic --threads 1 --csv perc.csv -q >/dev/null 2>interrupt.err &
  local pid=$!
  wait_ready "$pid" "$ready"
  rm -f "$ready"
  local during
  during=$(ls -A | grep -v '^interrupt.err$')
  kill -0 "$pid" 2>/dev/null || fail "the run ended before the signal: make it longer"
  kill -s INT "$pid"
  wait "$pid"; local got=$?
  set +m
  [ -z "$during" ] || fail "files while the first run computes: $during"
  [ "$got" = 130 ] || fail "exit $got after SIGINT, expected 130: $(cat interrupt.err)"
  [ "$(cat interrupt.err)" = "percolate: interrupted" ] || fail "stderr: $(cat interrupt.err)"
  [ -z "$(ls -A | grep -v '^interrupt.err$')" ] || fail "left files: $(ls -A)"
}

run_cases "$@"
