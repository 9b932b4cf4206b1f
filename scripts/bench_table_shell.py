"""Rows of the README benchmark table for shell mechanics (scripts/bench_shell.sh: name, value, unit per thread count)."""

_WHAT = {
    "force_evaluations": "shell forces (SVK + hinge-uniform + turgor), force evaluations",
    "triangle_forces": "shell forces (SVK + hinge-uniform + turgor), triangles",
    "fire_iterations_per_s": "shell relaxation, FIRE iterations",
}


def _row(r):
    name, value, unit = r["name"], r["value"], r["unit"]
    if name.startswith("inflate_2562"):
        return (f"shellpack shell: inflate one shell to equilibrium, {r['threads']} thread(s)", "2562 vertices",
                f"{float(value):.2f} {unit}", "thesis's code: 5 shells x 625 vertices, 200 steps did not finish in 300 s")
    kind, vertices = name.rsplit("_", 1)
    return (f"shellpack shell: {_WHAT.get(kind, kind)}, {r['threads']} thread(s)", f"{vertices} vertices",
            f"{float(value):,.0f} per second", "goal: tens of millions of triangle force evaluations per second per core")


SECTIONS = {"shell.csv": _row}
