#!/usr/bin/env bash
# make bench, compress: shellpack compress as a user runs it, from a jammed packing with
# icosahedral shells, the default box step (0.004 D0), tolerance and constant volume: time per
# box step and FIRE iterations per second over the first steps after jamming (step 0, the
# inflation, left out), 16 x 642 on 1 and 2 threads and 50 x 2562 on 2 (BENCH_COMPRESS_LARGE=0
# skips it); then the wall time of a whole compression to phi = 0.95 (16 x 642, hertz-faces).
# Sourced by scripts/bench/run.sh ($build, $out, $machine, $stamp).
echo "== shellpack compress: time per box step and FIRE iterations per second" >&2
cmp_work=$(mktemp -d)
compress_row() {  # compress_row N LEVEL STEPS THREADS
  local n=$1 level=$2 steps=$3 threads=$4
  [ -s "$cmp_work/j$n.xyz" ] || "$build/bin/shellpack" jam -N "$n" --seed 1 -o "$cmp_work/j$n.xyz" -q >/dev/null
  [ -s "$cmp_work/ico$level.off" ] || "$build/bin/rndmesh" icosa --level "$level" -o "$cmp_work/ico$level.off" -q
  "$build/bin/shellpack" compress "$cmp_work/j$n.xyz" --mesh "$cmp_work/ico$level.off" --contact hertz-vertices --phi 0.95 --timings -q \
    --stop-after-steps "$steps" --threads "$threads" --csv "$cmp_work/c.csv" --no-penetration-check
  /usr/bin/python3 - "$cmp_work/c.csv" "$n" "$threads" <<'PY'
import csv, sys
path, n, threads = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
meta = {l[2:].split("=", 1)[0]: l[2:].split("=", 1)[1].strip() for l in open(path) if l.startswith("# ")}
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
steps = rows[1:]
t = sum(float(r["seconds"]) for r in steps)
its = sum(int(r["iterations"]) for r in steps)
upd = sum(int(r["volume_updates"]) for r in steps)
print(f"{n},{meta['vertices_per_shell']},{threads},{len(steps)},{float(rows[0]['seconds']):.3g},{t:.4g},{t / len(steps):.4g},"
      f"{its},{its / t:.4g},{upd},{float(rows[0]['phi']):.4f},{float(steps[-1]['phi']):.4f},{meta['vertex_radius'][:6]}")
PY
}
{
  bench_header
  echo "shells,vertices_per_shell,threads,steps,start_seconds,seconds,seconds_per_step,fire_iterations,iterations_per_s,volume_updates,phi_start,phi_end,vertex_radius"
  for threads in 1 2; do compress_row 16 4 20 $threads; done
  if [ "${BENCH_COMPRESS_LARGE:-1}" = 1 ]; then compress_row 50 5 3 2; fi
} | tee "$out/compress_steps.csv" >&2
# A whole compression as a user runs one towards confluence: 16 x 642 shells with hertz-faces
# from jamming to phi = 0.95, the penetration check after every step, on all threads; wall
# time of the process (mesh and packing made beforehand).
echo "== shellpack compress: 16 x 642 shells with faces, jamming to phi 0.95" >&2
{
  bench_header
  echo "shells,vertices_per_shell,contact,threads,phi_start,phi_end,steps,fire_iterations,volume_updates,wall_seconds"
  start=$(date +%s.%N)
  "$build/bin/shellpack" compress "$cmp_work/j16.xyz" --mesh "$cmp_work/ico4.off" --contact hertz-faces \
    --phi 0.95 -q --csv "$cmp_work/w.csv"
  end=$(date +%s.%N)
  /usr/bin/python3 - "$cmp_work/w.csv" "$start" "$end" "$(nproc)" <<'PY'
import csv, sys
path, start, end, threads = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
meta = {l[2:].split("=", 1)[0]: l[2:].split("=", 1)[1].strip() for l in open(path) if l.startswith("# ")}
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
its = sum(int(r["iterations"]) for r in rows)
upd = sum(int(r["volume_updates"]) for r in rows)
print(f"16,{meta['vertices_per_shell']},hertz-faces,{threads},{float(rows[0]['phi']):.4f},{float(rows[-1]['phi']):.4f},"
      f"{len(rows) - 1},{its},{upd},{end - start:.1f}")
PY
} | tee "$out/compress_whole.csv" >&2
rm -rf "$cmp_work"
