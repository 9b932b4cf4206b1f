#!/usr/bin/env bash
# make run, jam2d: a colony of budding cells grown from two cells until jammed in a periodic
# box of 7 sigma (Fig. 3.1c-g), then beyond jamming with strong feedback; the moduli of the packing. Sourced
# by scripts/demo/run.sh, which sets $bin, $out and step(); appends to $out/README.txt what it made.
step "jam2d grow: two cells to the jamming point in a periodic box of 7 sigma (Fig. 3.1c-g) (thesis 3.4.2)"
"$bin/jam2d" grow --box 7 --seed 1 -o "$out/cells_jammed.xyz" -q >"$out/cells_growth.csv"
step "jam2d grow: the same colony to phi_J + 0.05 with feedback P0 = 0.001, then its moduli"
"$bin/jam2d" grow --box 7 --seed 1 --dphi 0.05 --P0 0.001 -o "$out/cells_packed.xyz" -q --csv ''
"$bin/jam2d" moduli "$out/cells_jammed.xyz" "$out/cells_packed.xyz" -o "$out/cells_moduli.csv"

cat >>"$out/README.txt" <<EOT
  cells_growth.csv         one row per accepted growth step to jamming (jam2d grow)
  cells_jammed.xyz, cells_packed.xyz   jammed and compressed budding-cell packings, one row per lobe (OVITO, ASE)
  cells_moduli.csv         P, B, G, Z, Z_iso, f_u of both packings (jam2d moduli)
EOT
