#!/usr/bin/env bash
# make run, the study: the thesis's campaign (make study) at toy size, jammed packings squeezed,
# voxelised, flowed through and fitted, and its report. Sourced by scripts/demo.sh ($build, $out, step()).
step "make study STUDY=demo: 4 packings of 12 shells (162 vertices) squeezed to phi = 0.8, percolate at 3 voxel sizes, lbflow, kcfit, the report"
make -f scripts/study/study.mk --no-print-directory STUDY=demo STUDY_DIR="$out/study" BUILD="$build" THREADS=1 -j2 all \
  >"$out/study.log" 2>&1 || { tail -30 "$out/study.log" >&2; echo "make run: the study failed (log: $out/study.log)" >&2; exit 1; }
cat >>"$out/README.txt" <<TXT
  study/report.html   the study at toy size (make study STUDY=demo): Figs 5.2-5.5, Ch. 4, Table S5.1 beside the thesis
  study/tables/, study/fits/, study/figures/   its tables (one per stage), kcfit's fits and the figures
TXT
