#!/usr/bin/env bash
# make run, lbflow: the flow through the percolating cluster of the jammed packing (or of the
# simple cubic array when shellpack's packing is absent): permeability and tortuosity, the
# velocity field for ParaView, the convergence history; then the same packing read as spheres
# (exact walls, interpolated bounce-back). Seconds at this size (delta = 0.1 D0, M = 1).
# Sourced by scripts/demo/run.sh, which sets $bin, $out and step(); appends to $out/README.txt.
spheres="$out/jammed.xyz"
[ -f "$spheres" ] || spheres=data/percolate/simple_cubic_4x4x4.xyz
step "lbflow: $(basename "$spheres") voxelised at delta = 0.1 D0 (percolate), flow at M = 1"
"$bin/percolate" "$spheres" --delta 0.1 --sphere-marking centre -q -o "$out/flow_cluster.vtk" --csv /dev/null
"$bin/lbflow" "$out/flow_cluster.vtk" --refine 1 --vtk "$out/flow.vtk" --history "$out/flow_history.csv" \
  -o "$out/flow.csv"
step "lbflow: the packing itself, the wall of every cut link at the exact sphere surface"
"$bin/lbflow" "$spheres" --delta 0.1 --refine 1 -o "$out/flow_exact.csv"
if ls "$out"/shells_*.off >/dev/null 2>&1; then
  step "the chain's question: flow through the shells as they are squeezed (percolate, delta = 0.05 D0; lbflow)"
  "$bin/percolate" "$out"/shells_*.off --delta 0.05 -q -o "$out/shell_cluster_{name}.vtk" --csv "$out/shell_pores.csv"
  printf '%6s %9s %12s %10s\n' phi porosity "kappa[D0^2]" tortuosity >&2
  for f in "$out"/shells_*.off; do
    name=$(basename "$f" .off)
    phi=${name#shells_}
    "$bin/lbflow" "$out/shell_cluster_$name.vtk" --refine 1 -q -o "$out/flow_$name.csv"
    grep -v '^#' "$out/flow_$name.csv" | awk -F, -v phi="$phi" 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { printf "%6s %9.4f %12.4g %10.4f\n", phi, $c["porosity"], $c["permeability_d02"], $c["tortuosity"] }' >&2
  done
  cat >>"$out/README.txt" <<EOT
  shell_pores.csv, shell_cluster_*.vtk   pore space of the squeezed shells (percolate)
  flow_shells_*.csv              permeability and tortuosity through them (lbflow; kcfit reads them)
EOT
fi
cat >>"$out/README.txt" <<EOT
  flow.csv, flow_exact.csv       permeability (lattice units, delta^2, D0^2), tortuosity, Re, Ma ... (lbflow; kcfit reads them)
  flow.vtk                       velocity and density on the cluster (ParaView: overlays flow_cluster.vtk and the packing)
  flow_history.csv               kappa and tau_H at every convergence check
EOT
