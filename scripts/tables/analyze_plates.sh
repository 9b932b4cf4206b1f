#!/usr/bin/env bash
# The rigid-box quantity of Fig. 4.5b on one shell: a 2562-vertex membrane (SVK, t = 0.02,
# P0/E = 0.0025, constant volume) squeezed between two plates by `shellpack shell`, its relaxed
# mesh turned into a packing OFF with walls at z = 0 and the gap, read by `shellpack analyze`:
# the wall pressure P over the coverage Theta (both per area of the arbitrary 10 x 10 walls:
# their ratio does not depend on it) against the turgor Pi. Prints a Markdown table
# (README, shellpack analyze). About 30 s. Usage: scripts/tables/analyze_plates.sh [BIN_DIR]
set -euo pipefail
bin=${1:-build/bin}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin/rndmesh" icosa --level 5 -r 1 -o "$work/cell.off" -q
echo "| squeeze | gap / D0 | Pi / P0 | (P / Theta) / Pi |"
echo "|---|---|---|---|"
for sq in 0.05 0.1 0.2 0.3 0.4; do
  "$bin/shellpack" shell --mesh "$work/cell.off" -E 1 --nu 0.5 -t 0.02 --pressure 0.0025 --pressure-model volume \
    --walls 2.1 --squeeze "$sq" --squeeze-steps 4 -q -o "$work/shell.off" >"$work/shell.csv"
  python3 "$(dirname "$0")/../data/plates_to_packing.py" "$work/shell.off" "$work/shell.csv" "$work/pack.off" \
    E=1 nu=0.5 vertex_radius=0.02 P0=0.0025
  "$bin/shellpack" analyze "$work/pack.off" -q 2>/dev/null | python3 -c "
import sys, csv
r = list(csv.DictReader(l for l in sys.stdin if not l.startswith('#')))[0]
pi, p, c = float(r['turgor_mean_P']), float(r['wall_pressure_P']), float(r['coverage'])
ratio = '%.3f' % (p / c / pi) if c > 0 else '(no face touches)'
print('| $sq | %.2f | %.3f | %s |' % (2.1 * (1 - $sq) / 2, pi / 0.0025, ratio))"
done
