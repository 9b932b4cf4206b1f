#!/usr/bin/env bash
# The cluster images that percolate, one path per line, from percolate's CSV ($1) of a run that
# wrote them as $2/c_{name}_{scale}.vtk with --scale $3 (the scales comma-separated, in the order
# given): lbflow refuses an image that does not percolate (nothing can flow through it). Rows run
# packings outermost, then scales in that order. Used by make flow-figure and make run.
set -euo pipefail
awk -F, -v dir="$2" -v scales="$3" 'BEGIN { ns = split(scales, sc, ",") }
  /^#/ { next } !h { for (i = 1; i <= NF; ++i) c[$i] = i; h = 1; next }
  { k = (NR_data++) % ns + 1 }
  $c["percolates"] == 1 { f = $c["file"]; sub(/.*\//, "", f); sub(/\.xyz$/, "", f); print dir "/c_" f "_" sc[k] ".vtk" }' "$1"
