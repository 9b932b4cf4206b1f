#!/usr/bin/env bash
# make bench, lbflow as a user runs it (the kernel's MLUPS and the bandwidth bound are
# 35-lbflow.sh's): a thesis-sized cluster (N = 50 jammed spheres, delta = 0.04, as jammed)
# through the whole program at M = 1 to convergence on 1 and 2 threads, and at M = 3 (the
# thesis's ~10^7 nodes) for LBFLOW_M3_STEPS (400) steps: speed, memory per fluid node and peak
# memory; the time to convergence at M = 3 is estimated from the M = 1 steps times 1.4 (what
# the M = 3 runs of make flow-figure took over M = 1). Each row has the bandwidth bounds of a
# triad measured just before it on as many threads (bench_lbm triad: 304 bytes per update, and
# 340 with the link table's), as the kernel rows do.
# Sourced by scripts/bench/run.sh ($build, $bench, $out, $machine, $stamp).
echo "== lbflow: N = 50 jammed spheres, delta = 0.04: M = 1 to convergence, M = 3 for ${LBFLOW_M3_STEPS:-400} steps" >&2
lb_dir=$(mktemp -d)
"$build/bin/shellpack" jam -N 50 --seed 1 -q -o "$lb_dir/jam.xyz" --csv /dev/null
"$build/bin/percolate" "$lb_dir/jam.xyz" --delta 0.04 -q -o "$lb_dir/c.vtk" --csv "$lb_dir/p.csv"
lb_row() {  # M threads max_steps: one CSV row, with the triad bound measured just before the run
  "$bench/bench_lbm" triad "$2" | tail -n 1 > "$lb_dir/triad"
  /usr/bin/time -f "%M" -o "$lb_dir/rss" "$build/bin/lbflow" "$lb_dir/c.vtk" --refine "$1" --threads "$2" \
    --max-steps "$3" --timings -q -o "$lb_dir/f.csv" 2>/dev/null || true
  /usr/bin/python3 - "$lb_dir/f.csv" "$2" "$(cat "$lb_dir/rss")" "$(cat "$lb_dir/triad")" <<'PY'
import csv, sys
r = next(csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#")))
nodes = int(r["nx"]) * int(r["ny"]) * int(r["nz"]) * int(r["refine"]) ** 3
print(",".join([r["refine"], sys.argv[2], r["nx"], str(nodes), r["fluid_nodes"], r["porosity"], r["steps"],
                r["converged"], r["seconds"], r["mlups"], r["bytes_per_fluid_node"],
                f"{int(sys.argv[3].split()[-1]) / 1024:.0f}", r["permeability_d02"], r["tortuosity"], sys.argv[4]]))
PY
}
{
  bench_header
  echo "refine,threads,voxels_per_side,nodes,fluid_nodes,porosity,steps,converged,seconds,mlups,bytes_per_fluid_node,peak_rss_mb,permeability_d02,tortuosity,triad_gbs,bound_mlups,bound_with_links_mlups"
  lb_row 1 1 200000
  lb_row 1 2 200000
  lb_row 3 2 "${LBFLOW_M3_STEPS:-400}"
} | tee "$out/lbflow_run.csv" >&2
rm -rf "$lb_dir"
