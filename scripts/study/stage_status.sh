#!/usr/bin/env bash
# stage_status.sh STAGE DONE TOTAL LOG: one row of `make study-status`: the stage, how many of
# its targets are finished and of how many, the seconds its finished tasks took (LOG, timed.sh's
# rows: the last one per target), their mean, and that mean times the targets left: the time
# left running one task at a time on this machine (divide by -j, or by the nodes of a cluster).
set -euo pipefail
stage=$1 done=$2 total=$3 log=$4
[ -f "$log" ] || log=/dev/null
awk -F, -v stage="$stage" -v done="$done" -v total="$total" '
  { seconds[$2] = $3 }
  END {
    n = 0; sum = 0
    for (t in seconds) { n++; sum += seconds[t] }
    if (n == 0) { printf "%s,%d,%d,0,,\n", stage, done, total; exit }
    mean = sum / n
    printf "%s,%d,%d,%.1f,%.1f,%.0f\n", stage, done, total, sum, mean, mean * (total - done)
  }' "$log"
