#!/usr/bin/env bash
# make jamming-figure: Figs S5.1 and S5.2 of the thesis regenerated. 100 jammed packings per N
# (N = 16, 32, 50), their mean volume fraction phi_J and contact number Z against N, beside the
# thesis's finite-size law psi* - psi_J = d0 N^(-1/(d nu)) (d0 = 0.12, nu = 0.71, psi* = 0.639)
# and Z = 6 - 4/N. Writes $out/jam_N*.csv, $out/phi_J.csv and $out/phi_J.png.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
count=${COUNT:-100}
mkdir -p "$out"
for n in 16 32 50; do
  echo "== shellpack jam -N $n --seeds 1:$count" >&2
  "$build/bin/shellpack" jam -N "$n" --seeds "1:$count" -q --csv "$out/jam_N$n.csv"
done
{
  echo "# thesis: psi_J = 0.639 - 0.12 N^(-1/(3*0.71)); Z = 6 - 4/N (Figs S5.1, S5.2)"
  echo "N,packings,phi_J_mean,phi_J_sem,phi_J_sd,phi_J_thesis_law,Z_mean,Z_isostatic,tries_per_packing,seconds_per_packing"
  for n in 16 32 50; do
    awk -F, -v n="$n" '/^#/ || /^seed/ { next }
      { k++; p += $3; pp += $3 * $3; z += $4; tries += $13 + 1; t += $16 }
      END { m = p / k; sd = sqrt(pp / k - m * m);
            printf "%d,%d,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.2f,%.3f\n", n, k, m, sd / sqrt(k), sd,
                   0.639 - 0.12 * n ^ (-1 / (3 * 0.71)), z / k, 6 - 4 / n, tries / k, t / k }' "$out/jam_N$n.csv"
  done
} >"$out/phi_J.csv"
cat "$out/phi_J.csv" >&2
gnuplot -e "in='$out/phi_J.csv'; out='$out/phi_J.png'" scripts/plot_phi_j.gp
echo "make jamming-figure: $out/phi_J.png and $out/phi_J.csv" >&2
