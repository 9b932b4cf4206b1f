#!/usr/bin/env bash
# make bench, percolate: connected-component labelling (ours vs scipy.ndimage.label on the very
# same images, in the same run) and voxelisation of a shell packing. Sourced by
# scripts/bench/run.sh, which sets $bench, $out, $machine and $stamp.
echo "== percolate: labelling of N^3 images, ours (1 and 2 threads) vs scipy.ndimage.label (1 core)" >&2
img_dir=$(mktemp -d)
{
  bench_header
  echo "image,N,porosity,threads,voxels,components,seconds,mvoxels_per_s,peak_rss_mb,bytes_per_voxel,scipy_seconds,scipy_mvoxels_per_s,scipy_components,speedup"
  for n in 128 256 512; do
    for kind in "random 0.35" "random 0.6" "packing"; do
      set -- $kind
      raw="$img_dir/image.u8"
      rows=()
      for threads in 1 2; do
        if [ "$1" = random ]; then
          rows+=("$("$bench/bench_voxel" label $n $2 $threads "$raw")")
        else
          rows+=("$("$bench/bench_voxel" packing $n $threads "$raw")")
        fi
      done
      # scipy on the same bytes: best of 3, default structuring element (6-connectivity)
      scipy=$(/usr/bin/python3 - "$raw" $n <<'PY'
import sys, time
import numpy as np
from scipy import ndimage
n = int(sys.argv[2])
img = np.fromfile(sys.argv[1], dtype=np.uint8).reshape(n, n, n)
best = 1e30
for _ in range(3):
    t = time.perf_counter()
    lab, k = ndimage.label(img)
    best = min(best, time.perf_counter() - t)
    del lab
print(f"{best:.4f},{img.size / best / 1e6:.1f},{k}")
PY
)
      for row in "${rows[@]}"; do
        ours_s=$(echo "$row" | cut -d, -f7)
        scipy_s=${scipy%%,*}
        echo "$row,$scipy,$(/usr/bin/python3 -c "print(f'{$scipy_s / $ours_s:.2f}')")"
      done
      rm -f "$raw"
    done
  done
} | tee "$out/percolate_label.csv" >&2
rm -rf "$img_dir"

echo "== percolate: voxelisation of 50 shells x 2562 vertices (icosahedral, D0 = 1) at delta = 0.03" >&2
{
  bench_header
  echo "shells,vertices_per_shell,triangles,delta,nx,ny,nz,threads,triangles_seconds,vertices_seconds,peak_rss_mb"
  for threads in 1 2; do "$bench/bench_voxel" voxelise $threads; done
} | tee "$out/percolate_voxelise.csv" >&2
