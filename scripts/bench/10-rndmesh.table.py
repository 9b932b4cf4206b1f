"""Rows of the README benchmark table for rndmesh and the neighbour machinery."""

# One row formatter per CSV file of scripts/bench/10-rndmesh.sh.
SECTIONS = {
    "rndmesh_anneal.csv": lambda r: (
        "rndmesh random: annealing, 200 x 100 sweeps, 1 core", f"N = {r['N']}",
        f"{float(r['seconds']):.2f} s, {float(r['trial_moves_per_s']) / 1e6:.1f} M trial moves/s "
        f"({float(r['ns_per_move']):.0f} ns/move)", "thesis code 1.5-1.9 M moves/s"),
    "rndmesh_anneal_decades.csv": lambda r: (
        "rndmesh random: one temperature decade, 50 x 100 sweeps, 1 core",
        f"N = {r['N']}, T {r['T_max']} to {r['T_min']}",
        f"{float(r['trial_moves_per_s']) / 1e6:.1f} M trial moves/s, acceptance {float(r['acceptance']):.2f}",
        "thesis code 1.5-1.9 M moves/s"),
    "rndmesh_delaunay.csv": lambda r: (
        "rndmesh: spherical Delaunay (CGAL), 1 core", f"N = {int(r['N']):,}",
        f"{float(r['seconds']):.3f} s ({float(r['points_per_s']) / 1e6:.2f} M points/s)",
        "CGAL 10^6 points in 0.6-1.2 s"),
    "neighbours.csv": lambda r: (
        f"neighbour list build / force loop, {r['order']}", f"N = {int(r['N']):,}, {r['threads']} thread(s)",
        f"{float(r['build_ms']):.1f} ms / {float(r['force_loop_ms']):.1f} ms "
        f"({float(r['pairs_per_particle']):.1f} neighbours each)", "(foundation for shellpack)"),
}
