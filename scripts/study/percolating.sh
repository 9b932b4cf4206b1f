#!/usr/bin/env bash
# percolating.sh DIR PHI...: the PHIs whose percolate row DIR/<phi>.csv says the cluster spans
# the flow axis (column `percolates` = 1), one per line: the clusters lbflow can run on (it
# refuses one that does not percolate: nothing flows through it). Rows not yet made are left out.
set -euo pipefail
dir=$1
shift
for phi in "$@"; do
  f="$dir/$phi.csv"
  [ -f "$f" ] || continue
  awk -F, '/^#/ { next } !h { for (i = 1; i <= NF; ++i) c[$i] = i; h = 1; next }
    $c["percolates"] == 1 { found = 1 } END { exit !found }' "$f" && echo "$phi"
done
exit 0
