#!/usr/bin/env bash
# make chamber-figures: Chapter 2's chamber (jam2d chamber, then jam2d avalanches), beside the
# thesis's numbers, at sizes that run in minutes on 2 cores:
#   - no feedback (mu = 8e4, the thesis's Fig. 2.2b): the pressure series over 500 generation
#     times, <P> (thesis 0.19 k), the drops' survival function and its exponential tail (Fig. 2.2e);
#   - feedback (P0 = 0.07 k, mu = 2e3, Fig. 2.2c), and P0 down to 0.005 k: <P> and c_P (Fig. S2.11);
#   - the ratio of mean drop rate to mean rise rate against mu, with and without feedback (Fig. S2.10);
#   - outlet widths 1.2-3 sigma without and with attraction (Delta = 0.05 sigma): the steady
#     pressure and the avalanche size (Figs. 2.4c and S2.13);
#   - the no-feedback run once more with the thesis's Gear integrator and with Euler (the others
#     use the Runge-Kutta-Chebyshev step, ten times cheaper per simulated time than Euler and 60
#     times cheaper than Gear; the tests show all three converge to one trajectory, and these two
#     rows show the statistics agree).
# TIME (default 347/gamma0 = 500 generation times) is the length of the main runs, SWEEP_TIME
# (60) of the sweeps, CHECK_TIME (20) of the Gear and Euler runs.
# Writes $out/chamber_*.csv, $out/chamber_summary.md (the table of docs/jam2d.md) and the PNGs.
# REUSE=1 redraws from the CSV files of an earlier run.
set -euo pipefail
build=${1:-build}
out=${2:-out/figures}
T=${TIME:-347} TS=${SWEEP_TIME:-60} TC=${CHECK_TIME:-20}
mkdir -p "$out"
jam2d="$build/bin/jam2d"
# name|options: one run each, two at a time.
runs=(
  "nofb|--mobility 8e4 --time $T"
  "fb|--mobility 2e3 --P0 0.07 --time $T"
  "gear3|--mobility 8e4 --time $TC --integrator gear3"
  "euler|--mobility 8e4 --time $TC --integrator euler"
  "nofb_mu2e4|--mobility 2e4 --time $TS"
  "nofb_mu3.2e5|--mobility 3.2e5 --time $TS"
  "fb_mu5e2|--mobility 5e2 --P0 0.07 --time $T"
  "fb_mu5e4|--mobility 5e4 --P0 0.07 --time $TS"
  "fb_P0_0.02|--mobility 2e3 --P0 0.02 --time $T"
  "fb_P0_0.005|--mobility 2e3 --P0 0.005 --time $T"
  "nofb_mu2e3|--mobility 2e3 --time $T"
)
# Fig. S2.11's feedback sweep once more at the no-feedback fit's mobility.
for p0 in 0.1 0.07 0.02; do runs+=("fb_mu8e4_P0_$p0|--mobility 8e4 --P0 $p0 --time $TS"); done
for a in 1.2 2 3; do runs+=("outlet_$a|--mobility 8e4 --time $TS --outlet $a"); done
# The avalanche size against the outlet scatters from seed to seed: seeds 2..OUTLET_SEEDS as well.
OUTLET_SEEDS=${OUTLET_SEEDS:-3}
for seed in $(seq 2 "$OUTLET_SEEDS"); do
  for a in 1.2 1.4 2 3; do runs+=("outlet_${a}_s$seed|--mobility 8e4 --time $TS --outlet $a --seed $seed"); done
done
for a in 1.2 1.4 2 3; do runs+=("sticky_$a|--mobility 8e4 --time $TS --outlet $a --contact sticky --attraction 0.05"); done
# One run and its avalanches: NAME OPTIONS... (rkc unless the options name an integrator).
run_one() {
  local name=$1
  shift
  local integrator=(--integrator rkc) seed=(--seed 1)
  case " $* " in *" --integrator "*) integrator=() ;; esac
  case " $* " in *" --seed "*) seed=() ;; esac
  echo "== jam2d chamber ${seed[*]} $*" >&2
  "$jam2d" chamber "${seed[@]}" --every 0.01 "${integrator[@]}" "$@" -q --csv "$out/chamber_$name.csv"
  "$jam2d" avalanches "$out/chamber_$name.csv" --distribution "$out/chamber_${name}_drops_dist.csv" \
    -o "$out/chamber_${name}_drops.csv"
}
export -f run_one
export jam2d out
if [ "${REUSE:-0}" != 1 ]; then
  printf '%s\n' "${runs[@]}" | tr '|' ' ' | parallel -j 2 --halt now,fail=1 run_one {=uq=}
fi
/usr/bin/python3 - "$out" "$OUTLET_SEEDS" <<'PY'
import csv, math, sys
out = sys.argv[1]
outlet_seeds = int(sys.argv[2])
def meta(path):
    m = {}
    for line in open(path):
        if not line.startswith("#"): break
        k, _, v = line[2:].strip().partition("=")
        m[k] = v
    return m
