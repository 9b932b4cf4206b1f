#!/usr/bin/env bash
# make bench, compress: shellpack compress as a user runs it, from a jammed packing with
# icosahedral shells, the default box step (0.004 D0), tolerance and constant volume: time per
# box step and FIRE iterations per second over the first steps after jamming (step 0, the
# inflation, left out), 16 x 642 on 1 and 2 threads and 50 x 2562 on 2 (BENCH_COMPRESS_LARGE=0
# skips it); then the wall time of a whole compression to phi = 0.95 (16 x 642, hertz-faces),
# and with BENCH_COMPRESS_THESIS=1 the thesis-sized one (50 x 2562, about 25 minutes).
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
# The thesis-sized compression (Chapter 5: 50 x 2,562 shells, jam seed 1) from jamming to
# phi = 0.95 with the thesis preset's COMPRESS_OPTS (scripts/study/presets/thesis.mk), on 2
# threads: about 25 minutes, so only with BENCH_COMPRESS_THESIS=1; its CSV stays in $out (and
# its row in the table) until the next such run.
if [ "${BENCH_COMPRESS_THESIS:-0}" = 1 ]; then
  echo "== shellpack compress: 50 x 2562 shells, the thesis preset, jamming to phi 0.95" >&2
  thesis_opts=$(sed -n 's/^COMPRESS_OPTS *?= *//p' "$(dirname "${BASH_SOURCE[0]}")/../study/presets/thesis.mk")
  "$build/bin/shellpack" jam -N 50 --seed 1 -o "$cmp_work/j50.xyz" -q >/dev/null
  "$build/bin/rndmesh" icosa --level 5 --radius 0.5 -o "$cmp_work/ico5.off" -q
  {
    bench_header
    echo "shells,vertices_per_shell,options,threads,phi_start,steps,fire_iterations,minutes_to_0.75,minutes_to_0.8,minutes_to_0.9,minutes_to_0.95,wall_minutes"
    start=$(date +%s.%N)
    # shellcheck disable=SC2086  # the preset's options are words
    "$build/bin/shellpack" compress "$cmp_work/j50.xyz" --mesh "$cmp_work/ico5.off" --phi 0.60:0.95:0.025 $thesis_opts \
      --threads 2 --timings -q --csv "$cmp_work/t.csv"
    end=$(date +%s.%N)
    /usr/bin/python3 - "$cmp_work/t.csv" "$start" "$end" "$thesis_opts" <<'PY'
import csv, sys
path, start, end, opts = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
meta = {l[2:].split("=", 1)[0]: l[2:].split("=", 1)[1].strip() for l in open(path) if l.startswith("# ")}
rows = list(csv.DictReader(l for l in open(path) if not l.startswith("#")))
reached, seconds = {}, 0.0
for r in rows:  # the minutes at which each target was landed (the steps' own timings)
    seconds += float(r["seconds"])
    reached.setdefault(round(float(r["phi"]), 6), seconds / 60)
at = [f"{reached[p]:.1f}" if p in reached else "" for p in (0.75, 0.8, 0.9, 0.95)]
print(f"50,{meta['vertices_per_shell']},{opts},2,{float(rows[0]['phi']):.4f},{len(rows) - 1},"
      f"{sum(int(r['iterations']) for r in rows)},{','.join(at)},{(end - start) / 60:.1f}")
PY
  } | tee "$out/compress_thesis.csv" >&2
fi
rm -rf "$cmp_work"
