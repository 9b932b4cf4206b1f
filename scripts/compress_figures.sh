#!/usr/bin/env bash
# make compress-figures: Figs 4.3-4.6 of the thesis at a size this machine affords, the chain
# shellpack jam -> shellpack compress -> shellpack analyze -> kcfit, no reshaping of tables.
# For each N in COMPRESS_N (default "32 50"): one jammed packing (seed COMPRESS_SEED, 1), one
# icosahedral cell of COMPRESS_LEVEL (4: 642 vertices; 5: 2562, the thesis's size), the
# shells compressed from jamming to dphi = 0.3 with packings written at the dphi of Fig. 4.3a;
# shellpack analyze reads the packings; kcfit fits dZ = C (phi - phi_c)^beta up to
# dphi = 0.15 (the thesis's power-law range) and the shape law delta_eps = C dphi^e.
# Writes $out/compress/N<N>/{compress.csv,structure.csv,rdf.csv,dz_fit.csv,shape_fit.csv} and
# $out/shell_compress.png. N = 32 and 50 at 642 vertices: about 15 minutes on 2 cores.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
sizes=${COMPRESS_N:-32 50}
level=${COMPRESS_LEVEL:-4}
seed=${COMPRESS_SEED:-1}
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bin="$build/bin"
runs="" labels=""
for n in $sizes; do
  dir="$out/compress/N$n"
  mkdir -p "$dir"
  echo "== N = $n: shellpack jam, rndmesh icosa --level $level, shellpack compress" >&2
  "$bin/shellpack" jam -N "$n" --seed "$seed" -q -o "$dir/jam.xyz" --csv "$dir/jam.csv"
  "$bin/rndmesh" icosa --level "$level" --radius 0.5 -q -o "$dir/cell.off"
  rm -f "$dir"/pack_*.off
  "$bin/shellpack" compress "$dir/jam.xyz" --mesh "$dir/cell.off" --seed "$seed" \
    --dphi 0.001,0.01,0.05,0.1,0.15,0.2,0.25,0.3 -o "$dir/pack_{phi}.off" -q >"$dir/compress.csv"
  "$bin/shellpack" analyze "$dir"/pack_*.off -q >"$dir/structure.csv"
  # g(r) in units of the contact distance sigma = D0 + 2 R_v of the vertex spheres (the
  # jammed spheres' diameter), where the thesis's sigma = D0 puts its contact peak.
  rv=$(sed -n 's/^# vertex_radius=//p' "$(ls "$dir"/pack_*.off | head -1)")
  "$bin/shellpack" analyze "$dir"/pack_*.off --d0 "$(awk -v r="$rv" 'BEGIN { printf "%.6f", 1 + 2 * r }')" \
    --rdf "$dir/rdf.csv" -q >/dev/null
  # dZ near jamming: the shells' own jamming point is fitted (phi_c, as a dphi: the shells
  # settle into contact a little above the start, where Z crosses 6 - 4/N).
  "$bin/kcfit" "$dir/compress.csv" --model power --x dphi --y dZ --where 'dZ>0' --where 'dphi<=0.15' \
    -q -o "$dir/dz_fit.csv"
  "$bin/kcfit" "$dir/compress.csv" --model power --x dphi --y delta_eps_mean --where 'dphi>0' --where 'dphi<=0.15' \
    -q -o "$dir/shape_fit.csv"
  runs="$runs $dir"
  labels="${labels:+$labels }N=$n"
done
# g(r) of the first N at dphi = 0.001, 0.01, 0.1 and 0.3 (its 1st, 2nd, 4th and 8th packing).
first=${runs# }; first=${first%% *}
packs=$(ls "$first"/pack_*.off | sort | sed -n '1p;2p;4p;8p' | tr '\n' ' ')
gnuplot -e "runs='${runs# }'; labels='$labels'; packs='${packs% }'; packlabels='0.001 0.01 0.1 0.3'; out='$out/shell_compress.png'" \
  "$src/scripts/plot_compress.gp"
echo "make compress-figures: $out/shell_compress.png" >&2