def series(name):
    return [r for r in csv.DictReader(l for l in open(f"{out}/chamber_{name}.csv") if not l.startswith("#"))]
def summary(name):
    m = meta(f"{out}/chamber_{name}_drops.csv")
    rows = [r for r in series(name) if float(r["time"]) >= float(m["from"])]
    cp = sum(float(r["c_P"]) for r in rows) / max(1, len(rows))
    cells = sum(float(r["chamber_cells"]) for r in rows) / max(1, len(rows))
    return dict(P=float(m["mean_pressure"]), events=int(m["events"]), drop=float(m["mean_drop"]),
                size=float(m["mean_size"]), ratio=float(m["drop_over_rise_rate"]), tail=int(m["tail_events"]),
                scale=float(m["tail_scale_over_mean_drop"]), ks=float(m["tail_ks_distance"]), cP=cp, cells=cells,
                span=float(m["to"]) - float(m["from"]))
S = {name: summary(name) for name in ["nofb", "fb", "gear3", "euler", "nofb_mu2e4", "nofb_mu3.2e5", "fb_mu5e2", "fb_mu5e4",
                                      "fb_P0_0.02", "fb_P0_0.005", "nofb_mu2e3"]
     + [f"fb_mu8e4_P0_{p}" for p in ("0.1", "0.07", "0.02")]
     + [f"outlet_{a}" for a in ("1.2", "2", "3")] + [f"sticky_{a}" for a in ("1.2", "1.4", "2", "3")]}
S["outlet_1.4"] = S["nofb"]
# The avalanche size per outlet over seeds 1..outlet_seeds (seed 1 at a = 1.4 is the main run,
# TIME long; every other run SWEEP_TIME): the mean of the per-seed means and its standard error.
def seeds_of(a):
    return [S[f"outlet_{a}"]] + [summary(f"outlet_{a}_s{k}") for k in range(2, outlet_seeds + 1)]
