#!/usr/bin/env bash
# make tables: Tables A.5 and A.6 of the thesis regenerated with rndmesh's defaults (one seed
# per row, as the thesis did), side by side with the printed values. Writes CSV and Markdown
# into the output folder and prints the Markdown.
set -euo pipefail
build=${1:-build}
out=${2:-out/tables}
seed=${SEED:-1}
bin="$build/bin"
mkdir -p "$out"
row() {  # label N T_end printed_qA printed_qtheta printed_q
  local f="$out/mesh_$1.off"
  "$bin/rndmesh" random -n "$2" --radius 2.5 --tmin "$3" --seed "$seed" -o "$f" -q
  local q
  q=$("$bin/rndmesh" stats "$f" | grep -v '^#' | tail -1 | cut -d, -f8-10)
  echo "$1,$2,$3,$q,$4,$5,$6"
}
{
  echo "r_v,N,T_end,q_A,q_theta,q,thesis_q_A,thesis_q_theta,thesis_q"
  row 0.45 123 0.1 0.661 0.729 0.829
  row 0.4 156 0.1 0.635 0.668 0.731
  row 0.35 204 0.1 0.624 0.651 0.719
  row 0.3 277 0.1 0.615 0.633 0.690
  row 0.25 400 0.1 0.614 0.624 0.671
  row 0.2 625 0.1 0.580 0.605 0.644
  row 0.15 1111 0.1 0.588 0.617 0.671
  row 0.1 2500 0.1 0.596 0.623 0.681
} > "$out/table_a5.csv"
{
  echo "label,N,T_end,q_A,q_theta,q,thesis_q_A,thesis_q_theta,thesis_q"
  for t in "0.1 0.595 0.619 0.657" "1 0.566 0.607 0.663" "10 0.381 0.514 0.583" "50 0.218 0.387 0.410" \
           "100 0.182 0.349 0.333" "250 0.135 0.304 0.329" "500 0.110 0.242 0.227" "750 0.085 0.251 0.224"; do
    set -- $t
    row "T$1" 2500 "$1" "$2" "$3" "$4"
  done
} > "$out/table_a6.csv"
/usr/bin/python3 scripts/tables/thesis_md.py "$out" "$seed"
