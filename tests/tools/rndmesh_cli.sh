#!/usr/bin/env bash
# rndmesh as a user runs it. `rndmesh_cli.sh --list` prints the cases; `rndmesh_cli.sh CASE`
# runs one (ctest registers each). Needs CMP_BIN (the built programs).
set -uo pipefail
bin=${CMP_BIN:-build/bin}
rndmesh="$bin/rndmesh"
cli_script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
source "$(dirname "${BASH_SOURCE[0]}")/../support/cli_harness.sh"
cli_tool=rndmesh
enter_scratch_dir
off_counts() { awk '!/^#/ && NF { if (++n == 2) { print $1, $2; exit } }' "$1"; }

case_help() {
  "$rndmesh" --help | grep >/dev/null "random" || fail "top-level help lacks subcommands"
  "$rndmesh" random --help | grep >/dev/null -- "--tmin" || fail "random --help lacks --tmin"
  "$rndmesh" random --help | grep >/dev/null "1000" || fail "random --help lacks the T_max default"
  "$rndmesh" icosa --help | grep >/dev/null -- "--level" || fail "icosa --help lacks --level"
  "$rndmesh" --version | grep -Eq "^rndmesh [0-9]" || fail "--version"
  "$rndmesh" --help-all | grep >/dev/null -- "--tmin" || fail "--help-all lacks the subcommands' options"
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
  same_lines "same seed, different files" '^# rndmesh' a.off b.off
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
    same_lines "seed $s differs" '^# rndmesh' m_$s.off one.off
  done
  expect_error 2 "{seed}" "$rndmesh" random -n 120 --seeds 1:2 -o out.off
  expect_error 2 "seeds" "$rndmesh" random -n 120 --seeds 2:1 -o 'out_{seed}.off'
}
case_random_stdout_and_trace() {
  "$rndmesh" random -n 50 --sweeps 2 --anneals 5 --trace trace.csv -q > mesh.off || fail "stdout"
  [ "$(off_counts mesh.off)" = "50 96" ] || fail "stdout counts"
  [ "$(grep -vc '^#' trace.csv)" = 6 ] || fail "trace rows: $(cat trace.csv)"
  grep -v '^#' trace.csv | head -1 | grep >/dev/null "temperature_en" || fail "trace header"
}
case_stats_csv() {
  "$rndmesh" octa --level 2 -o o.off -q
  "$rndmesh" stats o.off o.off > s.csv || fail "stats"
  grep -q "^file,vertices,faces" s.csv || fail "header: $(cat s.csv)"
  [ "$(grep -c '^o.off,18,32,48,2,1,1,0.57' s.csv)" = 2 ] || fail "rows: $(cat s.csv)"
  cat o.off | "$rndmesh" stats - | grep >/dev/null "^-,18,32" || fail "stdin"
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
case_bad_temperatures() { expect_error 2 "--tmax: must be at least --tmin" "$rndmesh" random -n 10 --tmin 10 --tmax 1 -o out.off; }
case_bad_level() {
  expect_error 2 "--level: must lie in \[1, 14\], got '0'" "$rndmesh" icosa --level 0 -o out.off
  expect_error 2 "--level: 'abc' is not an integer" "$rndmesh" icosa --level abc -o out.off
  # Every scheme, both ends: one line naming --level (its vertex count is not computed for a
  # level out of range: level 0 shifted by -2), nothing written.
  local s l
  for s in simple tetra octa icosa; do
    for l in -1 0 15 64; do
      expect_error 2 "--level: must lie in \[1, 14\], got '$l'$" "$rndmesh" $s --level $l -o out.off
    done
  done
  expect_error 2 "--level: .*99999999999" "$rndmesh" icosa --level 99999999999 -o out.off
  expect_error 2 "--points: '2e3' is not an integer" "$rndmesh" random -n 2e3 -o out.off
  expect_error 2 "--radius: '1x' is not a finite number" "$rndmesh" random -n 20 --radius 1x -o out.off
}
case_bad_subcommand() {
  expect_error 2 "unknown subcommand 'dodeca'; the subcommands are simple, tetra, octa, icosa, random, stats" \
    "$rndmesh" dodeca -o out.off
  expect_error 2 "a subcommand is required" "$rndmesh"
  expect_error 2 "no-such" "$rndmesh" icosa --no-such -o out.off
  grep -qx "rndmesh: run 'rndmesh icosa --help' for the options" stderr.txt || fail "no help hint: $(cat stderr.txt)"
}
case_bad_options_all_at_once() {
  "$rndmesh" random -n 3 --radius -1 --anneals 0 --step nan -o out.off 2>stderr.txt; [ $? = 2 ] || fail "status"
  diff - stderr.txt <<'EOT' || fail "messages"
rndmesh: --points: must be at least 4, got '3'
rndmesh: --radius: must be positive, got '-1'
rndmesh: --anneals: must be at least 1, got '0'
rndmesh: --step: 'nan' is not a finite number
rndmesh: run 'rndmesh random --help' for the options
EOT
  ! ls out.* .out.* 2>/dev/null | grep >/dev/null . || fail "left a file"
}
case_help_shows_types() {
  "$rndmesh" random --help | grep -Eq -- "-n,--points INT REQUIRED( |$)" || fail "$("$rndmesh" random --help | grep points)"
  "$rndmesh" random --help | grep >/dev/null -- "--tmax FLOAT=1000" || fail "no --tmax default"
  "$rndmesh" random --help | grep >/dev/null -- "--resume" || fail "no --resume"
}
interrupted_case() {  # interrupted_case SIGNAL STATUS
  interrupt_run "$1" "$rndmesh" random -n 40000 --seeds 1:2 --threads 2 -o 'out_{seed}.off' --trace 'out_{seed}.csv'
  local got=$?
  [ "$got" = "$2" ] || fail "exit $got after SIG$1, expected $2: $(cat interrupt.err)"
  [ "$(cat interrupt.err)" = "rndmesh: interrupted" ] || fail "stderr: $(cat interrupt.err)"
  [ -z "$(ls -A | grep -v '^interrupt.err$')" ] || fail "left files: $(ls -A)"
}
case_ready_file() {
  # CMP_READY_FILE (what interrupt_run waits for) appears once the options are checked: not
  # for a refused command line, and before the run's result.
  CMP_READY_FILE=$PWD/bad.ready "$rndmesh" icosa --level 0 -o out.off 2>/dev/null && fail "--level 0 accepted"
  [ ! -e bad.ready ] || fail "ready file written for a refused command line"
  CMP_READY_FILE=$PWD/good.ready "$rndmesh" icosa --level 2 -o good.off -q || fail "icosa --level 2"
  [ -e good.ready ] && [ -s good.off ] || fail "no ready file: $(ls -A)"
  [ ! good.ready -nt good.off ] || fail "ready file written after the result"
}
case_interrupt_sigint() { interrupted_case INT 130; }
case_interrupt_sigterm() { interrupted_case TERM 143; }
case_seeds_resume() {
  local opts=(random -n 60 --sweeps 2 --anneals 5 --threads 1 -q)
  "$rndmesh" "${opts[@]}" --seeds 1:3 -o 'm_{seed}.off' --trace 't_{seed}.csv' || fail "first run"
  rm m_2.off
  touch -d '2001-01-01' m_1.off t_1.csv m_3.off t_3.csv
  "$rndmesh" random -n 60 --sweeps 2 --anneals 5 --threads 1 --seeds 1:3 -o 'm_{seed}.off' --trace 't_{seed}.csv' \
    --resume 2>err.txt || fail "resume: $(cat err.txt)"
  grep -q "rndmesh: --resume: 2 of 3 seeds already done" err.txt || fail "stderr: $(cat err.txt)"
  [ -f m_2.off ] || fail "seed 2 not redone"
  [ -n "$(find m_2.off t_2.csv -newer m_1.off)" ] || fail "seed 2's files not rewritten"
  [ -z "$(find m_1.off t_1.csv m_3.off t_3.csv -newer m_2.off)" ] || fail "a complete seed was redone"
  [ "$(grep -c '^# provenance' t_2.csv)" = 1 ] || fail "trace of seed 2"
  expect_error 2 "--resume: needs -o FILE" "$rndmesh" random -n 60 --resume
}
case_summary_after_progress_bar() {
  # On a terminal the bar really draws; the summary must start on its own line.
  on_terminal tty.txt "$rndmesh" random -n 300 --sweeps 20 --anneals 40 -o rnd300.off || fail "run: $(cat tty.txt)"
  grep -aq "annealing \[" tty.txt || fail "no progress bar drawn on the terminal: $(cat -v tty.txt)"
  /usr/bin/python3 - <<'PY' || fail "summary glued to the bar: $(cat -v tty.txt)"
import re, sys
screen = open("tty.txt", "rb").read().decode()
# What a terminal shows: a carriage return goes back to column 0 and ESC[K clears the rest.
lines, line, col = [], [], 0
i = 0
while i < len(screen):
    if screen.startswith("\x1b[K", i):
        del line[col:]; i += 3; continue
    c = screen[i]; i += 1
    if c == "\r": col = 0
    elif c == "\n": lines.append("".join(line)); line, col = [], 0
    else:
        if col < len(line): line[col] = c
        else: line.append(c)
        col += 1
lines.append("".join(line))
summary = [l for l in lines if "rnd300.off:" in l]
sys.exit(0 if summary and all(l.startswith("rndmesh: rnd300.off:") for l in summary) else 1)
PY
}
case_same_seed_same_bytes() {
  # The files of a seeded run are the same bytes on every run and with 1 or 2 threads, the
  # provenance line (which holds the command line) aside.
  for run in a b; do
    for t in 1 2; do
      "$rndmesh" random -n 150 --sweeps 5 --anneals 10 --seeds 4:5 --threads $t -o "${run}${t}_{seed}.off" \
        --trace "${run}${t}_{seed}.csv" -q || fail "run $run threads $t"
    done
  done
  for s in 4 5; do
    for f in a2_$s.off b1_$s.off b2_$s.off; do
      same_lines "$f differs from a1_$s.off" '^# rndmesh ' a1_$s.off $f
    done
    for f in a2_$s.csv b1_$s.csv b2_$s.csv; do
      same_lines "$f differs from a1_$s.csv" '^# provenance=' a1_$s.csv $f
    done
  done
  ! cmp -s a1_4.off a1_5.off || fail "two seeds, one mesh"
}
case_trace_names_n_and_seed() {
  "$rndmesh" random -n 50 --seed 9 --sweeps 2 --anneals 5 --trace tr.csv -o m.off -q || fail "run"
  grep -qx "# points=50" tr.csv || fail "no points line: $(head tr.csv)"
  grep -qx "# seed=9" tr.csv || fail "no seed line"
  # scripts/figures/plot_anneal.gp (make run's anneal.png) puts both in its title
  local gp="$cli_script_dir/../../scripts/figures/plot_anneal.gp"
  title=$(gnuplot -e "in='tr.csv'; out='anneal.png'; load '$gp'; print sprintf('N = %s points on the sphere, seed %s', N, seed)" 2>&1) ||
    fail "gnuplot: $title"
  [ "$title" = "N = 50 points on the sphere, seed 9" ] || fail "title values: $title"
  grep -q 'title sprintf("simulated annealing of N = %s points on the sphere, seed %s", N, seed)' "$gp" || fail "title"
  [ -s anneal.png ] || fail "no figure"
}
case_bad_output_folder() { expect_error 2 "no/such/dir/out.off" "$rndmesh" icosa -o no/such/dir/out.off; }

run_cases "$@"
