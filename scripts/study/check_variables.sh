#!/usr/bin/env bash
# Checks the campaign's variables (NAME=VALUE arguments) before any work: one line per problem
# on stderr, exit 2 when there is any. Ranges are FIRST:LAST[:STEP] or comma-separated lists.
set -uo pipefail
here=$(dirname "$0")
status=0
bad() { echo "study: $1: $2" >&2; status=2; }
values() { "$here/range.sh" "$1"; }
is_number() { [[ $1 =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]]; }
n_value=
for arg in "$@"; do
  name=${arg%%=*} value=${arg#*=}
  [ $name = N ] && n_value=$value
  [ $name = FLOW_N ] && [ "$value" = "$n_value" ] && continue  # the default: N, said once
  case $name in
    N|FLOW_N)
      [ -n "$value" ] || { [ $name = FLOW_N ] && continue; bad $name "empty: give the shell counts, e.g. N='16 32'"; continue; }
      for n in $value; do [[ $n =~ ^[0-9]+$ ]] && [ "$n" -ge 10 ] || bad $name "'$n' is not a shell count of at least 10 (shellpack jam: fewer would touch their own images)"; done ;;
    SEEDS|FLOW_SEEDS)
      [ $name = FLOW_SEEDS ] && [ -z "$value" ] && continue
      list=$(values "$value"); [ -n "$list" ] || { bad $name "'$value' names no seed (FIRST:LAST or a list)"; continue; }
      for s in $list; do [[ $s =~ ^[0-9]+$ ]] || bad $name "'$s' is not a non-negative integer seed"; done ;;
    VERTICES)
      case $value in 12|42|162|642|2562|10242) ;; *) bad $name "'$value' is not an icosahedral mesh size (12, 42, 162, 642, 2562, 10242)";; esac ;;
    PHI)
      list=$(values "$value"); [ -n "$list" ] || { bad $name "'$value' is an empty range"; continue; }
      for p in $list; do is_number "$p" && awk -v p="$p" 'BEGIN { exit !(p > 0 && p < 1) }' || bad $name "'$p' is not a volume fraction in (0, 1)"; done ;;
    DELTA|FLOW_DELTA)
      list=$(values "$value"); [ -n "$list" ] || { bad $name "'$value' is an empty range"; continue; }
      for d in $list; do is_number "$d" && awk -v d="$d" 'BEGIN { exit !(d > 0 && d < 1) }' || bad $name "'$d' must lie in (0, 1) (units of D0)"; done ;;
    REFINE)
      list=$(values "$value"); [ -n "$list" ] || { bad $name "'$value' is an empty range"; continue; }
      for m in $list; do [[ $m =~ ^[0-9]+$ ]] && [ "$m" -ge 1 ] && [ "$m" -le 8 ] || bad $name "'$m' is not a refinement from 1 to 8"; done ;;
    THREADS)
      [[ $value =~ ^[0-9]+$ ]] || bad $name "'$value' is not a thread count (0: all cores)" ;;
  esac
done
exit $status
