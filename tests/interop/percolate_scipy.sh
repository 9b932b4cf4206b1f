#!/usr/bin/env bash
# percolate's connected-component labelling against scipy.ndimage.label (python3-scipy, a
# Debian package; the thesis's tool): random images, non-periodic, with the 6, 18 and 26
# structuring elements, component for component; and periodic merging against scipy's labels
# joined across the faces.
#   bash percolate_scipy.sh --list     one case per line
#   bash percolate_scipy.sh CASE       needs CMP_BIN (build/bin; test_voxel is in build/)
set -euo pipefail

cases=(six eighteen twentysix periodic)
if [[ ${1:-} == --list ]]; then
  printf '%s\n' "${cases[@]}"
  exit 0
fi
case_name=${1:?usage: $0 --list | CASE}
[[ " ${cases[*]} " == *" $case_name "* ]] || { echo "unknown case '$case_name'; cases: ${cases[*]}" >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
python=/usr/bin/python3  # the Debian interpreter, where python3-scipy lives
test_voxel="${CMP_BIN:?set CMP_BIN to the build folder bin/}/../test_voxel"
[[ -x $test_voxel ]] || { echo "no test_voxel at $test_voxel: build the test_voxel target" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export CMP_INTEROP_DIR=$work
"$python" "$here/percolate_scipy.py" write "$case_name" "$work"
for threads in 1 2; do
  OMP_NUM_THREADS=$threads "$test_voxel" -w NoTests "[.scipy]" > /dev/null
  "$python" "$here/percolate_scipy.py" check "$case_name" "$work"
done
