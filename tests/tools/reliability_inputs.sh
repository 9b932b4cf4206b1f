#!/usr/bin/env bash
# Issue 37, items 1 and 4-7: extreme but well-formed values give exit 2 naming file and line
# (no crash, no hang, no internal error); nothing non-finite is read where the format promises
# finite numbers or written anywhere; a damaged checkpoint is refused; size limits are said
# from the option or the header before anything large is allocated; '-' reads every format.
# `reliability_inputs.sh --list` prints the cases; `reliability_inputs.sh CASE` runs one
# (ctest registers each). Needs CMP_BIN and CMP_SRC.
set -uo pipefail
bin=${CMP_BIN:-build/bin}
src=${CMP_SRC:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
lbflow="$bin/lbflow"
percolate="$bin/percolate"
shellpack="$bin/shellpack"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
export OMP_NUM_THREADS=1
enter_scratch_dir

# bounded TOOL STATUS PATTERN cmd...: within 60 s of CPU time and 300 MB.
bounded() { expect_bounded 60 300000 "$@"; }

# The octahedron packing of tests/data/io with its box line or a vertex replaced.
packing_with() {
  sed "$1" "$src/tests/data/io/octahedron_packing.off" >"$2"
}
# A float VTK image of a straight duct, 6x4x4 (1 = fluid), with field data.
float_vtk() {
  /usr/bin/python3 - "$@" <<'PY'
import struct, sys
spacing = sys.argv[1] if len(sys.argv) > 1 else "1"
field = sys.argv[2] if len(sys.argv) > 2 else "0.125"
nx, ny, nz = 6, 4, 4
vals = [1.0 if 1 <= y <= 2 and 1 <= z <= 2 else 0.0 for z in range(nz) for y in range(ny) for x in range(nx)]
head = ("# vtk DataFile Version 3.0\nduct\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS %d %d %d\n"
        "ORIGIN 0 0 0\nSPACING %s %s %s\nFIELD FieldData 1\ndelta 1 1 double\n" % (nx, ny, nz, spacing, spacing, spacing))
points = "\nPOINT_DATA %d\nSCALARS v float 1\nLOOKUP_TABLE default\n" % (nx * ny * nz)
open("duct.vtk", "wb").write(head.encode() + struct.pack(">d", float(field)) + points.encode() +
                             struct.pack(">%df" % len(vals), *vals) + b"\n")
PY
}

# --- item 1: extreme values in a packing OFF ---
case_analyze_vertex_at_1e308() {
  packing_with '7s/.*/1e308 1e308 1e308/' far.off
  bounded shellpack 2 "far.off:7: coordinate '1e308' is beyond" "$shellpack" analyze far.off -o out.csv
  bounded percolate 2 "far.off:7: coordinate '1e308' is beyond" "$percolate" far.off --delta 0.5 -o out.vtk
}
case_analyze_huge_box() {
  packing_with 's/^# box .*/# box 1e308 1e308 1e308/' huge.off
  bounded shellpack 2 "huge.off:3: box side '1e308' is beyond" "$shellpack" analyze huge.off -o out.csv
  # periodic: g(r) and CGAL's periodic Voronoi cells ran (a crash, or minutes of CPU)
  packing_with 's/^# box .*/# box 1e308 1e308 1e308/; s/^# periodic .*/# periodic 1 1 1/' hugep.off
  bounded shellpack 2 "hugep.off:3: box side '1e308' is beyond" "$shellpack" analyze hugep.off -o out.csv
  packing_with 's/^# box .*/# box 1e100 1e100 1e100/; s/^# periodic .*/# periodic 1 1 1/' big.off
  bounded shellpack 2 "big.off:3: box side" "$shellpack" analyze big.off -o out.csv
}
case_xyz_huge_lattice_or_position() {
  # shellpack structure wrote g = nan (now refused by the writer, exit 1); refused at the line, exit 2
  xyz() { printf '2\nLattice="%s 0 0 0 %s 0 0 0 %s" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T"\nX %s 0.5 0.5 0.3\nX 0.2 0.2 0.2 0.3\n' "$1" "$1" "$1" "$2" >"$3"; }
  xyz 1e308 0.5 box.xyz
  bounded shellpack 2 "box.xyz:2: the Lattice has a side of 1e+308, beyond 1e+100" "$shellpack" structure box.xyz -o out.csv
  bounded percolate 2 "box.xyz:2: the Lattice has a side of 1e+308" "$percolate" box.xyz --delta 0.1 -o out.vtk
  xyz 1 1e308 far.xyz
  bounded percolate 2 "far.xyz:3: a position or radius is beyond 1e+100" "$percolate" far.xyz --delta 0.1 -o out.vtk
  bounded lbflow 2 "far.xyz:3: a position or radius is beyond 1e+100" "$lbflow" far.xyz --delta 0.25 -o out.csv
}
case_rdf_options_bounded() {
  packing_with 's/^# periodic .*/# periodic 1 1 1/' p.off
  bounded shellpack 2 "--bin: --rmax / --bin makes .* bins of g(r)" "$shellpack" analyze p.off --bin 1e-9 -o out.csv
  bounded shellpack 2 "--rmax: --rmax / --bin makes .* bins of g(r)" \
    "$shellpack" structure "$src/data/percolate/simple_cubic_4x4x4.xyz" --rmax 1e300 -o out.csv
}

# --- item 4: non-finite numbers ---
case_vtk_field_data_inf_refused() {
  float_vtk 1 inf
  bounded lbflow 2 "duct.vtk:9: FIELD array 'delta' holds inf: its values must be finite" "$lbflow" duct.vtk --refine 1 -o out.csv
  float_vtk 1 nan
  bounded lbflow 2 "duct.vtk:9: FIELD array 'delta' holds nan" "$lbflow" duct.vtk --refine 1 -o out.csv
}
case_vtk_spacing_overflow_refused() {
  float_vtk 1e308
  bounded lbflow 2 "duct.vtk:7: SPACING 1e+308 .*overflows" "$lbflow" duct.vtk --refine 1 -o out.csv
  float_vtk 1e200
  bounded lbflow 2 "duct.vtk:7: SPACING 1e+200 .*overflows" "$lbflow" duct.vtk --refine 1 -o out.csv
  # a large but sound spacing runs, and every number it writes is finite
  float_vtk 1e100
  "$lbflow" duct.vtk --refine 1 -q --drive force -o ok.csv || fail "spacing 1e100"
  ! grep -qiw 'inf\|nan' ok.csv || fail "non-finite number written: $(cat ok.csv)"
}

# --- item 5: checkpoints know they are intact ---
case_damaged_checkpoint_refused() {
  cluster_vtk
  "$lbflow" c.vtk --refine 1 -q --check-every 20 --max-steps 200 --checkpoint run.chk --checkpoint-every 0 \
    >/dev/null 2>&1
  [ -f run.chk ] || fail "no checkpoint"
  "$lbflow" --resume run.chk -q --max-steps 100000 -o intact.csv || fail "the intact checkpoint resumes"
  # one flipped bit in the populations
  /usr/bin/python3 - <<'PY'
data = bytearray(open("run.chk", "rb").read())
data[len(data) // 2] ^= 0x04
open("flip.chk", "wb").write(data)
data = bytearray(open("run.chk", "rb").read())
start = len(data) // 3
data[start:start + 64] = b"\xff" * 64
open("ff.chk", "wb").write(data)
open("cut.chk", "wb").write(open("run.chk", "rb").read()[:-100])
PY
  cli_tool=lbflow
  expect_error 2 "flip.chk: checkpoint damaged" "$lbflow" --resume flip.chk -q -o out.csv
  expect_error 2 "ff.chk: checkpoint damaged" "$lbflow" --resume ff.chk -q -o out.csv
  expect_error 2 "cut.chk: checkpoint damaged" "$lbflow" --resume cut.chk -q -o out.csv
}

# --- item 6: limits from the option or the header, before large allocations ---
case_raw_pipe_shorter_than_dims() {
  bounded lbflow 2 "<stdin>: holds 2 bytes, --dims 1000x1000x1000 needs 1000000000" \
    sh -c 'printf ab | "$0" - --dims 1000x1000x1000 -o out.csv' "$lbflow"
  bounded lbflow 2 "--dims: 10000x10000x10000 makes 2^31 - 1 voxels or more" \
    sh -c 'printf ab | "$0" - --dims 10000x10000x10000 -o out.csv' "$lbflow"
  bounded lbflow 2 "--dims: 2048x1024x1024 makes 2^31 - 1 voxels or more" \
    sh -c 'printf ab | "$0" - --dims 2048x1024x1024 -o out.csv' "$lbflow"
}
case_vtk_header_over_the_labelling_limit() {
  printf '# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2048 1024 1024\nPOINT_DATA 2147483648\nSCALARS v unsigned_char 1\nLOOKUP_TABLE default\n' >big.vtk
  truncate -s 2200000000 big.vtk  # sparse: the size of the data, no disk used
  bounded lbflow 2 "big.vtk: DIMENSIONS 2048 1024 1024 make 2^31 - 1 points or more" "$lbflow" big.vtk -o out.csv
}
case_rndmesh_level_by_the_mesh_it_makes() {
  # icosa at level 14 would have been 671 million vertices (tens of GB) before any check
  bounded rndmesh 2 "--level: level 14 of icosa makes 671088642 vertices, more than 16777216" \
    "$bin/rndmesh" icosa --level 14 -o out.off
  bounded rndmesh 2 "--level: level 12 of octa makes" "$bin/rndmesh" octa --level 12 -o out.off
  "$bin/rndmesh" simple --level 14 -q -o simple.off || fail "simple at level 14 (49,154 vertices)"
}
case_jam_spheres_bounded_at_the_option() {
  bounded shellpack 2 "--spheres: N = 2000000000 is more than the 1000000 spheres" "$shellpack" jam -N 2000000000 -o out.xyz
}
case_jam2d_box_bounded_at_the_option() {
  bounded jam2d 2 "--box: must be at most 1000 sigma" "$bin/jam2d" grow --box 1e300 -o out.xyz
  bounded jam2d 2 "--box: must be at most 1000 sigma" "$bin/jam2d" sweep --box 1e6 --seeds 1:2 -o out.csv
}
case_refine_too_large() {
  cluster_vtk
  bounded lbflow 2 "--refine: 8 x 8 x 8 voxels of c.vtk at M = 100000 make .* lattice nodes, more than 2\\^40" \
    "$lbflow" c.vtk --refine 100000 -o out.csv
  bounded lbflow 2 "--refine: .* more than 2\\^31 - 2" "$lbflow" sphere.xyz --delta 0.01 --refine 100 -o out.csv
}

# --- item 7: '-' reads every format ---
case_stdin_every_format() {
  "$shellpack" jam -N 12 -q -o - 2>/dev/null | "$lbflow" - --delta 0.1 --refine 1 -q -o xyz.csv ||
    fail "a sphere packing on stdin"
  [ "$(grep -v '^#' xyz.csv | wc -l)" -eq 2 ] || fail "no row: $(cat xyz.csv)"
  float_vtk
  "$lbflow" - --refine 1 -q --drive force -o float.csv <duct.vtk || fail "a float VTK on stdin"
  "$lbflow" duct.vtk --refine 1 -q --drive force -o file.csv || fail "the same from the file"
  # the same row but for the file's name
  cmp <(grep -v '^#' float.csv | tail -1 | cut -d, -f2-) <(grep -v '^#' file.csv | tail -1 | cut -d, -f2-) ||
    fail "stdin and file differ: $(diff float.csv file.csv)"
}

run_cases "$@"
