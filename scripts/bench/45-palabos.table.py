"""Rows of the README benchmark table for Palabos beside lbflow's kernel (scripts/bench/45-palabos.sh).

Each Palabos speed row names lbflow's figure for the same case and core count from the same
make bench run (lbflow_kernel.csv of scripts/bench/35-lbflow.sh, palabos_lbflow_cluster.csv)
and the ratio."""
import csv
import sys
from pathlib import Path

_OUT = Path(sys.argv[1])  # scripts/bench/table.py's output folder: the CSV files of this run


def _rows(name):
    path = _OUT / name
    if not path.exists():
        return []
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def _lbflow(r):
    """lbflow's row for the case, collision and core count of Palabos row r, or None."""
    if r["case"] == "cluster":
        rows = [x for x in _rows("palabos_lbflow_cluster.csv") if x["N"] == r["N"]]
    else:
        rows = [x for x in _rows("lbflow_kernel.csv") if x["case"] == r["case"] and x["N"] == r["N"]
                and x["collision"] == r["collision"]]
    return next((x for x in rows if x["threads"] == r["processes"]), None)


def _speed(r):
    n, fluid = int(r["N"]), int(r["fluid_nodes"])
    if r["case"] == "dense":
        what = f"dense {n}^3, " + ("body force (Guo)" if r["driving"] == "body_force" else "pressure planes, no force term")
    elif r["case"] == "porous":
        what = f"porous {n}^3 box, porosity {float(r['porosity']):.2f}, pressure planes"
    else:
        what = f"N = 50 jammed, delta = 0.04 cluster (lbflow's lattice): {n}^3 nodes, {fluid / 1e6:.2f} M fluid, pressure planes"
    mlups = float(r["mlups"])
    lb = _lbflow(r)
    if lb is None:
        ref = f"no lbflow {r['collision'].upper()} row for this case in this run"
    else:
        ref = (f"lbflow {lb['collision'].upper()}, {lb['threads']} thread(s), same run: {float(lb['mlups']):.1f} MLUPS "
               f"= {float(lb['mlups']) / mlups:.1f}x Palabos")
        if int(lb["fluid_nodes"]) != fluid:
            ref += f" (CASE DIFFERS: {lb['fluid_nodes']} fluid nodes)"
        elif r["case"] == "dense" and r["driving"] != "body_force":
            ref += " (lbflow's row is body-force driven)"
    return (f"Palabos 1.5: D3Q19 {r['collision'].upper()}, double, {r['processes']} MPI process(es)", what,
            f"{mlups:.1f} MLUPS over fluid nodes ({float(r['mlups_all_nodes']):.1f} over all nodes, {r['steps']} steps); "
            f"{r['bytes_per_node']} B/node, every node stored", ref)


def _duct(r):
    def rel(a, b):
        d = float(a) / float(b) - 1
        return "< 1e-9" if abs(d) < 1e-9 else f"{d:+.0e}"

    if r["palabos_bgk"]:
        what = f"square duct, {r['width']} x {r['width']} fluid nodes, body force, tau = {float(r['tau']):.1f}"
        bgk = f"; BGK: Palabos {float(r['palabos_bgk']):.7g}, lbflow off by {rel(r['lbflow_bgk'], r['palabos_bgk'])}"
    else:
        what = f"square duct, {r['width']} x {r['width']} fluid nodes, 16 long, pressure planes, tau = 1"
        bgk = ""
    return ("same physics? kappa (lattice units), Palabos 1.5 vs lbflow", what,
            f"MRT: Palabos {float(r['palabos_mrt']):.7g}, lbflow mrt-dh off by {rel(r['lbflow_mrt_dh'], r['palabos_mrt'])}, "
            f"lbflow mrt (Lambda = 3/16) {100 * (float(r['lbflow_mrt']) / float(r['palabos_mrt']) - 1):+.2f} %{bgk}",
            "Palabos's MRT rates are d'Humieres et al. (2002)'s, lbflow's mrt-dh")


SECTIONS = {"palabos.csv": _speed, "palabos_duct.csv": _duct}
