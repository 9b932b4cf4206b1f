#!/usr/bin/env bash
# make run, kcfit: the fits of thesis Table S5.1 on the SYNTHETIC sample tables of data/kcfit
# (points drawn from the thesis's fitted laws with noise, scripts/kcfit_sample_data.py) until
# percolate and lbflow feed it their own CSVs. Sourced by scripts/demo.sh, which sets $bin,
# $out and step(); appends to $out/README.txt what it made.
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
  kc_fit.csv, kc_fit.png   Eq. 5.8 fitted to synthetic permeabilities (log loss) + classical KC (kcfit)
  kc_fixed_fit.csv, power_fit.csv, power_fixed_fit.csv   the other laws of Table S5.1 (kcfit)
  tortuosity_fit.csv, hydraulic_radius_fit.csv           tau_H and R_h laws (kcfit)
  percolation_fit.csv/.png sigmoid of the percolation probability, maximum likelihood (kcfit)
  threshold_fit.csv/.png   phi_c(delta) = phi_c* + A delta^beta, Table S5.1's N = 50 law (kcfit)
  (kcfit inputs are SYNTHETIC sample tables from data/kcfit until percolate/lbflow feed it)
EOT
