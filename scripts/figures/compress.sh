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
# COMPRESS_CONTACT (hertz-vertices) is the contact law of these runs; COMPRESS_N="" skips them.
# Then towards confluence: COMPRESS_HIGH_N (32; 0 skips it) shells of the same cell with hertz-faces
# (vertices against triangles: the vertex-sphere layer cannot go much past phi = 0.85) from
# jamming to phi = COMPRESS_HIGH_PHI (0.95) in steps of 0.05, analysed:
# $out/compress/faces<N>/{compress.csv,structure.csv,dz_fit.csv,shape_fit.csv} and the table
# $out/compress/faces<N>/table.md (about 30 minutes at 32 x 642 on a quiet machine).
# The faces run is drawn as the N runs are: $out/shell_compress_faces.png (g(r) at phi = 0.6,
# 0.7, 0.8 and 0.9).
# Every compression checkpoints; COMPRESS_RESUME=1 keeps finished runs and continues the ones
# an interruption stopped (long runs: COMPRESS_LEVEL=5, the thesis's 2562 vertices per shell).
# Last, why the turgor near confluence depends on the mesh: COMPRESS_LAYER_N (16; 0 skips it)
# shells of 642 vertices with faces to phi = 0.95, as they are and with contacts four times
# stiffer against the membrane (about 8 minutes; $out/compress/layer<N>/table.md).
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
sizes=${COMPRESS_N-32 50}
level=${COMPRESS_LEVEL:-4}
seed=${COMPRESS_SEED:-1}
contact=${COMPRESS_CONTACT:-hertz-vertices}
high_n=${COMPRESS_HIGH_N:-32}
high_phi=${COMPRESS_HIGH_PHI:-0.95}
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
bin="$build/bin"
# compress DIR N OPTIONS...: one jammed packing of N spheres and the cell in DIR, the shells
# compressed from it with OPTIONS, a checkpoint every few minutes in DIR/compress.chk, the rows
# in DIR/compress.csv (written whole at the end). With COMPRESS_RESUME=1, a finished run
# (DIR/compress.csv) is kept and one interrupted before it finished (DIR/compress.chk without
# DIR/compress.csv) goes on from its checkpoint to the same files; otherwise everything of an
# earlier run in DIR is replaced.
compress() {
  local dir=$1 n=$2
  shift 2
  mkdir -p "$dir"
  if [ "${COMPRESS_RESUME:-0}" = 1 ] && [ -s "$dir/compress.csv" ]; then
    echo "   $dir/compress.csv is complete: kept" >&2
    return
  elif [ "${COMPRESS_RESUME:-0}" = 1 ] && [ -s "$dir/compress.chk" ]; then
    echo "   resuming from $dir/compress.chk" >&2
    "$bin/shellpack" compress --resume "$dir/compress.chk" -q >"$dir/compress.csv.part"
  else
    rm -f "$dir"/pack_*.off "$dir/compress.csv" "$dir/compress.chk"
    "$bin/shellpack" jam -N "$n" --seed "$seed" -q -o "$dir/jam.xyz" --csv "$dir/jam.csv"
    "$bin/rndmesh" icosa --level "$level" --radius 0.5 -q -o "$dir/cell.off"
    "$bin/shellpack" compress "$dir/jam.xyz" --mesh "$dir/cell.off" --seed "$seed" -o "$dir/pack_{phi}.off" \
      --checkpoint "$dir/compress.chk" "$@" -q >"$dir/compress.csv.part"
  fi
  mv "$dir/compress.csv.part" "$dir/compress.csv"
  rm -f "$dir/compress.chk"
}
runs="" labels=""
for n in $sizes; do
  dir="$out/compress/N$n"
  echo "== N = $n: shellpack jam, rndmesh icosa --level $level, shellpack compress" >&2
  compress "$dir" "$n" --contact "$contact" --dphi 0.001,0.01,0.05,0.1,0.15,0.2,0.25,0.3
  "$bin/shellpack" analyze "$dir"/pack_*.off -q >"$dir/structure.csv"
  # g(r) in units of the contact envelope sigma = D0 + reach (2 R_v of the vertex spheres, or
  # delta of the faces: the jammed spheres' diameter), where the thesis's sigma = D0 puts its
  # contact peak.
  first_pack=$(ls "$dir"/pack_*.off | head -1)
  if [ "$contact" = hertz-faces ]; then
    reach=$(sed -n 's/^# contact_distance=//p' "$first_pack")
  else
    reach=$(awk -v r="$(sed -n 's/^# vertex_radius=//p' "$first_pack")" 'BEGIN { print 2 * r }')
  fi
  "$bin/shellpack" analyze "$dir"/pack_*.off --d0 "$(awk -v r="$reach" 'BEGIN { printf "%.6f", 1 + r }')" \
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
if [ -n "${runs# }" ]; then
  first=${runs# }; first=${first%% *}
  packs=$(ls "$first"/pack_*.off | sort | sed -n '1p;2p;4p;8p' | tr '\n' ' ')
  gnuplot -e "runs='${runs# }'; labels='$labels'; packs='${packs% }'; packlabels='0.001 0.01 0.1 0.3'; out='$out/shell_compress.png'" \
    "$src/scripts/figures/plot_compress.gp"
  echo "make compress-figures: $out/shell_compress.png" >&2
fi

# Towards confluence with hertz-faces: phi, Z, turgor, shapes and Voronoi facets per target.
if [ "$high_n" -gt 0 ]; then
  dir="$out/compress/faces$high_n"
  echo "== towards confluence: $high_n shells, hertz-faces, to phi = $high_phi" >&2
  compress "$dir" "$high_n" --contact hertz-faces --phi "0.6:$high_phi:0.05" --timings
  "$bin/shellpack" analyze "$dir"/pack_*.off -q >"$dir/structure.csv"
  reach=$(sed -n 's/^# contact_distance=//p' "$(ls "$dir"/pack_*.off | head -1)")
  "$bin/shellpack" analyze "$dir"/pack_*.off --d0 "$(awk -v r="$reach" 'BEGIN { printf "%.6f", 1 + r }')" \
    --rdf "$dir/rdf.csv" -q >/dev/null
  # The same laws as above from this run's steps: dZ near jamming and the shapes.
  "$bin/kcfit" "$dir/compress.csv" --model power --x dphi --y dZ --where 'dZ>0' --where 'dphi<=0.15' \
    -q -o "$dir/dz_fit.csv"
  "$bin/kcfit" "$dir/compress.csv" --model power --x dphi --y delta_eps_mean --where 'dphi>0' --where 'dphi<=0.15' \
    -q -o "$dir/shape_fit.csv"
  awk -F, '/^#/ { next }
    !h { for (i = 1; i <= NF; i++) c[$i] = i; h = 1
         print "| phi | Z | <Pi>/Pi0 | cv(Pi) | delta_eps | Voronoi facets | force cv |"; print "|---|---|---|---|---|---|---|"; next }
    { printf "| %s | %.2f | %.2f | %.3f | %.3f | %.2f | %.2f |\n", $c["phi"], $c["Z"], $c["turgor_mean_P0"],
        $c["turgor_cv"], $c["delta_eps_mean"], $c["voronoi_faces_mean"], $c["force_normal_cv"] }' \
    "$dir/structure.csv" >"$dir/table.md"
  cat "$dir/table.md"
  echo "make compress-figures: $dir/table.md" >&2
  packs="" packlabels=""
  for phi in 0.6 0.7 0.8 0.9; do
    [ -s "$dir/pack_$phi.off" ] || continue
    packs="$packs $dir/pack_$phi.off" packlabels="$packlabels $phi"
  done
  gnuplot -e "runs='$dir'; labels='N=$high_n'; packs='${packs# }'; packlabels='${packlabels# }'; packvar='{/Symbol f}'; out='$out/shell_compress_faces.png'" \
    "$src/scripts/figures/plot_compress.gp"
  echo "make compress-figures: $out/shell_compress_faces.png" >&2
fi

# Why the turgor near confluence depends on the mesh: hertz-faces pushes each vertex with a
# Hertz force of its own, so the layer's stiffness per area grows with the vertex density (4x
# from 642 to 2,562 vertices per shell). COMPRESS_LAYER_N (16; 0 skips) shells of 642 vertices
# from jamming to phi = 0.95 twice: as above, and with the membrane four times softer (t/4,
# Pi_0 in E/4, the layer delta kept), i.e. contacts four times stiffer against the membrane,
# as a 2,562-vertex mesh has them. $out/compress/layer<N>/table.md: <Pi>/Pi0 of both.
layer_n=${COMPRESS_LAYER_N:-16}
if [ "$layer_n" -gt 0 ]; then
  dir="$out/compress/layer$layer_n"
  echo "== contact layer stiffness: $layer_n shells of 642 vertices, hertz-faces, as they are and with 4x stiffer contacts" >&2
  level=4 compress "$dir/as_is" "$layer_n" --contact hertz-faces --phi "0.6:0.95:0.05"
  level=4 compress "$dir/stiff" "$layer_n" --contact hertz-faces --phi "0.6:0.95:0.05" \
    -t 0.005 --contact-distance 0.02 --P0 0.000625
  for run in as_is stiff; do "$bin/shellpack" analyze "$dir/$run"/pack_*.off -q >"$dir/$run/structure.csv"; done
  awk -F, 'FNR == 1 { f++ } /^#/ { next }
    !h[f] { for (i = 1; i <= NF; i++) c[$i] = i; h[f] = 1; next }
    f == 1 { pi[$c["phi"]] = $c["turgor_mean_P0"]; z[$c["phi"]] = $c["Z"]; next }
    { p = $c["phi"]; printf "| %s | %.2f | %.2f | %.2f | %.2f | %.2f |\n", p, z[p], $c["Z"], pi[p], $c["turgor_mean_P0"],
        $c["turgor_mean_P0"] / pi[p] }' "$dir/as_is/structure.csv" "$dir/stiff/structure.csv" >"$dir/rows.md"
  { echo "| phi | Z | Z, contacts x4 | <Pi>/Pi0 | <Pi>/Pi0, contacts x4 | ratio |"; echo "|---|---|---|---|---|---|"
    cat "$dir/rows.md"; } >"$dir/table.md"
  rm "$dir/rows.md"
  cat "$dir/table.md"
  echo "make compress-figures: $dir/table.md" >&2
fi
