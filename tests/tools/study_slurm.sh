#!/usr/bin/env bash
# The study campaign on Slurm for real: a single-node slurm-wlm on this machine
# (scripts/study/slurm_local.sh: munged, slurmctld, slurmd on localhost, up in about a second),
# then the tiny campaign inside an allocation with every recipe an srun job step, as on a cluster:
#   salloc -N1 make -f scripts/study/study.mk -j2 RUN='srun -N1 -n1 -c1 --exclusive'
#   bash study_slurm.sh --list | CASE     (needs CMP_BIN, CMP_SRC; as root)
set -uo pipefail
if [[ ${1:-} == --list ]]; then echo campaign_as_job_steps; exit 0; fi
[ "${1:?CASE}" = campaign_as_job_steps ] || { echo "unknown case '$1'" >&2; exit 2; }
bin=${CMP_BIN:?set CMP_BIN}
src=${CMP_SRC:?set CMP_SRC}
tmp=$(mktemp -d)
fail() { echo "FAIL: $*" >&2; exit 1; }
trap '"$src/scripts/study/slurm_local.sh" stop "$tmp/slurm"; rm -rf "$tmp"' EXIT
export OMP_NUM_THREADS=1
"$src/scripts/study/slurm_local.sh" start "$tmp/slurm" >"$tmp/env" || fail "Slurm did not start"
export SLURM_CONF="$tmp/slurm/slurm.conf"
salloc -N1 make -C "$src" -f scripts/study/study.mk --no-print-directory STUDY=tiny STUDY_DIR="$tmp/st" \
  BUILD="$(dirname "$bin")" THREADS=1 -j2 RUN='srun -N1 -n1 -c1 --exclusive' all >"$tmp/log" 2>&1 ||
  fail "the campaign under salloc: $(tail -20 "$tmp/log")"
[ -s "$tmp/st/report.html" ] || fail "no report"
n=$(wc -l <"$tmp/st/log/recipes.log")
steps=$(grep -c ' slurm_step=[0-9]*\.[0-9]*$' "$tmp/st/log/recipes.log")
[ "$n" -gt 10 ] && [ "$steps" = "$n" ] || fail "$steps of $n recipes ran as Slurm job steps: $(head -5 "$tmp/st/log/recipes.log")"
jobs=$(sed -n 's/.* slurm_step=\([0-9]*\)\..*/\1/p' "$tmp/st/log/recipes.log" | sort -u | wc -l)
[ "$jobs" = 1 ] || fail "the steps belong to $jobs jobs, not to the one allocation"
echo "$n recipes, each an srun step of one allocation"
