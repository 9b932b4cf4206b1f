#!/usr/bin/env bash
# compare_commits.sh BEFORE [AFTER_BUILD] [ROUNDS]: the kernels of make bench (FIRE on spheres,
# labelling, lbflow's sweep, shell forces, jam2d) built at commit BEFORE (in a scratch worktree;
# or BEFORE is a build folder made at that commit) and from AFTER_BUILD (default build/, the checkout), run in alternation ROUNDS times (default 3)
# on one thread; prints one CSV row per figure with the best of each side and their ratio.
# Alternating and keeping the best keeps a busy machine's noise out of the comparison as far as
# it can. Used for "no figure gets slower" after a reorganisation: make bench-compare BEFORE=rev.
set -euo pipefail
before=${1:?usage: compare_commits.sh BEFORE [AFTER_BUILD] [ROUNDS]}
after_build=${2:-build}
rounds=${3:-3}
kernels=(bench_spheres bench_voxel bench_lbm bench_shell bench_jam2d)

work=$(mktemp -d)
trap 'git worktree remove --force "$work/tree" >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
if [ -d "$before/bench" ]; then
  before_build=$before
else
  git worktree add --detach "$work/tree" "$before" >/dev/null
  echo "compare_commits: building the kernels at $(git rev-parse --short "$before")" >&2
  before_build=$work/tree/build
  cmake -S "$work/tree" -B "$before_build" -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$before_build" -j 2 --target "${kernels[@]}" >/dev/null
cmake --build "$after_build" -j 2 --target "${kernels[@]}" >/dev/null

# One figure per line, "name,value" (larger is faster), from the bench programs' own outputs.
figures() {
  local b=$1
  export OMP_NUM_THREADS=1
  "$b/bench_spheres" fire 1024 0.66 1e-12 1 | awk -F, '{printf "fire_particle_iterations_per_s_1024,%s\n", $8}'
  "$b/bench_voxel" label 256 0.35 1 "$work/image.u8" | awk -F, '{printf "label_mvoxels_per_s_256,%s\n", $8}'
  "$b/bench_lbm" speed 128 1 mrt 40 | awk -F, '$1 == "dense" || $1 == "porous" {printf "lbm_mlups_%s_128,%s\n", $1, $9}'
  "$b/bench_shell" terms 4 | awk -F, '$3 == "us" {printf "shell_%s_per_s,%s\n", $1, 1e6 / $2}'
  "$b/bench_jam2d" 10 1 3 | awk -F, '{s += $7} END {printf "jam2d_packings_per_s_box10,%s\n", NR / s}'
}

for side in before after; do : >"$work/$side.csv"; done
for ((r = 0; r < rounds; r++)); do
  figures "$before_build/bench" >>"$work/before.csv"
  figures "$after_build/bench" >>"$work/after.csv"
done
echo "figure,before_best,after_best,after_over_before"
awk -F, 'FNR == NR { if (!($1 in b) || $2 > b[$1]) b[$1] = $2; next }
         { if (!($1 in a) || $2 > a[$1]) a[$1] = $2; if (!($1 in seen)) { seen[$1] = 1; order[++n] = $1 } }
         END { for (i = 1; i <= n; ++i) { f = order[i]; printf "%s,%.4g,%.4g,%.3f\n", f, b[f], a[f], a[f] / b[f] } }' \
  "$work/before.csv" "$work/after.csv"
