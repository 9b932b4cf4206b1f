#!/usr/bin/env bash
# make bench, study: the wall time of each stage of the study's campaign (make study) at the demo
# size (STUDY=demo, make -j2, one thread a task), run from scratch into $out/study, per stage:
# tasks, total, mean and longest task. BENCH_STUDY=default measures the default campaign instead
# (about an hour). Sourced by scripts/bench/run.sh ($build, $out, $machine, $stamp).
preset=${BENCH_STUDY:-demo}
echo "== make study STUDY=$preset: wall time per stage" >&2
rm -rf "$out/study"
start=$(date +%s.%N)
make -f scripts/study/study.mk --no-print-directory STUDY="$preset" STUDY_DIR="$out/study" BUILD="$build" THREADS=1 -j2 all \
  >"$out/study.log" 2>&1 || { tail -20 "$out/study.log" >&2; echo "make bench: the study failed" >&2; exit 1; }
wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
{
  bench_header
  echo "# study=$preset"
  echo "stage,tasks,total_s,mean_s,longest_s,campaign_wall_s"
  for stage in mesh jam compress analyze percolate flow; do
    f="$out/study/log/$stage.csv"
    [ -f "$f" ] && awk -F, -v s="$stage" -v w="$wall" '{ t += $3; n++; if ($3 > m) m = $3 }
      END { printf "%s,%d,%.2f,%.3f,%.2f,%s\n", s, n, t, t / n, m, w }' "$f"
  done
} | tee "$out/study.csv" >&2
