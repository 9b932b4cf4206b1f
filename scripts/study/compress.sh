#!/usr/bin/env bash
# compress.sh SHELLPACK DIR PACKING MESH 'PHI...' THREADS PARAMS [OPTIONS...]: one compression of
# the campaign, DIR/compress.csv and DIR/pack_<phi>.off at every PHI, checkpointed in DIR/run.ckpt
# every 5 minutes. A checkpoint left by a killed run is resumed (it repeats the run's own
# arguments, and refuses one of other inputs) unless the campaign's parameters file PARAMS
# changed since; a finished run removes it.
set -euo pipefail
source "$(dirname "$0")/forward_signals.sh"
shellpack=$1 dir=$2 packing=$3 mesh=$4 phis=$5 threads=$6 params=$7
shift 7
ckpt="$dir/run.ckpt"
if [ -f "$ckpt" ] && [ "$ckpt" -ot "$params" ]; then rm -f "$ckpt"; fi
if [ -f "$ckpt" ]; then
  forward_signals "$shellpack" compress --resume "$ckpt" --threads "$threads" -q
else
  forward_signals "$shellpack" compress "$packing" --mesh "$mesh" --phi "$(echo $phis | tr ' ' ',')" "$@" --threads "$threads" -q \
    -o "$dir/pack_{phi}.off" --csv "$dir/compress.csv" --checkpoint "$ckpt" --checkpoint-every 300
fi
rm -f "$ckpt"
