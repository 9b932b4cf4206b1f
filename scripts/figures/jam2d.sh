#!/usr/bin/env bash
# make jam2d-figures: Chapter 3's figures at small boxes, beside the thesis's values.
#   - sweep at L = 10 sigma (SEEDS10 seeds, default 24): jamming and dphi up to 0.1 for P0 = inf,
#     0.005, 0.001: phi_J, Z_J, f_u, Z_J >= Z_iso (Fig. S3.2), Z - Z_J and G against P with the
#     fitted exponents (Fig. 3.3, thesis: 1/2 without feedback), f_u against P (Fig. 3.2a);
#   - jamming at L = 15 and 20 sigma (SEEDS15, SEEDS20): the mean cell numbers (thesis 172, 307);
#   - one colony at L = 15 sigma grown to dphi = 0.16 per P0: P against phi (Fig. 3.1h, P_max ~ 0.1 k);
#   - FIG33_SEEDS > 0 (default 0; 100 is the thesis's Fig. 3.3, about 15 min on 2 cores): the
#     no-feedback sweep at L = 15 sigma over that many seeds, and its exponents in the table.
# Exponents of Z - Z_J and G against P: least squares of ln <Y> on ln <P> (means over seeds per
# dphi, as Fig. 3.3 plots them) over the dphi with <N^2 P> >= 10 (above the finite-size regime
# N^2 P < 1; O'Hern et al. 2003, Goodrich et al. 2012), the error from resampling seeds.
# Writes $out/jam2d_*.csv, $out/jam2d_summary.md (the table of the README) and the PNGs.
# REUSE=1 redraws from the CSV files of an earlier run.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
s10=${SEEDS10:-24} s15=${SEEDS15:-8} s20=${SEEDS20:-4} s33=${FIG33_SEEDS:-0}
mkdir -p "$out"
jam2d="$build/bin/jam2d"
dphis=0,0.0001,0.0003,0.001,0.003,0.01,0.02,0.04,0.07,0.1
if [ "${REUSE:-0}" != 1 ]; then
echo "== jam2d sweep --box 10 --seeds 1:$s10 --dphi $dphis --P0 inf,0.005,0.001" >&2
"$jam2d" sweep --box 10 --seeds "1:$s10" --dphi "$dphis" --P0 inf,0.005,0.001 -q >"$out/jam2d_sweep10.csv"
for spec in 15:$s15 20:$s20; do
  L=${spec%:*} k=${spec#*:}
  echo "== jam2d sweep --box $L --seeds 1:$k --dphi 0" >&2
  "$jam2d" sweep --box "$L" --seeds "1:$k" --dphi 0 --P0 inf -q >"$out/jam2d_sweep$L.csv"
done
if [ "$s33" -gt 0 ]; then
  echo "== jam2d sweep --box 15 --seeds 1:$s33 --dphi $dphis --P0 inf" >&2
  "$jam2d" sweep --box 15 --seeds "1:$s33" --dphi "$dphis" --P0 inf -q >"$out/jam2d_sweep15_fig3_3.csv"
else
  rm -f "$out/jam2d_sweep15_fig3_3.csv"  # not an earlier run's
fi
for P0 in inf 0.005 0.001; do
  echo "== jam2d grow --box 15 --seed 1 --dphi 0.16 --P0 $P0" >&2
  "$jam2d" grow --box 15 --seed 1 --dphi 0.16 --P0 "$P0" -q >"$out/jam2d_growth15_P0_$P0.csv"
done
fi
/usr/bin/python3 - "$out" <<'PY'
import csv, math, os, sys
import numpy as np
out = sys.argv[1]
def table(path):
    with open(path) as f:
        return [r for r in csv.DictReader(l for l in f if not l.startswith("#"))]
s10 = table(f"{out}/jam2d_sweep10.csv")
f = lambda r, k: float(r[k])
jam = [r for r in s10 if f(r, "dphi") == 0 and r["P0"] == "inf"]
phiJ = np.array([f(r, "phi_J") for r in jam]); ZJ = np.array([f(r, "Z") for r in jam])
fu = np.array([f(r, "f_u") for r in jam]); Ziso = np.array([f(r, "Z_iso") for r in jam])
N = {10: np.array([f(r, "cells") for r in jam])}
for L in (15, 20):
    N[L] = np.array([f(r, "cells") for r in table(f"{out}/jam2d_sweep{L}.csv")])
exact = int(np.sum(np.abs(ZJ - Ziso) < 1e-9)); above = int(np.sum(ZJ >= Ziso - 1e-9))
# Fig. S3.2 data: Z_J + 2/(N - N_r) against f_u, one point per packing.
with open(f"{out}/jam2d_figS3_2.dat", "w") as g:
    for r in jam:
        n = f(r, "cells") - f(r, "rattlers")
        g.write(f"{f(r, 'f_u')} {f(r, 'Z') + 2 / n}\n")
def exponents(rows, np_min=10):
    """Exponents of Z - Z_J and G against P (no feedback) from one sweep's rows (dphi = 0 rows
    give Z_J): least squares of ln <Y> on ln <P>, means over seeds per dphi as Fig. 3.3 plots
    them, over the dphi > 0 whose <N^2 P> >= np_min (N cells; below N^2 P ~ 1 finite size
    dominates: Goodrich et al., PRL 109, 095704, 2012); errors: s.d. over 400 resamples of the
    seeds. Also the same fit per packing over those dphi (packings with G > 0 and dZ > 0)."""
    zj = {r["seed"]: f(r, "Z") for r in rows if f(r, "dphi") == 0}
    rows = [r for r in rows if f(r, "dphi") > 0 and r["seed"] in zj]
    seeds = sorted(zj); dps = sorted({f(r, "dphi") for r in rows})
    A = {k: np.full((len(seeds), len(dps)), np.nan) for k in ("P", "dZ", "G", "N")}
    for r in rows:
        i, j = seeds.index(r["seed"]), dps.index(f(r, "dphi"))
        A["P"][i, j], A["G"][i, j], A["N"][i, j] = f(r, "pressure"), f(r, "G"), f(r, "cells")
        A["dZ"][i, j] = f(r, "Z") - zj[r["seed"]]
    cols = np.nanmean(A["N"] ** 2 * A["P"], axis=0) >= np_min
    def slopes(k):
        P = A["P"][k][:, cols].mean(0); Y = [A[y][k][:, cols].mean(0) for y in ("dZ", "G")]
        return [np.polyfit(np.log(P), np.log(y), 1)[0] if np.all(y > 0) and cols.sum() > 1 else np.nan for y in Y]
    e = {"dZ": 0.0, "G": 0.0}
    e["dZ"], e["G"] = slopes(np.arange(len(seeds)))
    rng = np.random.default_rng(1)
    boot = np.array([slopes(rng.integers(0, len(seeds), len(seeds))) for _ in range(400)])
    e["dZ_err"], e["G_err"] = np.nanstd(boot, axis=0)
    use = np.zeros(A["P"].shape, bool); use[:, cols] = True
    use &= (A["G"] > 0) & (A["dZ"] > 0)
    for y in ("dZ", "G"):
        e[y + "_packing"] = np.polyfit(np.log(A["P"][use]), np.log(A[y][use]), 1)[0]
    e["used"] = int(use.sum()); e["seeds"] = len(seeds); e["points"] = int(cols.sum())
    e["dphi_min"] = min(d for d, c in zip(dps, cols) if c); e["dphi_max"] = max(dps)
    e["P_min"] = np.nanmean(A["P"], axis=0)[cols].min(); e["P_max"] = np.nanmean(A["P"], axis=0)[cols].max()
    # Per dphi: dphi, <P>, <dZ>, <G>, their s.d. over seeds, <N^2 P>, fitted (1) or not (0).
    e["table"] = np.column_stack([dps, np.nanmean(A["P"], 0), np.nanmean(A["dZ"], 0), np.nanmean(A["G"], 0),
                                  np.nanstd(A["dZ"], 0, ddof=1), np.nanstd(A["G"], 0, ddof=1),
                                  np.nanmean(A["N"] ** 2 * A["P"], 0), cols])
    return e
def exponent_rows(e, L):
    where = (f"{e['points']} points, dphi {e['dphi_min']:g}-{e['dphi_max']:g}, <P> {e['P_min']:.1e}-{e['P_max']:.1e} k "
             f"(<N^2 P> >= 10), {e['seeds']} seeds")
    return [(f"exponent of Z - Z_J against P, no feedback, L = {L} sigma (fit of seed means)", "1/2",
             f"{e['dZ']:.3f} ± {e['dZ_err']:.3f}; per packing {e['dZ_packing']:.3f} ({e['used']} packings); {where}"),
            (f"exponent of G against P, no feedback, L = {L} sigma (the same fit)", "1/2",
             f"{e['G']:.3f} ± {e['G_err']:.3f}; per packing {e['G_packing']:.3f}")]
# Per P0 and dphi: means over seeds of P, Z - Z_J (per seed), G, f_u, B.
zj = {r["seed"]: f(r, "Z") for r in jam}
fits = {}
for P0 in ("inf", "0.005", "0.001"):
    rows = [r for r in s10 if r["P0"] == P0 and f(r, "dphi") > 0]
    dps = sorted({f(r, "dphi") for r in rows})
    with open(f"{out}/jam2d_fig3_3_P0_{P0}.dat", "w") as g:
        g.write("# dphi P dZ G f_u B packings\n")
        for d in dps:
            sel = [r for r in rows if f(r, "dphi") == d]
            P = np.mean([f(r, "pressure") for r in sel]); dZ = np.mean([f(r, "Z") - zj[r["seed"]] for r in sel])
            G = np.mean([f(r, "G") for r in sel]); fu_ = np.mean([f(r, "f_u") for r in sel]); B = np.mean([f(r, "B") for r in sel])
            g.write(f"{d} {P} {dZ} {G} {fu_} {B} {len(sel)}\n")
    fits[P0] = exponents([r for r in s10 if r["P0"] == "inf"]) if P0 == "inf" else {}
    P = np.array([f(r, "pressure") for r in rows]); G = np.array([f(r, "G") for r in rows])
    n = np.array([f(r, "cells") for r in rows])
    fits[P0]["negative_G"] = int(np.sum((G <= 0) & (P > 1e-7))); fits[P0]["negative_G_stable"] = int(np.sum((G <= 0) & (P * n * n > 1)))
    fits[P0]["unjammed"] = int(np.sum(P < 1e-7)); fits[P0]["packings"] = len(rows)
# Fig. 3.1h: P at phi = 1 (the largest phi reached) per P0.
pmax = {}
for P0 in ("inf", "0.005", "0.001"):
    g = table(f"{out}/jam2d_growth15_P0_{P0}.csv")
    pmax[P0] = (f(g[-1], "phi"), f(g[-1], "pressure"))
    if P0 == "inf":
        j = next(i for i, r in enumerate(g) if f(r, "energy_per_cell") >= 1e-16)
        below = max(f(r, "pressure") for r in g[:j])
        P_above = next(f(r, "pressure") for r in g if f(r, "phi") > f(g[j], "phi") + 0.01)
    with open(f"{out}/jam2d_fig3_1h_P0_{P0}.dat", "w") as h:
        for r in g[:: max(1, len(g) // 800)] + [g[-1]]:
            h.write(f"{r['phi']} {r['pressure']} {r['Z']}\n")
P_at = lambda P0, d: np.mean([f(r, "pressure") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
G_at = lambda P0, d: np.mean([f(r, "G") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
Z_at = lambda P0, d: np.mean([f(r, "Z") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
sem = lambda a: a.std(ddof=1) / math.sqrt(len(a)) if len(a) > 1 else float("nan")
fig33 = f"{out}/jam2d_sweep15_fig3_3.csv"
e15 = exponents(table(fig33)) if os.path.exists(fig33) else None
if e15:
    np.savetxt(f"{out}/jam2d_fig3_3_L15.dat", e15["table"], header="dphi P dZ G dZ_sd G_sd N2P fitted")
elif os.path.exists(f"{out}/jam2d_fig3_3_L15.dat"):
    os.remove(f"{out}/jam2d_fig3_3_L15.dat")
rows = [
    ("phi_J, L = 10 sigma", "0.84 ± 0.02", f"{phiJ.mean():.4f} ± {phiJ.std(ddof=1):.4f} (s.d.), {len(phiJ)} packings"),
    ("Z_J", "≈ 5.5", f"{ZJ.mean():.3f} ± {sem(ZJ):.3f}"),
    ("f_u at jamming", "≈ 0.25", f"{fu.mean():.3f} ± {sem(fu):.3f}"),
    ("Z_J ≥ Z_iso = 6 - 2 f_u - 2/(N - N_r) (Fig. S3.2)", "every packing; most exactly", f"{above} of {len(jam)}; exactly {exact}"),
    ("mean cells at jamming, L = 10, 15, 20 sigma", "75, 172, 307",
     ", ".join(f"{N[L].mean():.1f} ({len(N[L])})" for L in (10, 15, 20))),
    ("packings beyond jamming with G <= 0 (no feedback): all / at N^2 P > 1", "(not reported)",
     f"{fits['inf']['negative_G']} / {fits['inf']['negative_G_stable']} of {fits['inf']['packings']}; unjammed by a division (P < 1e-7): {fits['inf']['unjammed']}"),
] + exponent_rows(fits["inf"], 10) + (exponent_rows(e15, 15) if e15 else []) + [
    ("P below jamming (largest over the growth, L = 15 sigma)", "0",
     f"{below:.1e} k (the residue of V/(kN) < 1e-16); {P_above:.1e} k at phi_J + 0.01"),
    ("P at the largest phi, L = 15, no feedback", "≈ 0.1 k near phi = 1", f"{pmax['inf'][1]:.4f} k at phi = {pmax['inf'][0]:.4f}"),
    ("Z at dphi = 0.02, P0 = inf / 0.005 / 0.001", "rises with feedback (Fig. 3.1i)",
     " / ".join(f"{Z_at(p, 0.02):.3f}" for p in ("inf", "0.005", "0.001"))),
    ("P at dphi = 0.02, P0 = inf / 0.005 / 0.001", "lower with strong feedback (Fig. 3.1h)",
     " / ".join(f"{P_at(p, 0.02):.5f}" for p in ("inf", "0.005", "0.001"))),
    ("G at dphi = 0.02, P0 = inf / 0.005 / 0.001", "higher with strong feedback at fixed P (Fig. 3.3b)",
     " / ".join(f"{G_at(p, 0.02):.4f}" for p in ("inf", "0.005", "0.001"))),
]
with open(f"{out}/jam2d_summary.md", "w") as g:
    g.write("| quantity | thesis | jam2d |\n|---|---|---|\n")
    for r in rows:
        g.write(f"| {r[0]} | {r[1]} | {r[2]} |\n")
print(open(f"{out}/jam2d_summary.md").read())
PY
gnuplot -e "dir='$out'" scripts/figures/plot_jam2d.gp
echo "make jam2d-figures: $out/jam2d_summary.md, $out/jam2d_fig3_1h.png, jam2d_fig3_2.png, jam2d_fig3_3.png, jam2d_figS3_2.png" >&2