def mean_err(values):
    m = sum(values) / len(values)
    if len(values) < 2: return m, float("nan")
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1) / len(values))
size_over_seeds = {a: mean_err([r["size"] for r in seeds_of(a)]) for a in ("1.2", "1.4", "2", "3")}
P_over_seeds = {a: mean_err([r["P"] for r in seeds_of(a)]) for a in ("1.2", "1.4", "2", "3")}
n = S["nofb"]
ks_crit = 1.36 / math.sqrt(max(1, n["tail"]))
lines = [
    "| quantity | here | thesis |",
    "|---|---|---|",
    f"| ⟨P⟩ without feedback (μ = 8×10⁴), wall pressure | {n['P']:.3f} k ({n['events']} events over {n['span']:.0f}/γ) | 0.19 k |",
    f"| the same with the Gear integrator / Euler (over {S['gear3']['span']:.0f}/γ) | {S['gear3']['P']:.3f} / {S['euler']['P']:.3f} k | (Gear) |",
    f"| mean drop ⟨ΔP⟩ and c_P: Runge-Kutta-Chebyshev / Gear / Euler | {n['drop']:.3f} / {S['gear3']['drop']:.3f} / {S['euler']['drop']:.3f} k; {n['cP']:.2f} / {S['gear3']['cP']:.2f} / {S['euler']['cP']:.2f} | |",
    f"| cells in the chamber | {n['cells']:.0f} | \"up to about 100\" (experiment) |",
    f"| drops above the mean: exponential? | scale {n['scale']:.2f} ⟨ΔP⟩, KS distance {n['ks']:.3f} for {n['tail']} drops (5 % critical value {ks_crit:.3f}) | \"nearly exponentially distributed\" |",
    f"| Ṗ↓/Ṗ↑, no feedback, μ = 2×10⁴ / 8×10⁴ / 3.2×10⁵ | {S['nofb_mu2e4']['ratio']:.2f} / {n['ratio']:.2f} / {S['nofb_mu3.2e5']['ratio']:.2f} | rises with μ; 8×10⁴ fits the experiment (Fig. S2.10b) |",
    f"| Ṗ↓/Ṗ↑, feedback P0 = 0.07 k, μ = 5×10² / 2×10³ / 5×10⁴ | {S['fb_mu5e2']['ratio']:.2f} / {S['fb']['ratio']:.2f} / {S['fb_mu5e4']['ratio']:.2f} | rises with μ; 2×10³ fits (Fig. S2.10c) |",
    f"| ⟨P⟩ at μ = 2×10³: P0 = ∞ / 0.07 / 0.02 / 0.005 k | {S['nofb_mu2e3']['P']:.3f} / {S['fb']['P']:.3f} / {S['fb_P0_0.02']['P']:.3f} / {S['fb_P0_0.005']['P']:.3f} k | rises as P0 falls (Fig. S2.11) |",
    f"| c_P at μ = 2×10³: P0 = ∞ / 0.07 / 0.02 / 0.005 k | {S['nofb_mu2e3']['cP']:.2f} / {S['fb']['cP']:.2f} / {S['fb_P0_0.02']['cP']:.2f} / {S['fb_P0_0.005']['cP']:.2f} | falls by about 40 % (Fig. S2.11) |",
    f"| ⟨P⟩ and c_P at μ = 8×10⁴: P0 = ∞ / 0.1 / 0.07 / 0.02 k | {n['P']:.3f} / " + " / ".join(f"{S['fb_mu8e4_P0_'+p]['P']:.3f}" for p in ("0.1", "0.07", "0.02")) + f" k; {n['cP']:.2f} / " + " / ".join(f"{S['fb_mu8e4_P0_'+p]['cP']:.2f}" for p in ("0.1", "0.07", "0.02")) + " | ⟨P⟩ rises, c_P falls by about 40 % (Fig. S2.11) |",
    "| ⟨P⟩ against the outlet a = 1.2 / 1.4 / 2 / 3 σ, no attraction | " + " / ".join(f"{S['outlet_'+a]['P']:.3f}" for a in ("1.2", "1.4", "2", "3")) + " k | falls with a (Fig. S2.13) |",
    "| mean avalanche (cells) against a, no attraction, seed 1 | " + " / ".join(f"{S['outlet_'+a]['size']:.1f}" for a in ("1.2", "1.4", "2", "3")) + " | grows with a (Fig. S2.13) |",
    f"| the same, mean ± standard error over seeds 1-{outlet_seeds} | " + " / ".join(f"{size_over_seeds[a][0]:.1f} ± {size_over_seeds[a][1]:.1f}" for a in ("1.2", "1.4", "2", "3")) + " | grows with a (Fig. S2.13) |",
    f"| ⟨P⟩ against a, the same seeds | " + " / ".join(f"{P_over_seeds[a][0]:.3f} ± {P_over_seeds[a][1]:.3f}" for a in ("1.2", "1.4", "2", "3")) + " k | falls with a (Fig. S2.13) |",
    "| ⟨P⟩ against a with attraction Δ = 0.05 σ | " + " / ".join(f"{S['sticky_'+a]['P']:.3f}" for a in ("1.2", "1.4", "2", "3")) + " k | above the non-sticky pressure (Fig. 2.4c) |",
]
# The thesis's viscous-friction estimate (S2.15-S2.20): P = 3 pi k eta N_o N_c for the cells in the
# outlet pushed out against the medium; eta = 1e-3 Pa s, N_c = 100, N_o = 10, k = 0.4 / h (the
# thesis rounds it to 1e-4 / s).
eta, Nc, No = 1e-3, 100, 10
P_rounded = 3 * math.pi * 1e-4 * eta * No * Nc
P_exact = 3 * math.pi * (0.4 / 3600) * eta * No * Nc
lines.append(f"| viscous friction in the outlet, 3πkηN_oN_c (S2.17) | {P_rounded:.2e} Pa (k = 10⁻⁴/s), {P_exact:.2e} Pa (k = 0.4/h): "
             "10⁹ times below the measured 0.7 MPa, so friction cannot explain the pressure | \"1 × 10⁻³ Pa\", negligible |")
open(f"{out}/chamber_summary.md", "w").write("\n".join(lines) + "\n")
with open(f"{out}/chamber_outlets.dat", "w") as g:
    g.write("# outlet P_plain size_plain P_sticky size_sticky size_plain_seeds size_plain_seeds_error\n")
    for a in ("1.2", "1.4", "2", "3"):
        g.write(f"{a} {S['outlet_'+a]['P']} {S['outlet_'+a]['size']} {S['sticky_'+a]['P']} {S['sticky_'+a]['size']} "
                f"{size_over_seeds[a][0]} {size_over_seeds[a][1]}\n")
with open(f"{out}/chamber_rates.dat", "w") as g:
    g.write("# mobility ratio_nofb ratio_fb\n")
    for mu, a, b in ((5e2, None, "fb_mu5e2"), (2e3, "nofb_mu2e3", "fb"), (2e4, "nofb_mu2e4", None),
                     (5e4, None, "fb_mu5e4"), (8e4, "nofb", None), (3.2e5, "nofb_mu3.2e5", None)):
        g.write(f"{mu} {S[a]['ratio'] if a else 'NaN'} {S[b]['ratio'] if b else 'NaN'}\n")
print(open(f"{out}/chamber_summary.md").read())
PY
gnuplot -e "dir='$out'" scripts/figures/plot_chamber.gp
echo "make chamber-figures: $out/chamber_summary.md, $out/chamber_fig2_2.png, chamber_fig2_2e.png, chamber_figS2_10.png, chamber_outlets.png" >&2
