#!/usr/bin/env bash
# Interoperability of lib/io with the programs users open our files in: ASE reads
# our extended XYZ, meshio our OFF and binary VTK, and our readers take what ASE and meshio
# write. test_io writes and reads the files (hidden Catch2 cases [.interop], [.interop-read]),
# io_readers.py runs the Python side.
#   bash io_readers.sh --list     one case per line
#   bash io_readers.sh CASE       needs CMP_BIN (build/bin; test_io is in build/)
set -euo pipefail

cases=(ase_xyz meshio_off meshio_vtk ase_writes_xyz meshio_writes_off)
if [[ ${1:-} == --list ]]; then
  printf '%s\n' "${cases[@]}"
  exit 0
fi
case_name=${1:?usage: $0 --list | CASE}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
python=/usr/bin/python3  # the Debian interpreter, where python3-ase and python3-meshio live
test_io="${CMP_BIN:?set CMP_BIN to the build folder bin/}/../test_io"
[[ -x $test_io ]] || { echo "no test_io at $test_io: build the test_io target" >&2; exit 1; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export CMP_INTEROP_DIR=$work

# -w NoTests: fail, rather than pass, when the tag or name matches no test case.
run_test_io() { "$test_io" -w NoTests "$1"; }

case $case_name in
  ase_xyz | meshio_off | meshio_vtk)
    run_test_io "[.interop]"
    "$python" "$here/io_readers.py" "$case_name" "$work"
    ;;
  ase_writes_xyz)
    "$python" "$here/io_readers.py" write_ase "$work"
    run_test_io "read an extended XYZ written by ASE"
    ;;
  meshio_writes_off)
    "$python" "$here/io_readers.py" write_meshio "$work"
    run_test_io "read an OFF written by meshio"
    ;;
  *)
    echo "unknown case '$case_name'; cases: ${cases[*]}" >&2
    exit 2
    ;;
esac
