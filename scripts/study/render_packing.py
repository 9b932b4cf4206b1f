#!/usr/bin/python3
"""render_packing.py PACKING.off CLUSTER.vtk OUT.png [FLOW.vtk]: one shell packing, its percolating
pore cluster and (with lbflow's --vtk field) streamlines of the flow through it, drawn by VTK's
renderer (Fig. 5.2A). The shells are unwrapped across the periodic faces
along their edges (as percolate and shellpack analyze read them); the cluster (percolate's image,
1 = the spanning cluster) is drawn as its iso-surface at 0.5. Needs a display: the report runs
it under xvfb-run when there is none."""
import sys
from collections import deque

import numpy as np
import vtk
from vtk.util import numpy_support


def read_packing(path):
    box, counts, lines = None, None, []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s.startswith("# box"):
                box = np.array([float(x) for x in s.split()[2:5]])
            elif s.startswith("# shells"):
                counts = [int(x) for x in s.split()[3:]]
            elif s and not s.startswith("#"):
                lines.append(s)
    nv, nf = (int(x) for x in lines[1].split()[:2])
    V = np.array([[float(x) for x in l.split()[:3]] for l in lines[2:2 + nv]])
    F = np.array([[int(x) for x in l.split()[1:4]] for l in lines[2 + nv:2 + nv + nf]])
    return V, F, box, counts


def unwrap(V, F, box):
    """Each vertex moved by box vectors to sit within half a box of its neighbours along edges."""
    adj = [[] for _ in range(len(V))]
    for a, b, c in F:
        adj[a] += (b, c)
        adj[b] += (a, c)
        adj[c] += (a, b)
    out, seen = V.copy(), np.zeros(len(V), bool)
    for start in range(len(V)):
        if seen[start]:
            continue
        seen[start] = True
        q = deque([start])
        while q:
            u = q.popleft()
            for w in adj[u]:
                if not seen[w]:
                    d = V[w] - out[u]
                    out[w] = out[u] + d - box * np.round(d / box)
                    seen[w] = True
                    q.append(w)
    return out


def polydata(V, F):
    pts = vtk.vtkPoints()
    pts.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(V), deep=True))
    cells = vtk.vtkCellArray()
    conn = np.hstack([np.full((len(F), 1), 3), F]).astype(np.int64).ravel()
    cells.SetCells(len(F), numpy_support.numpy_to_vtkIdTypeArray(conn, deep=True))
    pd = vtk.vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    return pd


def streamlines(flow, box):
    """Streamlines of lbflow's velocity field from a grid of seeds on the inlet plane, coloured by speed."""
    reader = vtk.vtkStructuredPointsReader()
    reader.SetFileName(flow)
    reader.ReadAllVectorsOn()
    reader.ReadAllScalarsOn()
    reader.Update()
    data = reader.GetOutput()
    data.GetPointData().SetActiveVectors("velocity")
    seeds = vtk.vtkPlaneSource()
    seeds.SetOrigin(0.02 * box[0], 0, 0)
    seeds.SetPoint1(0.02 * box[0], box[1], 0)
    seeds.SetPoint2(0.02 * box[0], 0, box[2])
    seeds.SetResolution(24, 24)
    tracer = vtk.vtkStreamTracer()
    tracer.SetInputData(data)
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetIntegrationDirectionToForward()
    tracer.SetMaximumPropagation(4 * box[0])
    tracer.SetIntegratorTypeToRungeKutta45()
    tracer.Update()
    speed = tracer.GetOutput().GetPointData().GetArray("velocity")
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(tracer.GetOutputPort())
    if speed is not None:
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("velocity")
        mapper.ColorByArrayComponent("velocity", -1)
        lo, hi = speed.GetRange(-1)
        mapper.SetScalarRange(lo, hi)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetLineWidth(1.5)
    return actor


def main(packing, cluster, out, flow=None):
    V, F, box, _ = read_packing(packing)
    V = unwrap(V, F, box)
    ren = vtk.vtkRenderer()
    ren.SetBackground(1, 1, 1)
    shells = vtk.vtkPolyDataMapper()
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(polydata(V, F))
    shells.SetInputConnection(normals.GetOutputPort())
    sa = vtk.vtkActor()
    sa.SetMapper(shells)
    sa.GetProperty().SetColor(0.85, 0.55, 0.35)
    sa.GetProperty().SetOpacity(0.35)
    ren.AddActor(sa)
    reader = vtk.vtkStructuredPointsReader()
    reader.SetFileName(cluster)
    reader.ReadAllScalarsOn()
    iso = vtk.vtkContourFilter()
    iso.SetInputConnection(reader.GetOutputPort())
    iso.SetValue(0, 0.5)
    cm = vtk.vtkPolyDataMapper()
    cm.SetInputConnection(iso.GetOutputPort())
    cm.ScalarVisibilityOff()
    ca = vtk.vtkActor()
    ca.SetMapper(cm)
    ca.GetProperty().SetColor(0.2, 0.4, 0.85)
    if flow:
        ca.GetProperty().SetOpacity(0.25)
        ren.AddActor(streamlines(flow, box))
    ren.AddActor(ca)
    outline = vtk.vtkOutlineSource()
    outline.SetBounds(0, box[0], 0, box[1], 0, box[2])
    om = vtk.vtkPolyDataMapper()
    om.SetInputConnection(outline.GetOutputPort())
    oa = vtk.vtkActor()
    oa.SetMapper(om)
    oa.GetProperty().SetColor(0, 0, 0)
    ren.AddActor(oa)
    cam = ren.GetActiveCamera()
    cam.Azimuth(35)
    cam.Elevation(25)
    ren.ResetCamera()
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(900, 750)
    win.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(out)
    png.SetInputConnection(grab.GetOutputPort())
    png.Write()


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        sys.exit("usage: render_packing.py PACKING.off CLUSTER.vtk OUT.png [FLOW.vtk]")
    main(*sys.argv[1:])
