#!/usr/bin/env bash
# make jam2d-figures: Chapter 3's figures at small boxes, beside the thesis's values.
#   - sweep at L = 10 sigma (SEEDS10 seeds, default 24): jamming and dphi up to 0.1 for P0 = inf,
#     0.005, 0.001: phi_J, Z_J, f_u, Z_J >= Z_iso (Fig. S3.2), Z - Z_J and G against P with the
#     fitted exponents (Fig. 3.3, thesis: 1/2 without feedback), f_u against P (Fig. 3.2a);
#   - jamming at L = 15 and 20 sigma (SEEDS15, SEEDS20): the mean cell numbers (thesis 172, 307);
#   - one colony at L = 15 sigma grown to dphi = 0.16 per P0: P against phi (Fig. 3.1h, P_max ~ 0.1 k).
# Writes $out/jam2d_*.csv, $out/jam2d_summary.md (the table of the README) and the PNGs.
# REUSE=1 redraws from the CSV files of an earlier run.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
s10=${SEEDS10:-24} s15=${SEEDS15:-8} s20=${SEEDS20:-4}
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
for P0 in inf 0.005 0.001; do
  echo "== jam2d grow --box 15 --seed 1 --dphi 0.16 --P0 $P0" >&2
  "$jam2d" grow --box 15 --seed 1 --dphi 0.16 --P0 "$P0" -q >"$out/jam2d_growth15_P0_$P0.csv"
done
fi
/usr/bin/python3 - "$out" <<'PY'
import csv, math, sys
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
# Per P0 and dphi: means over seeds of P, Z - Z_J (per seed), G, f_u, B.
zj = {r["seed"]: f(r, "Z") for r in jam}
fits = {}
lines = []
for P0 in ("inf", "0.005", "0.001"):
    rows = [r for r in s10 if r["P0"] == P0 and f(r, "dphi") > 0]
    dps = sorted({f(r, "dphi") for r in rows})
    with open(f"{out}/jam2d_fig3_3_P0_{P0}.dat", "w") as g:
        g.write("# dphi P dZ G f_u B packings\n")
        pts = []
        for d in dps:
            sel = [r for r in rows if f(r, "dphi") == d]
            P = np.mean([f(r, "pressure") for r in sel]); dZ = np.mean([f(r, "Z") - zj[r["seed"]] for r in sel])
            G = np.mean([f(r, "G") for r in sel]); fu_ = np.mean([f(r, "f_u") for r in sel]); B = np.mean([f(r, "B") for r in sel])
            g.write(f"{d} {P} {dZ} {G} {fu_} {B} {len(sel)}\n")
            pts.append((P, dZ, G))
    pts = np.array(pts)
    ok = (pts[:, 0] > 0) & (pts[:, 1] > 0) & (pts[:, 2] > 0)
    fits[P0] = {k: np.polyfit(np.log(pts[ok, 0]), np.log(pts[ok, i]), 1)[0] for k, i in (("dZ", 1), ("G", 2))}
    # Per packing, over the packings that are jammed and stable to shear at N^2 P > 1 (below,
    # a finite fraction of packings has G < 0: Dagois-Bohy et al., PRL 109, 095703, 2012).
    P = np.array([f(r, "pressure") for r in rows]); G = np.array([f(r, "G") for r in rows])
    n = np.array([f(r, "cells") for r in rows]); dZ = np.array([f(r, "Z") - zj[r["seed"]] for r in rows])
    use = (P * n * n > 1) & (G > 0) & (dZ > 0)
    fits[P0]["dZ_packing"] = np.polyfit(np.log(P[use]), np.log(dZ[use]), 1)[0]
    fits[P0]["G_packing"] = np.polyfit(np.log(P[use]), np.log(G[use]), 1)[0]
    fits[P0]["negative_G"] = int(np.sum((G <= 0) & (P > 1e-7))); fits[P0]["negative_G_stable"] = int(np.sum((G <= 0) & (P * n * n > 1)))
    fits[P0]["unjammed"] = int(np.sum(P < 1e-7)); fits[P0]["packings"] = len(rows); fits[P0]["used"] = int(use.sum())
# Fig. 3.1h: P at phi = 1 (the largest phi reached) per P0.
pmax = {}
for P0 in ("inf", "0.005", "0.001"):
    g = table(f"{out}/jam2d_growth15_P0_{P0}.csv")
    pmax[P0] = (f(g[-1], "phi"), f(g[-1], "pressure"))
    if P0 == "inf":
        j = next(i for i, r in enumerate(g) if f(r, "energy_per_cell") >= 1e-16)
        below = max(f(r, "pressure") for r in g[:j])
        above = next(f(r, "pressure") for r in g if f(r, "phi") > f(g[j], "phi") + 0.01)
    with open(f"{out}/jam2d_fig3_1h_P0_{P0}.dat", "w") as h:
        for r in g[:: max(1, len(g) // 800)] + [g[-1]]:
            h.write(f"{r['phi']} {r['pressure']} {r['Z']}\n")
P_at = lambda P0, d: np.mean([f(r, "pressure") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
G_at = lambda P0, d: np.mean([f(r, "G") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
Z_at = lambda P0, d: np.mean([f(r, "Z") for r in s10 if r["P0"] == P0 and f(r, "dphi") == d])
sem = lambda a: a.std(ddof=1) / math.sqrt(len(a)) if len(a) > 1 else float("nan")
rows = [
    ("phi_J, L = 10 sigma", "0.84 ± 0.02", f"{phiJ.mean():.4f} ± {phiJ.std(ddof=1):.4f} (s.d.), {len(phiJ)} packings"),
    ("Z_J", "≈ 5.5", f"{ZJ.mean():.3f} ± {sem(ZJ):.3f}"),
    ("f_u at jamming", "≈ 0.25", f"{fu.mean():.3f} ± {sem(fu):.3f}"),
    ("Z_J ≥ Z_iso = 6 - 2 f_u - 2/(N - N_r) (Fig. S3.2)", "every packing; most exactly", f"{above} of {len(jam)}; exactly {exact}"),
    ("mean cells at jamming, L = 10, 15, 20 sigma", "75, 172, 307",
     ", ".join(f"{N[L].mean():.1f} ({len(N[L])})" for L in (10, 15, 20))),
    ("exponent of Z - Z_J against P, no feedback (fit per packing, N^2 P > 1, G > 0)", "1/2",
     f"{fits['inf']['dZ_packing']:.3f} ({fits['inf']['used']} of {fits['inf']['packings']} packings; seed means: {fits['inf']['dZ']:.3f})"),
    ("exponent of G against P, no feedback (the same packings)", "1/2",
     f"{fits['inf']['G_packing']:.3f} (seed means: {fits['inf']['G']:.3f})"),
    ("packings beyond jamming with G <= 0 (no feedback): all / at N^2 P > 1", "(not reported)",
     f"{fits['inf']['negative_G']} / {fits['inf']['negative_G_stable']} of {fits['inf']['packings']}; unjammed by a division (P < 1e-7): {fits['inf']['unjammed']}"),
    ("P below jamming (largest over the growth, L = 15 sigma)", "0",
     f"{below:.1e} k (the residue of V/(kN) < 1e-16); {above:.1e} k at phi_J + 0.01"),
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
gnuplot -e "dir='$out'" scripts/plot_jam2d.gp
echo "make jam2d-figures: $out/jam2d_summary.md, $out/jam2d_fig3_1h.png, jam2d_fig3_2.png, jam2d_fig3_3.png, jam2d_figS3_2.png" >&2
