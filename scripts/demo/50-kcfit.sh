#!/usr/bin/env bash
# make run, kcfit: first the chain on its own output (jammed packings inflated, percolate,
# lbflow, then Eq. 5.8 and the tortuosity law fitted to lbflow's permeabilities, as make
# flow-figure does at a larger size), then every model of thesis Table S5.1 on the SYNTHETIC
# sample tables of data/kcfit (points drawn from the thesis's fitted laws with noise,
# scripts/data/kcfit_sample_data.py: enough points for every model, and the percolation outcomes
# and thresholds that only many packings give). Sourced by scripts/demo/run.sh, which sets $bin,
# $out and step(); appends to $out/README.txt what it made.
chain="$out/chain" scales=0.90,0.94,0.98,1.02,1.06,1.10,1.14
mkdir -p "$chain"
step "the chain to a fitted law: 4 jammed packings of 32 spheres inflated by $scales, percolate (delta = 0.08 D0), lbflow (M = 1), kcfit"
"$bin/shellpack" jam -N 32 --seeds 1:4 -q -o "$chain/jam_{seed}.xyz" --csv /dev/null
"$bin/percolate" "$chain"/jam_*.xyz --delta 0.08 --scale "$scales" -q --csv "$chain/percolate.csv" \
  -o "$chain/c_{name}_{scale}.vtk"
# shellcheck disable=SC2046
"$bin/lbflow" $(scripts/data/percolating_images.sh "$chain/percolate.csv" "$chain" "$scales") --refine 1 -q \
  -o "$chain/flows.csv"
"$bin/kcfit" "$chain/flows.csv" --model kc-percolation --y permeability_d02 --loss log -o "$out/kc_flow_fit.csv"
"$bin/kcfit" "$chain/flows.csv" --model tortuosity -o "$out/tortuosity_flow_fit.csv"

kc_data=data/kcfit
step "kcfit: permeability, Eq. 5.8 with free gamma, log loss (Fig. 5.5), with the classical KC law"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model kc-percolation --loss log --plot "$out/kc_fit.png" --plot-kc \
  -o "$out/kc_fit.csv"
step "kcfit: the fixed-exponent form (2.52) and the power-law ansatz, log loss"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model kc-fixed --loss log -o "$out/kc_fixed_fit.csv"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model power --loss log -o "$out/power_fit.csv"
step "kcfit: power law with phi_c fixed at 0.141, linear loss (Fig. S5.5 D), bootstrap errors"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model power --fix phi_c=0.141 --loss linear --bootstrap 1000 --seed 1 \
  -o "$out/power_fixed_fit.csv"
step "kcfit: tortuosity tau_H = C (phi - phi_c)^-0.38 (Fig. 5.4 B) and hydraulic radius (Fig. 5.3)"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model tortuosity -o "$out/tortuosity_fit.csv"
"$bin/kcfit" "$kc_data/flow_synthetic.csv" --model hydraulic-radius -o "$out/hydraulic_radius_fit.csv"
step "kcfit: percolation probability (maximum likelihood on 0/1 outcomes) and threshold extrapolation (Fig. 5.2 C-D)"
"$bin/kcfit" "$kc_data/percolation_synthetic.csv" --model sigmoid --plot "$out/percolation_fit.png" \
  -o "$out/percolation_fit.csv"
"$bin/kcfit" "$kc_data/threshold_synthetic.csv" --model threshold --x delta --y phi_c --plot "$out/threshold_fit.png" \
  -o "$out/threshold_fit.csv"

cat >>"$out/README.txt" <<EOT
  chain/                   4 jammed packings inflated, their percolating clusters, flows.csv (lbflow)
  kc_flow_fit.csv          Eq. 5.8 fitted to those permeabilities in D0^2 (kcfit, log loss)
  tortuosity_flow_fit.csv  tau_H = C (phi - phi_c)^-0.38 fitted to their tortuosities (kcfit)
  kc_fit.csv, kc_fit.png   Eq. 5.8 fitted to synthetic permeabilities (log loss) + classical KC (kcfit)
  kc_fixed_fit.csv, power_fit.csv, power_fixed_fit.csv   the other laws of Table S5.1 (kcfit)
  tortuosity_fit.csv, hydraulic_radius_fit.csv           tau_H and R_h laws (kcfit)
  percolation_fit.csv/.png sigmoid of the percolation probability, maximum likelihood (kcfit)
  threshold_fit.csv/.png   phi_c(delta) = phi_c* + A delta^beta, Table S5.1's N = 50 law (kcfit)
  (the fits above the chain's own: SYNTHETIC sample tables from data/kcfit, every model of Table S5.1)
EOT
