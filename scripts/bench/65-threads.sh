#!/usr/bin/env bash
# make bench, threads under load: every parallel path on 1 thread, on 2 threads, and on 2
# threads while another process keeps one core busy (`sh -c 'while :; do :; done'`), as
# happens under make -j or on a shared node. The loaded two-thread run should stay within
# about 20 % of the quiet one-thread run. Sourced by scripts/bench/run.sh ($build, $bench, $out,
# $machine, $stamp); the best of BENCH_REPEAT runs (default 2) of each case is kept.
echo "== threads under load: 1 thread, 2 threads, 2 threads with another process busy on one core" >&2
work=$(mktemp -d)
repeat=${BENCH_REPEAT:-2}
bin="$build/bin"
"$bench/bench_fit" data >"$work/kc.csv"
"$bin/shellpack" jam -N 50 --seed 1 -q -o "$work/jam.xyz" --csv /dev/null
"$bin/percolate" "$work/jam.xyz" --delta 0.04 -q -o "$work/cluster.vtk" --csv /dev/null
"$bin/shellpack" jam -N 16 --seed 1 -q -o "$work/jam16.xyz" --csv /dev/null
"$bin/rndmesh" icosa --level 4 --radius 0.5 -q -o "$work/ico4.off"
"$bin/rndmesh" icosa --level 5 --radius 0.5 -q -o "$work/ico5.off"

# name|what it runs|command ({T}: the thread count)
cases=(
  "fire_hertz_4096|FIRE + Hertz forces, 4096 spheres, phi 0.66, max force 1e-12|OMP_NUM_THREADS={T} $bench/bench_spheres fire 4096 0.66 1e-12 1"
  "percolate_marking|percolate marking: 50 shells x 2562 vertices, delta 0.03|$bench/bench_voxel voxelise {T}"
  "percolate_labelling|percolate labelling: 256^3 random image, porosity 0.35|$bench/bench_voxel label 256 0.35 {T}"
  "percolate_cli|percolate on a jammed packing of 50 spheres, --scale 1.1 --delta 0.01|$bin/percolate $work/jam.xyz --scale 1.1 --delta 0.01 --threads {T} -q --csv /dev/null"
  "rndmesh_seeds|rndmesh random -n 300 --seeds 1:4|$bin/rndmesh random -n 300 --seeds 1:4 --threads {T} -q -o $work/m_{seed}.off"
  "lbflow_cluster|lbflow on the cluster of a jammed packing of 50 spheres, delta 0.04, M = 1, 600 steps|$bin/lbflow $work/cluster.vtk --refine 1 --max-steps 600 --threads {T} -q -o /dev/null || true"
  "jam2d_sweep|jam2d sweep --box 8 --seeds 1:4 (jamming, 4 colonies)|$bin/jam2d sweep --box 8 --seeds 1:4 --threads {T} -q > /dev/null"
  "shell_inflate_2562|shellpack shell: inflate a 2562-vertex shell (SVK + hinge-uniform + turgor) to equilibrium|OMP_NUM_THREADS={T} $bench/bench_shell inflate 5"
  "compress_faces_16x642|shellpack compress: 16 shells x 642 vertices, hertz-faces, the first 12 box steps|$bin/shellpack compress $work/jam16.xyz --mesh $work/ico4.off --contact hertz-faces --phi 0.9 --stop-after-steps 12 --threads {T} -q -o /dev/null --csv /dev/null"
  "compress_faces_50x2562|shellpack compress: 50 shells x 2562 vertices, hertz-faces, the first 3 box steps (passes large enough to run on both threads)|$bin/shellpack compress $work/jam.xyz --mesh $work/ico5.off --contact hertz-faces --phi 0.9 --stop-after-steps 3 --threads {T} -q -o /dev/null --csv /dev/null"
  "compress_vertices_16x642|shellpack compress: 16 shells x 642 vertices, hertz-vertices, the first 12 box steps|$bin/shellpack compress $work/jam16.xyz --mesh $work/ico4.off --phi 0.9 --stop-after-steps 12 --threads {T} -q -o /dev/null --csv /dev/null"
  "kcfit_bootstrap|kcfit kc-percolation, 120 points, --bootstrap 1000|$bin/kcfit $work/kc.csv --model kc-percolation --loss log --bootstrap 1000 --threads {T} -o $work/fit.csv"
)

# Wall seconds of the best of $repeat runs of a command (nanosecond clock, integer arithmetic).
best_time() {
  local best="" t0 t1 ns
  for _ in $(seq "$repeat"); do
    t0=$(date +%s%N)
    bash -c "$1" >/dev/null 2>&1 || { echo NaN; return; }
    t1=$(date +%s%N)
    ns=$((t1 - t0))
    if [ -z "$best" ] || [ "$ns" -lt "$best" ]; then best=$ns; fi
  done
  printf '%d.%03d' $((best / 1000000000)) $((best / 1000000 % 1000))
}

{
  bench_header
  echo "# wait_policy=${OMP_WAIT_POLICY:-toolkit default (passive)}"
  echo "case,what,threads_1_s,threads_2_s,loaded_threads_2_s,loaded_over_quiet_1"
  for c in "${cases[@]}"; do
    IFS='|' read -r name what cmd <<<"$c"
    one=$(best_time "${cmd//\{T\}/1}")
    two=$(best_time "${cmd//\{T\}/2}")
    sh -c 'while :; do :; done' &
    load=$!
    loaded=$(best_time "${cmd//\{T\}/2}")
    kill "$load"; wait "$load" 2>/dev/null || true
    ratio=$(/usr/bin/python3 -c "import sys; print(f'{float(sys.argv[1]) / float(sys.argv[2]):.2f}')" "$loaded" "$one")
    printf '%s,"%s",%s,%s,%s,%s\n' "$name" "$what" "$one" "$two" "$loaded" "$ratio"
  done
} | tee "$out/threads_loaded.csv" >&2
rm -rf "$work"
