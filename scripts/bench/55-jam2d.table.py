"""Rows of the README benchmark table for jam2d (scripts/bench/55-jam2d.sh)."""


def _jamming(r):
    ref = "thesis's Fortran code: 48 cells, 60 s on one core; target <= 3 s (20x)" if r["box"] == "8" else \
        "(thesis: not reported)"
    return (
        f"jam2d: growth to jamming (1 thread), seed {r['seed']}",
        f"L = {r['box']} sigma, {r['cells']} cells, phi_J = {float(r['phi_J']):.4f}",
        f"{float(r['seconds']):.2f} s, {int(r['fire_iterations'])} FIRE iterations, "
        f"{r['accepted']} steps + {r['rejected']} rejected"
        + (f" ({60 / float(r['seconds']):.0f}x the thesis)" if r["box"] == "8" else ""),
        ref,
    )


SECTIONS = {
    "jam2d_jamming.csv": _jamming,
    "jam2d_sweep.csv": lambda r: (
        f"jam2d sweep, {r['threads']} threads" + (", --double-step" if r.get("step_after_acceptance") == "double" else ""),
        f"L = {r['box']} sigma, jamming + dphi = {r['dphi']}, {r['packings']} packings",
        f"{float(r['seconds_per_packing']):.1f} s per packing (100 packings: {float(r['seconds_per_packing']) * 100 / 60:.0f} min)",
        "Fig. 3.3 point (100 packings) in minutes on 2 cores"),
}
