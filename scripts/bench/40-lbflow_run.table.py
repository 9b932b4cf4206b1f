"""Rows of the README benchmark table for lbflow as a program (scripts/bench/40-lbflow_run.sh)."""

_m1_steps = {}


def _row(r):
    m, steps, s = int(r["refine"]), int(r["steps"]), float(r["seconds"])
    if m == 1:
        _m1_steps["steps"] = steps
    size = (f"N = 50 jammed, delta = 0.04 ({r['voxels_per_side']}^3 voxels), M = {m}: "
            f"{int(r['nodes']) / 1e6:.2f} M nodes, {int(r['fluid_nodes']) / 1e6:.2f} M fluid")
    mlups = float(r["mlups"])
    bound = ""
    if r.get("bound_mlups"):
        links = ""
        if r.get("bound_with_links_mlups"):
            links = f"; with the links' bytes, 340 B per update: {mlups / float(r['bound_with_links_mlups']):.2f}"
        bound = (f" = {mlups / float(r['bound_mlups']):.2f} of the (double) triad bound measured just before "
                 f"({float(r['triad_gbs']):.1f} GB/s -> {float(r['bound_mlups']):.0f} MLUPS{links})")
    if r["converged"] == "1":
        figure = (f"{s:.0f} s to convergence ({steps} steps), {mlups:.0f} MLUPS{bound}, "
                  f"{float(r['bytes_per_fluid_node']):.0f} B/fluid node, peak {r['peak_rss_mb']} MB")
    else:
        est = ""
        if "steps" in _m1_steps:
            total = int(round(1.4 * _m1_steps["steps"], -2))
            est = (f"; to convergence ~{total} steps = ~{total * s / steps / 60:.0f} min (1.4x the M = 1 steps, "
                   f"as the refinement runs of make flow-figure took)")
        figure = (f"{mlups:.0f} MLUPS{bound} over {steps} steps, {float(r['bytes_per_fluid_node']):.0f} "
                  f"B/fluid node, peak {r['peak_rss_mb']} MB{est}")
    return (f"lbflow (whole program), {r['threads']} thread(s)", size, figure,
            "thesis: Palabos MRT, up to ~10^7 nodes per packing; ~10 MLUPS per core here")


SECTIONS = {"lbflow_run.csv": _row}
