"""Rows of the README benchmark table for shell mechanics (scripts/bench/20-shell.sh: name, value, unit per thread count)."""


def _row(r):
    name, value, unit, threads = r["name"], float(r["value"]), r["unit"], r["threads"]
    if name.startswith("inflate_2562"):
        return (f"shellpack shell: inflate one shell to equilibrium, {threads} thread(s)", "2562 vertices",
                f"{value:.2f} {unit}", "thesis's code: 5 shells x 625 vertices, 200 steps did not finish in 300 s")
    kind, vertices = name.rsplit("_", 1)
    if kind == "triangle_forces":
        return None  # said in the force_evaluations row
    if kind == "force_evaluations":
        triangles = 2 * int(vertices) - 4
        per_core = value * triangles / 1e6 / int(threads)
        return (f"shellpack shell: forces of SVK + hinge-uniform + turgor, {threads} thread(s)", f"{vertices} vertices",
                f"{value:,.0f} evaluations/s = {value * triangles / 1e6:.1f} M triangles/s ({per_core:.1f} M per core)",
                "goal: tens of millions of triangle force evaluations per second per core")
    return (f"shellpack shell: FIRE relaxation, {threads} thread(s)", f"{vertices} vertices", f"{value:,.0f} iterations/s",
            "force passes on all threads from 65536 elements, FIRE's vector passes from 2048 vertices")


SECTIONS = {"shell.csv": _row}
