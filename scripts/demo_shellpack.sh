#!/usr/bin/env bash
# make run, shellpack: a jammed packing of 32 soft spheres and its structure. Sourced by
# scripts/demo.sh ($bin, $out, step()).
step "shellpack jam: 32 Hertzian spheres jammed at P ~ 1e-8 E (thesis 5.5.1), rattler-free and isostatic"
"$bin/shellpack" jam -N 32 --seed 7 -o "$out/jammed.xyz" >"$out/jam.csv"
step "shellpack structure: g(r), contacts, rattlers and contact forces of that packing"
"$bin/shellpack" structure "$out/jammed.xyz" --forces "$out/contact_forces.csv" >"$out/rdf.csv"
cat >>"$out/README.txt" <<EOT
  jammed.xyz      jammed packing of 32 spheres, extended XYZ (OVITO, ASE)
  jam.csv         phi_J, Z, contacts, pressure, FIRE iterations of that packing
  rdf.csv         its radial distribution function g(r), r in diameters
  contact_forces.csv  distribution of its contact forces, P(f/<f>)
EOT
