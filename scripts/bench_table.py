"""Turns the CSV files of scripts/bench.sh into the Markdown table of the README."""
import csv
import sys
from pathlib import Path


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


out, machine, stamp = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
print(f"Measured by `make bench` on {machine}, {stamp}.\n")
print("| work | size | figure | reference (BENCHMARKS.md) |")
print("|---|---|---|---|")
# One row formatter per CSV file of scripts/bench.sh; files that are absent are skipped.
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
for name, row in SECTIONS.items():
    if (out / name).exists():
        for r in rows(out / name):
            print("| " + " | ".join(row(r)) + " |")
