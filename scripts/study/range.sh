#!/usr/bin/env bash
# Expands a campaign range to its values, one per line, in the form the programs print numbers
# (%.12g: 0.6, 0.625): FIRST:LAST:STEP, FIRST:LAST (integers, step 1), a comma-separated list
# or one value. Used by study.mk for seeds, phi, delta and M.
set -euo pipefail
awk -v spec="$1" 'BEGIN {
  n = split(spec, p, ":")
  if (n == 1) { m = split(spec, v, ","); for (i = 1; i <= m; ++i) if (v[i] != "") printf "%.12g\n", v[i] + 0; exit }
  step = (n == 3) ? p[3] + 0 : 1
  if (step <= 0 || p[2] + 0 < p[1] + 0) exit
  count = int((p[2] - p[1]) / step + 1e-9)
  for (k = 0; k <= count; ++k) printf "%.12g\n", p[1] + k * step
}'
