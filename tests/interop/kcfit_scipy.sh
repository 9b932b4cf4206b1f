#!/usr/bin/env bash
# kcfit and scipy.optimize.curve_fit (python3-scipy, what thesis 5.5.6 used) agree on the same
# data: parameters and standard errors to 1e-6 relative, for several models and both losses.
#   bash kcfit_scipy.sh --list     one case per line
#   bash kcfit_scipy.sh CASE       needs CMP_BIN (build/bin)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
python=/usr/bin/python3  # the Debian interpreter, where python3-scipy lives
if [[ ${1:-} == --list ]]; then
  "$python" "$here/kcfit_scipy.py" --list
  exit 0
fi
case_name=${1:?usage: $0 --list | CASE}
kcfit="${CMP_BIN:?set CMP_BIN to the build folder bin/}/kcfit"
[[ -x $kcfit ]] || { echo "no kcfit at $kcfit: build the kcfit target" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$python" "$here/kcfit_scipy.py" "$case_name" "$kcfit" "$work"
