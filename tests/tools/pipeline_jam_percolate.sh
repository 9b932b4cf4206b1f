#!/usr/bin/env bash
# The pipeline shellpack jam -> percolate -> kcfit as a user chains it (issue 7's last item, thesis
# Fig. 5.2C's trend): jammed sphere packings inflated step by step lose their percolating
# void, and a finer lattice (smaller delta) keeps it open to a lower porosity.
#   bash pipeline_jam_percolate.sh --list | CASE     (needs CMP_BIN)
set -uo pipefail
if [[ ${1:-} == --list ]]; then echo inflated_jammed_packings; exit 0; fi
bin=${CMP_BIN:?set CMP_BIN}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

"$bin/shellpack" jam -N 32 --seeds 1:8 -o 'jam_{seed}.xyz' -q >jam.csv || fail "jam"
scales=1.00,1.05,1.10,1.15,1.20,1.25,1.30
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
