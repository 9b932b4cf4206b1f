#!/usr/bin/env bash
# make run, shellpack: a jammed packing of 32 soft spheres and its structure; 16 elastic shells
# squeezed from a jammed packing towards confluence (read by lbflow's stage). Sourced by
# scripts/demo/run.sh ($bin, $out, step()).
step "shellpack jam: 32 Hertzian spheres jammed at P ~ 1e-8 E (thesis 5.5.1), rattler-free and isostatic"
"$bin/shellpack" jam -N 32 --seed 7 -o "$out/jammed.xyz" >"$out/jam.csv"
step "shellpack structure: g(r), contacts, rattlers and contact forces of that packing"
"$bin/shellpack" structure "$out/jammed.xyz" --forces "$out/contact_forces.csv" >"$out/rdf.csv"
step "shellpack compress: 16 pressurised elastic shells (162 vertices) from a jammed packing, squeezed to phi = 0.7"
"$bin/shellpack" jam -N 16 --seed 3 -o "$out/jammed16.xyz" -q >/dev/null
"$bin/rndmesh" icosa --level 3 --radius 0.5 -o "$out/cell.off" -q
"$bin/shellpack" compress "$out/jammed16.xyz" --mesh "$out/cell.off" --contact hertz-faces --step 0.02 --ftol 1e-4 \
  --phi 0.6,0.65,0.7 -o "$out/shells_{phi}.off" -q >"$out/compress.csv"
"$bin/shellpack" analyze "$out"/shells_*.off -q >"$out/shells_structure.csv"
grep -v '^#' "$out/shells_structure.csv" | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i;
    printf "%6s %6s %8s %8s\n", "phi", "Z", "Pi/Pi0", "delta_eps"; next }
  { printf "%6s %6s %8.3f %8.4f\n", $c["phi"], $c["Z"], $c["turgor_mean_P0"], $c["delta_eps_mean"] }' >&2
cat >>"$out/README.txt" <<EOT
  compress.csv    16 elastic shells squeezed from jamming: phi, Z, turgor, shapes per box step
  shells_0.6.off, shells_0.65.off, shells_0.7.off   the shell packings (MeshLab, ParaView; percolate reads them)
  shells_structure.csv   shellpack analyze of them: Z, turgor, shapes, contact forces
  jammed.xyz      jammed packing of 32 spheres, extended XYZ (OVITO, ASE)
  jam.csv         phi_J, Z, contacts, pressure, FIRE iterations of that packing
  rdf.csv         its radial distribution function g(r), r in diameters
  contact_forces.csv  distribution of its contact forces, P(f/<f>)
EOT
