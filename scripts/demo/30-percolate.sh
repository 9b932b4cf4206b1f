#!/usr/bin/env bash
# make run, percolate: pore space, percolating cluster, porosity and hydraulic radius of a
# sphere packing (shellpack's jammed packing once it exists, else the simple cubic array of
# data/percolate), an inflation sweep turned into percolation probability, and the thesis's
# caveat on one closed shell (vertex marking leaks, triangle marking does not). Sourced by
# scripts/demo/run.sh, which sets $bin, $out and step(); appends to $out/README.txt what it made.
spheres="$out/jammed.xyz"
[ -f "$spheres" ] || spheres=data/percolate/simple_cubic_4x4x4.xyz
step "percolate: $(basename "$spheres") inflated by 1.2, delta = 0.04 and 0.05 D0"
"$bin/percolate" "$spheres" --delta 0.04,0.05 --scale 1.2 -o "$out/cluster_{delta}.vtk" --csv "$out/percolate.csv"
# (the simple cubic array up to r = 0.7 < a/sqrt 2; beyond, three spheres share points and the
# pair-corrected porosity is an upper bound: porosity_exact = 0 and a warning on stderr)
step "percolate: inflation sweep (scale 1.0 to 1.75) at delta = 0.05, 0.1; percolation probability"
"$bin/percolate" "$spheres" --delta 0.05,0.1 --scale 1.0,1.1,1.2,1.3,1.4,1.5,1.6,1.65,1.7,1.75 -q \
  --csv "$out/percolate_sweep.csv"
"$bin/percolate" sweep "$out/percolate_sweep.csv" --bins 6 -o "$out/percolation_probability.csv"
grep -v '^#' "$out/percolate_sweep.csv" | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i;
    printf "%6s %6s %10s %6s %10s %9s %10s %10s\n", "scale", "delta", "porosity", "exact", "phi_voxel", "percol.", "R_h[D0]", "clusters"; next }
  { printf "%6s %6s %10.4f %6s %10.4f %9s %10.4f %10s\n", $c["scale"], $c["delta"], $c["porosity"], $c["porosity_exact"],
    $c["porosity_voxels"], $c["percolates"], $c["rh_faces_d0"], $c["clusters"] }' >&2
if [ -f "$out/icosa4.off" ]; then
  step "percolate: one closed shell (icosa4.off, edges ~0.19) at delta = 0.05: triangles vs vertices"
  awk 'NR == 1 { print; print "# box 3 3 3"; print "# periodic 1 1 1"; print "# shells 1 642"; next }
       /^#/ { next }
       !counts { print; counts = 1; nv = $1; next }
       nv > 0 { printf "%.17g %.17g %.17g\n", $1 + 1.5, $2 + 1.5, $3 + 1.5; --nv; next }
       { print }' "$out/icosa4.off" > "$out/one_shell.off"
  "$bin/percolate" "$out/one_shell.off" --delta 0.05 --d0 2 -q --csv "$out/shell_triangles.csv"
  "$bin/percolate" "$out/one_shell.off" --delta 0.05 --d0 2 --marking vertices -q --csv "$out/shell_vertices.csv"
  for m in triangles vertices; do
    printf '  %-9s marking: %s void clusters (2 = inside and outside apart)\n' $m \
      "$(grep -v '^#' "$out/shell_$m.csv" | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "clusters") c = i; next } { print $c }')" >&2
  done
fi

cat >>"$out/README.txt" <<EOT
  cluster_0.04.vtk, cluster_0.05.vtk   percolating cluster of $(basename "$spheres") (ParaView; lbflow's input)
  percolate.csv                  porosity, percolation per axis, R_h, ... one row per delta (VTK in the packing's units)
  percolate_sweep.csv            the same for an inflation sweep (scale 1.0 to 1.75)
  percolation_probability.csv    percolation probability vs porosity per delta (percolate sweep)
EOT
[ -f "$out/icosa4.off" ] && cat >>"$out/README.txt" <<EOT
  one_shell.off, shell_*.csv     one closed shell: triangle marking holds the liquid, vertex marking leaks
EOT
true
