#!/usr/bin/env bash
# The chain shellpack jam -> percolate -> lbflow -> kcfit at a tiny size, as a user chains it:
# jammed packings inflated step by step (percolate --scale, one cluster image per run), the
# flow through each cluster, and kcfit's permeability and tortuosity laws fitted to lbflow's
# table with kcfit's default columns (no --x/--y). The trends of thesis Figs. 5.4-5.5: kappa
# falls and tau_H rises as the porosity falls.
#   bash pipeline_lbflow.sh --list | CASE     (needs CMP_BIN)
set -uo pipefail
if [[ ${1:-} == --list ]]; then printf '%s\n' jam_percolate_lbflow_kcfit; exit 0; fi
case=${1:?CASE}
[ "$case" = jam_percolate_lbflow_kcfit ] || { echo "unknown case '$case'" >&2; exit 2; }
bin=${CMP_BIN:?set CMP_BIN}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }
export OMP_NUM_THREADS=1  # tiny lattices: one thread each is fastest on a loaded machine

"$bin/shellpack" jam -N 16 --seeds 1:2 -q -o 'jam_{seed}.xyz' --csv /dev/null || fail "jam"
"$bin/percolate" jam_*.xyz --delta 0.1 --sphere-marking centre --scale 0.9,1.0,1.1 -o 'c_{name}_{scale}.vtk' \
  -q --csv perc.csv 2>/dev/null || fail "percolate"
[ "$(grep -v '^#' perc.csv | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "percolates") c = i; next } { s += $c } END { print s }')" = 6 ] ||
  fail "every image should percolate: $(cat perc.csv)"
"$bin/lbflow" c_*.vtk --refine 1 --tol 1e-5 -q > flows.csv || fail "lbflow"
/usr/bin/python3 - <<'PY' || fail "trends: $(cat flows.csv)"
import csv
rows = list(csv.DictReader(l for l in open("flows.csv") if not l.startswith("#")))
assert len(rows) == 6
for seed in ("1", "2"):
    r = sorted((row for row in rows if row["file"].startswith(f"c_jam_{seed}_")), key=lambda r: float(r["porosity"]))
    k = [float(x["permeability_d02"]) for x in r]
    t = [float(x["tortuosity"]) for x in r]
    assert k == sorted(k), k                 # kappa rises with porosity
    assert t == sorted(t, reverse=True), t   # tau_H falls with porosity
    assert all(x["converged"] == "1" and x["porosity_source"] == "file" for x in r)
PY
"$bin/kcfit" flows.csv --model tortuosity -q > tau_fit.csv || fail "kcfit tortuosity"
grep -q "^# y=tortuosity" tau_fit.csv || fail "kcfit's default y: $(head -20 tau_fit.csv)"
"$bin/kcfit" flows.csv --model kc-percolation --loss log -q > kappa_fit.csv || fail "kcfit kc-percolation"
grep -q "^# y=permeability_delta2" kappa_fit.csv || fail "kcfit's default y: $(head -20 kappa_fit.csv)"
grep -q "^# x=porosity" kappa_fit.csv || fail "kcfit's default x"
