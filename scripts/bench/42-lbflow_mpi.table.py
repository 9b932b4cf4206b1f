"""Rows of the README benchmark table for lbflow on MPI ranks (scripts/bench/42-lbflow_mpi.sh),
and the model of its parallel efficiency on many machines.

The model (docs/lbflow.md, "Across machines"): each machine holds a cube of n^3 lattice nodes
(porosity phi) as a range of slabs along the flow axis; a step costs n^3 phi / R of compute (R:
the machine's fluid-node updates per second) plus the halo exchange, not overlapped: two
messages (one per neighbour) of 5 populations x 8 bytes per fluid node of a plane, one way
after an even step and back after an odd one, i.e. 2 latencies + 80 phi n^2 bytes / bandwidth
per step. Efficiency = compute / (compute + exchange); with slabs a machine has at most two
neighbours, so it does not depend on the machine count (8 or 256) in weak scaling. The
reductions of the steady-state test (every 100 steps, a gather of 32 bytes per slab over log2 P
latency hops) are added, amortised.
"""
import math

NETWORK_GBS = 10.0      # stated network: 10 GB/s per link
LATENCY_US = 2.0        # and 2 microseconds per message
CORES_PER_MACHINE = 32  # a cluster machine of 32 cores at this machine's speed per core

_rows = {}


def _mpi(r):
    ranks, threads = int(r["ranks"]), int(r["threads_per_rank"])
    _rows[(ranks, threads)] = r
    mlups = float(r["mlups"])
    size = (f"N = 50 jammed, delta = 0.04, M = {r['refine']}: {int(r['fluid_nodes']) / 1e6:.2f} M fluid nodes, "
            f"{int(r['plane_nodes'])} nodes per plane")
    if ranks == 1:
        return None  # folded into the 2-rank row
    if ranks == 2:
        one = _rows.get((1, 2))
        ratio = f" against {float(one['mlups']):.1f} MLUPS on 1 rank x 2 threads (ratio {mlups / float(one['mlups']):.2f})" if one else ""
        figure = (f"2 ranks x 1 thread: {mlups:.1f} MLUPS{ratio}; halo {float(r['halo_bytes_per_step']) / 1e6:.2f} MB "
                  f"per step, {float(r['halo_us_per_step']):.0f} us per step in the exchange")
        return ("lbflow on MPI ranks (mpirun, shared memory)", size, figure, "within 10 % of 1 rank x 2 threads")
    figure = (f"{ranks} ranks x 1 thread (oversubscribed on {ranks} > cores): {mlups:.1f} MLUPS, halo "
              f"{float(r['halo_bytes_per_step']) / 1e6:.2f} MB per step, {float(r['halo_us_per_step']):.0f} us per "
              f"step in the exchange (waiting for the others included)")
    return ("lbflow on MPI ranks (mpirun, shared memory)", size, figure, "halo: at most 80 B per fluid node of a cut plane")


def efficiency(n, phi, rate, machines):
    compute = n ** 3 * phi / rate
    exchange = 2 * LATENCY_US * 1e-6 + 80 * phi * n ** 2 / (NETWORK_GBS * 1e9)
    reduce = math.ceil(math.log2(machines)) * LATENCY_US * 1e-6 / 100
    return compute / (compute + exchange + reduce)


def _model(r):
    per_core = float(r["per_core_mlups"]) * 1e6
    rate = per_core * CORES_PER_MACHINE
    phi = float(r["porosity"])
    n80 = next(n for n in range(8, 4000) if all(efficiency(n, phi, rate, p) >= 0.8 for p in (8, 16, 64, 256)))
    effs = ", ".join(f"n = {n}: {efficiency(n, phi, rate, 256) * 100:.0f} %" for n in (64, 128, 256, 512))
    return ("lbflow on 8-256 machines (model)",
            f"weak scaling, n^3 nodes per machine, porosity {phi:.2f}, {CORES_PER_MACHINE} cores x "
            f"{per_core / 1e6:.1f} MLUPS per machine, {NETWORK_GBS:.0f} GB/s, {LATENCY_US:.0f} us",
            f"efficiency over 80 % above n = {n80} ({n80 ** 3 / 1e6:.2f} M nodes per machine); {effs} "
            f"(same for 8 and 256 machines: two neighbours each)",
            "waLBerla: 10^12 cells, 1.93 10^12 cell updates/s on 1.8 M threads, excellent weak and strong scaling (Godenschwager et al., SC13)")


SECTIONS = {"lbflow_mpi.csv": _mpi, "lbflow_mpi_model.csv": _model}
