#!/usr/bin/env bash
# make run, the study: the thesis's campaign (make study) at toy size, jammed packings squeezed,
# voxelised, flowed through and fitted, and its report. Sourced by scripts/demo/run.sh ($build, $out, step()).
step "make study STUDY=demo: 4 packings of 12 shells (162 vertices) squeezed to phi = 0.8, percolate at 3 voxel sizes, lbflow, kcfit, the report"
make -f scripts/study/study.mk --no-print-directory STUDY=demo STUDY_DIR="$out/study" BUILD="$build" THREADS=1 -j2 all \
  >"$out/study.log" 2>&1 || { tail -30 "$out/study.log" >&2; echo "make run: the study failed (log: $out/study.log)" >&2; exit 1; }
cat >>"$out/README.txt" <<TXT
  study/report.html   the study at toy size (make study STUDY=demo): Figs 5.2-5.5, Ch. 4, Table S5.1 beside the thesis
  study/tables/, study/fits/, study/figures/   its tables (one per stage), kcfit's fits and the figures
TXT
# The fitted laws must come out finite and physical: 0 < phi_c < 1, a positive total exponent of
# Eq. 5.8 (gamma + 0.76 > 0), a tortuosity that falls with porosity (e < 0).
/usr/bin/python3 - "$out/study/fits" <<'PY' >&2 || { echo "make run: the study's fits are not physical" >&2; exit 1; }
import csv, math, sys
def params(name):
    rows = csv.DictReader(l for l in open(f"{sys.argv[1]}/{name}.csv") if not l.startswith("#"))
    return {r["parameter"]: float(r["value"]) for r in rows}
kc, tau = params("kappa_kc-percolation_log"), params("tortuosity_free_M1")
phi_c, gamma, e = kc["phi_c"], kc["gamma"], tau["e"]
print(f"  study: Eq. 5.8 phi_c = {phi_c:.3f}, gamma = {gamma:.2f}; tau_H ~ (phi - phi_c)^e, e = {e:.2f}")
assert all(math.isfinite(v) for v in (phi_c, gamma, e)), (phi_c, gamma, e)
assert 0 < phi_c < 1 and gamma + 0.76 > 0 and e < 0, (phi_c, gamma, e)
PY
