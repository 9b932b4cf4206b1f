#!/usr/bin/env bash
# check_tools.sh [RUN]: what the campaign needs beyond the toolkit's programs, each missing one
# named with the command that installs it (one line each, exit 2): python3 with numpy and
# matplotlib (the report), python3-vtk9 and xvfb-run without a display (its picture), and srun
# when the recipes run under it.
set -uo pipefail
status=0
missing() { echo "study: $1 is missing: $2 (or make deps)" >&2; status=2; }
py=/usr/bin/python3
if [ ! -x $py ]; then
  missing "python3" "apt-get install python3"
else
  $py -c "import numpy" 2>/dev/null || missing "numpy for $py" "apt-get install python3-numpy"
  $py -c "import matplotlib" 2>/dev/null || missing "matplotlib for $py" "apt-get install python3-matplotlib"
  $py -c "import vtk" 2>/dev/null || missing "VTK for $py" "apt-get install python3-vtk9"
fi
[ -n "${DISPLAY:-}" ] || command -v xvfb-run >/dev/null || missing "xvfb-run (the picture's renderer needs a display)" "apt-get install xvfb xauth"
case "${1:-}" in srun*) command -v srun >/dev/null || missing "srun (RUN=$1)" "apt-get install slurm-client";; esac
exit $status
