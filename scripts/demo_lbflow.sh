#!/usr/bin/env bash
# make run, lbflow: the flow through the percolating cluster of the jammed packing (or of the
# simple cubic array when shellpack's packing is absent): permeability and tortuosity, the
# velocity field for ParaView, the convergence history; then the same packing read as spheres
# (exact walls, interpolated bounce-back). Seconds at this size (delta = 0.1 D0, M = 1).
# Sourced by scripts/demo.sh, which sets $bin, $out and step(); appends to $out/README.txt.
spheres="$out/jammed.xyz"
[ -f "$spheres" ] || spheres=data/percolate/simple_cubic_4x4x4.xyz
step "lbflow: $(basename "$spheres") voxelised at delta = 0.1 D0 (percolate), flow at M = 1"
"$bin/percolate" "$spheres" --delta 0.1 --sphere-marking centre -q -o "$out/flow_cluster.vtk" --csv /dev/null
"$bin/lbflow" "$out/flow_cluster.vtk" --refine 1 --vtk "$out/flow.vtk" --history "$out/flow_history.csv" \
  -o "$out/flow.csv"
step "lbflow: the packing itself, the wall of every cut link at the exact sphere surface"
"$bin/lbflow" "$spheres" --delta 0.1 --refine 1 -o "$out/flow_exact.csv"
cat >>"$out/README.txt" <<EOT
  flow.csv, flow_exact.csv       permeability (lattice units, delta^2, D0^2), tortuosity, Re, Ma ... (lbflow; kcfit reads them)
  flow.vtk                       velocity and density on the cluster (ParaView: overlays flow_cluster.vtk and the packing)
  flow_history.csv               kappa and tau_H at every convergence check
EOT
