#!/usr/bin/env bash
# The pipeline shellpack jam -> percolate -> kcfit as a user chains it (issue 7's last item, thesis
# Fig. 5.2C's trend): jammed sphere packings inflated step by step lose their percolating
# void, and a finer lattice (smaller delta) keeps it open to a lower porosity.
#   bash pipeline_jam_percolate.sh --list | CASE     (needs CMP_BIN)
set -uo pipefail
if [[ ${1:-} == --list ]]; then printf '%s\n' inflated_jammed_packings through_pipes; exit 0; fi
case=${1:?CASE}
bin=${CMP_BIN:?set CMP_BIN}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }
scales=1.00,1.05,1.10,1.15,1.20,1.25,1.30

if [ "$case" = through_pipes ]; then
  # The whole chain through pipes, as a user types it: eight jammed packings as frames of one
  # extended XYZ on stdout, percolate reading them from stdin (format told from the content),
  # kcfit fitting percolate's rows from stdin with its default columns. No file in between.
  "$bin/shellpack" jam -N 32 --seeds 1:8 -q -o - |
    "$bin/percolate" - --delta 0.05 --scale $scales -q 2>/dev/null |
    "$bin/kcfit" - --model sigmoid -q >fit_pipe.csv || fail "shellpack jam -o - | percolate - | kcfit -"
  # The same packings through files give the same fit, to the last digit.
  "$bin/shellpack" jam -N 32 --seeds 1:8 -q -o 'jam_{seed}.xyz' --csv /dev/null || fail "jam to files"
  "$bin/percolate" jam_*.xyz --delta 0.05 --scale $scales -q --csv perc.csv 2>/dev/null || fail "percolate files"
  [ "$(grep -vc '^#' perc.csv)" = 57 ] || fail "rows: $(grep -vc '^#' perc.csv), expected 8 x 7 + header"
  "$bin/kcfit" perc.csv --model sigmoid -q >fit_files.csv || fail "kcfit perc.csv"
  diff <(grep -v '^#' fit_pipe.csv) <(grep -v '^#' fit_files.csv) >/dev/null ||
    fail "pipe and files differ: $(grep -v '^#' fit_pipe.csv) vs $(grep -v '^#' fit_files.csv)"
  /usr/bin/python3 - fit_pipe.csv <<'PY' || fail "phi_c: $(cat fit_pipe.csv)"
import csv, sys
rows = {r["parameter"]: r for r in csv.DictReader(l for l in open(sys.argv[1]) if not l.startswith("#"))}
phi_c = float(rows["phi_c"]["value"])
assert 0.08 < phi_c < 0.25, phi_c
PY
  exit 0
fi

"$bin/shellpack" jam -N 32 --seeds 1:8 -o 'jam_{seed}.xyz' -q >jam.csv || fail "jam"
"$bin/percolate" jam_*.xyz --delta 0.03,0.07 --scale $scales -q --csv perc.csv 2>/dev/null || fail "percolate --scale $scales"
# columns by name: scale, delta, percolates
awk -F, '/^#/ { next } $1 == "file" { for (i = 1; i <= NF; i++) c[$i] = i; next }
  { k = sprintf("%.2f,%.2f", $c["scale"], $c["delta"]); n[k]++; p[k] += $c["percolates"]
    total[sprintf("%.2f", $c["delta"])] += $c["percolates"] }
  END {
    for (k in n) printf "scale,delta %s: %d of %d percolate\n", k, p[k], n[k] > "/dev/stderr"
    bad = 0
    # as jammed, every packing percolates at both deltas; at scale 1.30 none does
    if (p["1.00,0.03"] != 8 || p["1.00,0.07"] != 8) { print "not all jammed packings percolate"; bad = 1 }
    if (p["1.30,0.03"] != 0 || p["1.30,0.07"] != 0) { print "inflated by 1.3 some still percolate"; bad = 1 }
    # the finer lattice percolates more often over the sweep: a lower threshold porosity
    if (!(total["0.03"] > total["0.07"] + 4)) { print "delta 0.03 does not percolate more than 0.07"; bad = 1 }
    exit bad }' perc.csv || fail "trend of Fig. 5.2C not seen"
# percolate -> kcfit without renaming: the sigmoid of percolates against porosity at one delta
"$bin/percolate" jam_*.xyz --delta 0.05 --scale $scales -q 2>/dev/null |
  "$bin/kcfit" - --model sigmoid --x porosity --y percolates -q > fit.csv || fail "percolate | kcfit"
phi_c=$(grep -v '^#' fit.csv | awk -F, '$1 == "phi_c" { print $2 }')
/usr/bin/python3 -c "import sys; assert 0.05 < float(sys.argv[1]) < 0.3, sys.argv[1]" "$phi_c" || fail "phi_c = $phi_c: $(cat fit.csv)"
