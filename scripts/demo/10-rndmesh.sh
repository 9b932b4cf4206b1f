#!/usr/bin/env bash
# make run, rndmesh: two sphere meshes, their quality and the annealing trace. Sourced by
# scripts/demo/run.sh, which sets $bin, $out and step(); appends to $out/README.txt what it made.
step "rndmesh: icosahedral sphere mesh, level 4 (642 vertices)"
"$bin/rndmesh" icosa --level 4 -o "$out/icosa4.off"
step "rndmesh: 642 annealed random points + spherical Delaunay (thesis schedule)"
"$bin/rndmesh" random -n 642 --seed 7 --trace "$out/anneal.csv" -o "$out/cell.off"
step "rndmesh: quality metrics of both meshes"
"$bin/rndmesh" stats "$out/icosa4.off" "$out/cell.off" -o "$out/mesh_stats.csv"
grep -v '^#' "$out/mesh_stats.csv" | awk -F, 'NR == 1 { printf "%-22s %8s %6s %7s %7s %7s %12s\n", $1, $2, $3, $8, $9, $10, $19; next }
  { printf "%-22s %8d %6d %7.3f %7.3f %7.3f %12.2e\n", $1, $2, $3, $8, $9, $10, $19 }' >&2
step "gnuplot: the annealing trace"
gnuplot -e "in='$out/anneal.csv'; out='$out/anneal.png'" scripts/figures/plot_anneal.gp

cat >>"$out/README.txt" <<EOT
  icosa4.off      icosahedral mesh (MeshLab, ParaView)
  cell.off        Monte Carlo mesh, N = 642 (MeshLab, ParaView)
  anneal.csv      temperature, acceptance and energy per anneal
  anneal.png      the same as a figure (gnuplot, scripts/figures/plot_anneal.gp)
  mesh_stats.csv  quality metrics of both meshes, one row each
EOT
