#!/usr/bin/env bash
# rndmesh as a user runs it. `rndmesh_cli.sh --list` prints the cases; `rndmesh_cli.sh CASE`
# runs one (ctest registers each). Needs CMP_BIN (the built programs).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
rndmesh="$bin/rndmesh"
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=rndmesh
enter_scratch_dir
off_counts() { awk '!/^#/ && NF { if (++n == 2) { print $1, $2; exit } }' "$1"; }

case_help() {
  "$rndmesh" --help | grep -q "random" || fail "top-level help lacks subcommands"
  "$rndmesh" random --help | grep -q -- "--tmin" || fail "random --help lacks --tmin"
  "$rndmesh" random --help | grep -q "1000" || fail "random --help lacks the T_max default"
  "$rndmesh" icosa --help | grep -q -- "--level" || fail "icosa --help lacks --level"
  "$rndmesh" --version | grep -Eq "^rndmesh [0-9]" || fail "--version"
  "$rndmesh" --help-all | grep -q -- "--tmin" || fail "--help-all lacks the subcommands' options"
}
case_icosa() {
  "$rndmesh" icosa --level 4 -o cell.off -q || fail "icosa failed"
  [ "$(off_counts cell.off)" = "642 1280" ] || fail "counts $(off_counts cell.off)"
  grep -q "^# q_A=0.66" cell.off || fail "no quality comment"
  grep -q "^# rndmesh .*icosa --level 4" cell.off || fail "no provenance"
}
case_all_schemes() {
  for s in simple tetra octa icosa; do
    "$rndmesh" $s --level 3 --radius 2 -o out.$s.off -q || fail "$s"
    "$rndmesh" stats out.$s.off -o out.$s.csv -q || fail "stats $s"
    grep -q "^out.$s.off,.*" out.$s.csv || fail "stats row $s"
  done
  rm -f out.*
}
case_random_reproducible() {
  "$rndmesh" random -n 200 --seed 7 --sweeps 5 --anneals 20 -o a.off -q || fail "random a"
  "$rndmesh" random -n 200 --seed 7 --sweeps 5 --anneals 20 -o b.off -q || fail "random b"
  "$rndmesh" random -n 200 --seed 8 --sweeps 5 --anneals 20 -o c.off -q || fail "random c"
  cmp -s <(grep -v '^# rndmesh' a.off) <(grep -v '^# rndmesh' b.off) || fail "same seed, different files"
  cmp -s <(grep -v '^#' a.off) <(grep -v '^#' c.off) && fail "different seeds, same mesh"
  [ "$(off_counts a.off)" = "200 396" ] || fail "counts $(off_counts a.off)"
  grep -q "^# closed_manifold=1" a.off || fail "not closed"
  grep -q "^# euler_characteristic=2" a.off || fail "euler"
}
case_random_seeds_parallel() {
  # Four seeds on two threads: the same files as one seed at a time.
  "$rndmesh" random -n 120 --seeds 3:6 --threads 2 --sweeps 5 --anneals 10 -o 'm_{seed}.off' -q || fail "seeds"
  for s in 3 4 5 6; do
    [ -f m_$s.off ] || fail "m_$s.off missing"
    "$rndmesh" random -n 120 --seed $s --threads 1 --sweeps 5 --anneals 10 -o one.off -q || fail "seed $s"
    cmp -s <(grep -v '^# rndmesh' m_$s.off) <(grep -v '^# rndmesh' one.off) || fail "seed $s differs"
  done
  expect_error 2 "{seed}" "$rndmesh" random -n 120 --seeds 1:2 -o out.off
  expect_error 2 "seeds" "$rndmesh" random -n 120 --seeds 2:1 -o 'out_{seed}.off'
}
case_random_stdout_and_trace() {
  "$rndmesh" random -n 50 --sweeps 2 --anneals 5 --trace trace.csv -q > mesh.off || fail "stdout"
  [ "$(off_counts mesh.off)" = "50 96" ] || fail "stdout counts"
  [ "$(grep -vc '^#' trace.csv)" = 6 ] || fail "trace rows: $(cat trace.csv)"
  head -2 trace.csv | grep -q "temperature_en" || fail "trace header"
}
case_stats_csv() {
  "$rndmesh" octa --level 2 -o o.off -q
  "$rndmesh" stats o.off o.off > s.csv || fail "stats"
  grep -q "^file,vertices,faces" s.csv || fail "header: $(cat s.csv)"
  [ "$(grep -c '^o.off,18,32,48,2,1,1,0.57' s.csv)" = 2 ] || fail "rows: $(cat s.csv)"
  cat o.off | "$rndmesh" stats - | grep -q "^-,18,32" || fail "stdin"
}
case_meshio_reads_output() {
  # What MeshLab and ParaView would open: meshio (a real OFF reader) reads rndmesh's files,
  # comments and all, with the same vertices and triangles.
  "$rndmesh" random -n 100 --sweeps 5 --anneals 10 -o r.off -q || fail "random"
  "$rndmesh" simple --level 4 -o s.off -q || fail "simple"
  /usr/bin/python3 - <<'PY' || fail "meshio"
import meshio, numpy as np
for name, nv, nf in (("r.off", 100, 196), ("s.off", 50, 96)):
    m = meshio.read(name)
    assert m.points.shape == (nv, 3), m.points.shape
    tri = m.cells_dict["triangle"]
    assert tri.shape == (nf, 3), tri.shape
    # outward: the signed volume (1/6) sum a.(b x c) is positive
    a, b, c = (m.points[tri[:, k]] for k in range(3))
    assert np.einsum("ij,ij->i", a, np.cross(b, c)).sum() > 0
PY
}
case_bad_missing_file() { expect_error 2 "nothing.off: cannot open" "$rndmesh" stats nothing.off -o out.csv; }
case_bad_empty_file() { : > empty.off; expect_error 2 "empty.off.*empty" "$rndmesh" stats empty.off -o out.csv; }
case_bad_truncated() {
  "$rndmesh" tetra --level 2 -o t.off -q; head -n 20 t.off > trunc.off
  expect_error 2 "trunc.off:[0-9]*: " "$rndmesh" stats trunc.off -o out.csv
}
case_bad_face_index() {
  printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 9\n3 1 2 3\n' > bad.off
  expect_error 2 "bad.off:9: .*9" "$rndmesh" stats bad.off -o out.csv
}
case_bad_number() {
  printf 'OFF\n4 4 0\n0 0 0\n1 x 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n' > bad.off
  expect_error 2 "bad.off:4: .*x" "$rndmesh" stats bad.off -o out.csv
}
case_bad_quad() {
  printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n' > bad.off
  expect_error 2 "bad.off:7: .*triangle" "$rndmesh" stats bad.off -o out.csv
}
case_bad_nan() {
  printf 'OFF\n4 4 0\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 2 3\n3 1 2 3\n' > bad.off
  expect_error 2 "bad.off:4: " "$rndmesh" stats bad.off -o out.csv
}
case_bad_points() { expect_error 2 "at least 4" "$rndmesh" random -n 3 -o out.off; }
case_bad_radius() {
  expect_error 2 "radius" "$rndmesh" random -n 10 --radius -1 -o out.off
  expect_error 2 "radius" "$rndmesh" icosa --level 2 --radius -1 -o out.off
}
case_bad_temperatures() { expect_error 2 "T_max" "$rndmesh" random -n 10 --tmin 10 --tmax 1 -o out.off; }
case_bad_level() { expect_error 2 "level" "$rndmesh" icosa --level 0 -o out.off; }
case_bad_subcommand() { expect_error 2 "" "$rndmesh" dodeca -o out.off; }
case_bad_output_folder() { expect_error 2 "no/such/dir/out.off" "$rndmesh" icosa -o no/such/dir/out.off; }

run_cases "$@"
