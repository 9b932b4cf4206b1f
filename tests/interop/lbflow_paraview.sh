#!/usr/bin/env bash
# lbflow's --vtk output as ParaView reads it: VTK's own legacy reader (python3-vtk9, a Debian
# package; ParaView uses the same vtkStructuredPointsReader) finds the velocity vectors, the
# density and the fluid mask, the field data, and the geometry of the input image (origin and
# spacing in the packing's length units, refined M times), so the flow overlays percolate's
# cluster and the packing. The mean of u_x over every point is the CSV's superficial velocity.
#   bash lbflow_paraview.sh --list     one case per line
#   bash lbflow_paraview.sh CASE       needs CMP_BIN (build/bin)
set -euo pipefail

cases=(vtk_reader_geometry_and_fields)
if [[ ${1:-} == --list ]]; then
  printf '%s\n' "${cases[@]}"
  exit 0
fi
case_name=${1:?usage: $0 --list | CASE}
[[ " ${cases[*]} " == *" $case_name "* ]] || { echo "unknown case '$case_name'; cases: ${cases[*]}" >&2; exit 2; }
bin=${CMP_BIN:?set CMP_BIN to the build folder bin/}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
printf '1\nLattice="2 0 0 0 2 0 0 0 2" Properties=species:S:1:pos:R:3:radius:R:1 pbc="T T T" D0=2\nX 1 1 1 0.8\n' > s.xyz
"$bin/percolate" s.xyz --delta 0.125 -o c.vtk -q > p.csv
"$bin/lbflow" c.vtk --refine 2 --vtk flow.vtk -q > f.csv
/usr/bin/python3 - <<'PY'
import csv
import vtk
from vtk.util.numpy_support import vtk_to_numpy

def read(name):
    r = vtk.vtkStructuredPointsReader()
    r.SetFileName(name)
    r.ReadAllVectorsOn()
    r.ReadAllScalarsOn()
    r.Update()
    return r.GetOutput()

cluster, flow = read("c.vtk"), read("flow.vtk")
row = next(csv.DictReader(line for line in open("f.csv") if not line.startswith("#")))
M = int(row["refine"])
# The same box: the cluster's voxel centres, each voxel split into M^3 nodes.
cd, cs, co = cluster.GetDimensions(), cluster.GetSpacing(), cluster.GetOrigin()
fd, fs, fo = flow.GetDimensions(), flow.GetSpacing(), flow.GetOrigin()
assert fd == tuple(M * n for n in cd), (fd, cd)
for a in range(3):
    assert abs(fs[a] - cs[a] / M) < 1e-12, (fs, cs)
    assert abs(fo[a] - (co[a] - cs[a] / 2 + fs[a] / 2)) < 1e-12, (fo, co)
    lo, hi = flow.GetBounds()[2 * a], flow.GetBounds()[2 * a + 1]
    assert abs((hi - lo + fs[a]) - 2.0) < 1e-9, (lo, hi)  # the packing's box side
pd = flow.GetPointData()
u = vtk_to_numpy(pd.GetArray("velocity"))
rho = vtk_to_numpy(pd.GetArray("density"))
fluid = vtk_to_numpy(pd.GetArray("fluid"))
assert u.shape == (fd[0] * fd[1] * fd[2], 3), u.shape
assert fluid.sum() == int(row["fluid_nodes"]), (fluid.sum(), row["fluid_nodes"])
assert (u[fluid == 0] == 0).all() and (rho[fluid == 0] == 0).all()
assert abs(rho[fluid == 1].mean() - 1) < 1e-3
ux = u[:, 0].mean()  # superficial: solid points count as zero
want = float(row["superficial_velocity_lu"])
assert abs(ux - want) < 1e-5 * abs(want), (ux, want)
field = flow.GetFieldData()
values = {field.GetArrayName(i): field.GetArray(i).GetValue(0) for i in range(field.GetNumberOfArrays())}
assert values["delta"] == 0.125 and values["d0"] == 2.0 and values["refine"] == M, values
assert values["permeability_lu"] == float(row["permeability_lu"]), values
# The fluid nodes are the cluster's voxels, refined.
cl = vtk_to_numpy(cluster.GetPointData().GetScalars()).reshape(cd[2], cd[1], cd[0])
fl = fluid.reshape(fd[2], fd[1], fd[0])
assert (fl == cl.repeat(M, 0).repeat(M, 1).repeat(M, 2)).all()
PY
