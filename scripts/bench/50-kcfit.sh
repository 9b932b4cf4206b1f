#!/usr/bin/env bash
# make bench, kcfit: fits per second and bootstrap wall time (bench_fit), and scipy's
# curve_fit on the same data for the ratio. Sourced by scripts/bench/run.sh, which sets $bench
# (the benchmark programs), $out, $machine and $stamp.
echo "== kcfit: Eq. 5.8 fits on ln kappa (120 points) and a 1000-replica bootstrap; scipy curve_fit alongside" >&2
{
  bench_header
  echo "stage,model,points,threads,fits,seconds,fits_per_s"
  "$bench/bench_fit"
  "$bench/bench_fit" data | /usr/bin/python3 scripts/bench/kcfit_scipy.py || echo "# scipy timing failed" >&2
} | tee "$out/kcfit.csv" >&2
