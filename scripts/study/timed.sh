#!/usr/bin/env bash
# timed.sh LOGDIR STAGE TARGET COMMAND...: runs one recipe of the campaign and, when it
# succeeds, appends `stage,target,seconds,parameters` to LOGDIR/<stage>.csv: its wall time and
# the hash of the stage's parameters file (LOGDIR/../params/<stage>.txt; analyze: compress's),
# which the report compares with the current one. Every start is counted in LOGDIR/recipes.log
# (with its Slurm job step when srun launched it), so a test can see what a rerun recomputed.
set -uo pipefail
source "$(dirname "$0")/forward_signals.sh"
log=$1 stage=$2 target=$3
shift 3
mkdir -p "$log"
echo "$stage $target${SLURM_STEP_ID:+ slurm_step=$SLURM_JOB_ID.$SLURM_STEP_ID}" >> "$log/recipes.log"
start=$(date +%s.%N)
forward_signals "$@"
status=$?
if [ $status -eq 0 ]; then
  params="$log/../params/${stage/analyze/compress}.txt"
  hash=$( [ -f "$params" ] && sha1sum "$params" | cut -c1-12 )
  awk -v a="$start" -v b="$(date +%s.%N)" -v s="$stage" -v t="$target" -v h="$hash" \
    'BEGIN { printf "%s,%s,%.3f,%s\n", s, t, b - a, h }' >> "$log/$stage.csv"
fi
exit $status
