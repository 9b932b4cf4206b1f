"""Rows of the README benchmark table for percolate (scripts/bench/30-percolate.sh)."""


def _label(r):
    what = f"random, porosity {float(r['porosity']):.2f}" if r["image"] == "random" else \
        f"shell packing pore space, porosity {float(r['porosity']):.2f}"
    return (
        f"percolate: connected components (6-conn.), {r['threads']} thread(s)",
        f"{r['N']}^3, {what}",
        f"{float(r['mvoxels_per_s']):.0f} M voxels/s ({float(r['seconds']) * 1e3:.0f} ms), "
        f"{float(r['speedup']):.1f}x scipy; peak RSS {float(r['bytes_per_voxel']):.1f} B/voxel",
        f"scipy.ndimage.label {float(r['scipy_mvoxels_per_s']):.0f} M voxels/s, same run; target >= 300 M/s on 2 cores",
    )


SECTIONS = {
    "percolate_label.csv": _label,
    "percolate_voxelise.csv": lambda r: (
        f"percolate: voxelisation, {r['threads']} thread(s)",
        f"{r['shells']} shells x {r['vertices_per_shell']} vertices, delta = {r['delta']} "
        f"({r['nx']}x{r['ny']}x{r['nz']})",
        f"triangles {float(r['triangles_seconds']) * 1e3:.0f} ms, vertices {float(r['vertices_seconds']) * 1e3:.1f} ms",
        "(thesis: not reported)"),
}
