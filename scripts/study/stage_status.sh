#!/usr/bin/env bash
# stage_status.sh STAGE DONE TOTAL LOG [N,M:COUNT ...]: one row of `make study-status`: the
# stage, how many of its targets are finished and of how many, the seconds its finished tasks
# took (LOG, timed.sh's rows: the last one per target), their mean, and the time left running the
# targets still to do one at a time on this machine (divide by -j, or by the nodes of a cluster):
# COUNT of them with runs of N shells (0: no N, as the mesh) at refinement M (the flow's; 0
# elsewhere). Each counts at the mean of the finished targets of its N and M, or, when none of
# those has finished, at the seconds per shell of the finished ones (of its M) times N: a
# compression of 50 shells costs about what three of 16 do, so a campaign that has run only its
# small N is not told that it is nearly done.
set -euo pipefail
stage=$1 done=$2 total=$3 log=$4
shift 4
[ -f "$log" ] || log=/dev/null
awk -F, -v stage="$stage" -v done="$done" -v total="$total" -v left="$*" '
  function last_number(t, re, skip,   n) {  # the number in the last match of re, after skip characters
    n = 0
    while (match(t, re)) { n = substr(t, RSTART + skip, RLENGTH - skip) + 0; t = substr(t, RSTART + RLENGTH) }
    return n
  }
  { seconds[$2] = $3 }
  END {
    n = 0; sum = 0
    for (t in seconds) {
      n++; sum += seconds[t]
      k = last_number(t, "N[0-9]+_s", 1); m = last_number(t, "/M[0-9]+/", 2)
      group_sum[k, m] += seconds[t]; group_n[k, m]++
      if (k > 0) { shell_sum[m] += seconds[t] / k; shell_n[m]++ }
    }
    if (n == 0) { printf "%s,%d,%d,0,,\n", stage, done, total; exit }
    mean = sum / n
    estimate = 0
    groups = split(left, group, " ")
    for (i = 1; i <= groups; ++i) {
      split(group[i], part, /[,:]/); k = part[1] + 0; m = part[2] + 0; count = part[3] + 0
      if (group_n[k, m] > 0) each = group_sum[k, m] / group_n[k, m]
      else if (k > 0 && shell_n[m] > 0) each = shell_sum[m] / shell_n[m] * k
      else each = mean
      estimate += count * each
    }
    printf "%s,%d,%d,%.1f,%.1f,%.0f\n", stage, done, total, sum, mean, estimate
  }' "$log"
