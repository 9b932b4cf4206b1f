#!/usr/bin/env bash
# make bench, jam2d chamber (thesis Ch. 2): simulated generation times (ln 2 / gamma0) per
# wall-clock second in the thesis's 6 x 16 sigma chamber at its steady state (about 100 cells),
# without feedback (mu = 8e4) and with (P0 = 0.07 k, mu = 2e3), with the Gear integrator (the
# default), Euler and the Runge-Kutta-Chebyshev step (rkc), on 1 and 2 threads (the run is
# serial: the row shows that the second thread neither helps nor hurts) and with another process busy on one core. Each case resumes
# one checkpoint taken at t = 6/gamma0, after the chamber has filled. Target: 500 generation
# times (a Fig. 2.2 series) in under 5 minutes. Sourced by scripts/bench/run.sh ($build, $out).
echo "== jam2d chamber: generation times per second at the steady state" >&2
work=$(mktemp -d)
jam2d="$build/bin/jam2d"
# name|options|simulated time measured [1/gamma0]
configs=(
  "nofb_gear3|--mobility 8e4 --integrator gear3|0.3"
  "nofb_euler|--mobility 8e4 --integrator euler|1"
  "nofb_rkc|--mobility 8e4 --integrator rkc|5"
  "fb_gear3|--mobility 2e3 --P0 0.07 --integrator gear3|10"
  "fb_euler|--mobility 2e3 --P0 0.07 --integrator euler|30"
  "fb_rkc|--mobility 2e3 --P0 0.07 --integrator rkc|60"
)
{
  bench_header
  echo "case,integrator,mobility,P0,threads,load,cells,simulated,seconds,generations_per_second,minutes_for_500_generations"
  for c in "${configs[@]}"; do
    IFS='|' read -r name opts span <<<"$c"
    "$jam2d" chamber --seed 1 $opts --time 6 --every 0.5 --csv "$work/$name.csv" --checkpoint "$work/$name.ckpt" -q
    cells=$(tail -1 "$work/$name.csv" | cut -d, -f4)
    to=$(awk -v s="$span" 'BEGIN { print 6 + s }')
    for load in none busy; do
      for threads in 1 2; do
        [ $load = busy ] && [ $threads = 1 ] && continue
        hog=
        if [ $load = busy ]; then sh -c 'while :; do :; done' & hog=$!; fi
        t0=$(date +%s%N)
        OMP_NUM_THREADS=$threads "$jam2d" chamber --seed 1 $opts --time "$to" --every 0.5 --csv /dev/null --resume "$work/$name.ckpt" -q
        t1=$(date +%s%N)
        [ -n "$hog" ] && kill "$hog"
        awk -v n="$name" -v o="$opts" -v th="$threads" -v l="$load" -v c="$cells" -v s="$span" -v ns=$((t1 - t0)) 'BEGIN {
          split(o, w, " "); mu = ""; P0 = "inf"; integ = "";
          for (i = 1; i in w; i++) { if (w[i] == "--mobility") mu = w[i+1]; if (w[i] == "--P0") P0 = w[i+1]; if (w[i] == "--integrator") integ = w[i+1] }
          sec = ns / 1e9; g = s / log(2) / sec;
          printf "%s,%s,%s,%s,%d,%s,%s,%s,%.3f,%.4g,%.3g\n", n, integ, mu, P0, th, l, c, s, sec, g, 500 / g / 60 }'
      done
    done
  done
} | tee "$out/chamber_speed.csv" >&2
rm -rf "$work"
