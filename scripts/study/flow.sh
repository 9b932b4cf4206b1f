#!/usr/bin/env bash
# flow.sh LBFLOW CLUSTER.vtk M OUT.csv THREADS PARAMS [OPTIONS...]: one lbflow run of the campaign,
# checkpointed beside OUT (OUT without .csv, .ckpt) every 5 minutes; a checkpoint left by a
# killed run is resumed (it repeats the run's arguments) unless the campaign's parameters file
# PARAMS changed since; a finished run removes it.
set -euo pipefail
source "$(dirname "$0")/forward_signals.sh"
lbflow=$1 cluster=$2 M=$3 out=$4 threads=$5 params=$6
shift 6
ckpt="${out%.csv}.ckpt"
if [ -f "$ckpt" ] && { [ "$ckpt" -ot "$params" ] || [ "$ckpt" -ot "$cluster" ]; }; then rm -f "$ckpt"; fi
if [ -f "$ckpt" ]; then
  forward_signals "$lbflow" --resume "$ckpt" --threads "$threads" -q
else
  forward_signals "$lbflow" "$cluster" --refine "$M" "$@" --threads "$threads" -q -o "$out" --checkpoint "$ckpt" --checkpoint-every 300
fi
rm -f "$ckpt"
