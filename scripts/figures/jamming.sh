#!/usr/bin/env bash
# make jamming-figure: Figs S5.1 and S5.2 of the thesis regenerated. 100 jammed packings per N
# (N = 16, 32, 50; the thesis's protocol, rattler-free and isostatic), their mean volume
# fraction phi_J with its standard deviation (the thesis's green dots and error bars) and the
# maximum of its distribution (what the finite-size law psi* - psi_J = d0 N^(-1/(d nu)),
# d0 = 0.12, nu = 0.71, psi* = 0.639, describes), and Z, against N. Larger N (50, 128, 256)
# with rattlers and hyperstatic packings kept (rattler-free packings of hundreds of spheres are
# rare) show where phi_J goes. Writes $out/jam_*.csv, $out/phi_J.csv and $out/phi_J.png.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
count=${COUNT:-100}
mkdir -p "$out"
runs=()
for n in 16 32 50; do
  echo "== shellpack jam -N $n --seeds 1:$count" >&2
  "$build/bin/shellpack" jam -N "$n" --seeds "1:$count" -q --csv "$out/jam_N$n.csv"
  runs+=("$n,rattler_free_isostatic,$out/jam_N$n.csv")
done
for spec in 50:24 128:24 256:12; do
  n=${spec%:*} k=${spec#*:}
  echo "== shellpack jam -N $n --seeds 1:$k --keep-rattlers --allow-hyperstatic" >&2
  "$build/bin/shellpack" jam -N "$n" --seeds "1:$k" -q --keep-rattlers --allow-hyperstatic --csv "$out/jam_all_N$n.csv"
  runs+=("$n,all_packings,$out/jam_all_N$n.csv")
done
/usr/bin/python3 - "$out/phi_J.csv" "${runs[@]}" <<'PY'
# Mean, spread and the maximum of a Gaussian kernel density of phi_J per run.
import csv, sys
import numpy as np
from scipy.stats import gaussian_kde
rows = []
for spec in sys.argv[2:]:
    n, selection, path = spec.split(",", 2)
    n = int(n)
    with open(path) as f:
        data = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    phi = np.array([float(r["phi_J"]) for r in data])
    z = np.array([float(r["Z"]) for r in data])
    tries = np.mean([int(r["rejected_tries"]) + 1 for r in data])
    seconds = np.mean([float(r["seconds"]) for r in data])
    grid = np.linspace(phi.min() - 0.02, phi.max() + 0.02, 4001)
    mode = grid[np.argmax(gaussian_kde(phi)(grid))]
    sd = phi.std(ddof=1)
    law = 0.639 - 0.12 * n ** (-1 / (3 * 0.71))
    rows.append([n, selection, len(phi), phi.mean(), sd / np.sqrt(len(phi)), sd, mode, law, z.mean(),
                 6 - 4 / n, tries, seconds])
with open(sys.argv[1], "w") as f:
    f.write("# thesis: psi_J = 0.639 - 0.12 N^(-1/(3*0.71)) for the maximum of the distribution; Z = 6 - 4/N (Figs S5.1, S5.2)\n")
    f.write("N,selection,packings,phi_J_mean,phi_J_sem,phi_J_sd,phi_J_mode,phi_J_thesis_law,Z_mean,Z_isostatic,tries_per_packing,seconds_per_packing\n")
    for r in rows:
        f.write("{},{},{},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.2f},{:.3f}\n".format(*r))
PY
cat "$out/phi_J.csv" >&2
gnuplot -e "in='$out/phi_J.csv'; out='$out/phi_J.png'" scripts/figures/plot_phi_j.gp
echo "make jamming-figure: $out/phi_J.png and $out/phi_J.csv" >&2
