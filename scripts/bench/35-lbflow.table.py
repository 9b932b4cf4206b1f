"""Rows of the README benchmark table for lbflow's kernel (scripts/bench/35-lbflow.sh)."""


def _fractions(r):
    """The fraction of the 304-byte bound, and of the bound with the link table's bytes where the CSV has it."""
    text = f"{float(r['fraction_of_bound']):.2f}"
    if r.get("fraction_with_links") and r.get("precision", "double") == "double":
        text += f" (with the links' bytes, {float(r['update_bytes']):.0f} B per update: {float(r['fraction_with_links']):.2f})"
    return text


def _speed(r):
    what = "dense 128^3, body force" if r["case"] == "dense" else f"porous 128^3 box, porosity {float(r['porosity']):.2f}, pressure planes"
    precision = r.get("precision", "double")
    return (f"lbflow kernel: D3Q19 {r['collision'].upper()}, {precision}, {r['threads']} thread(s)", what,
            f"{float(r['mlups']):.1f} MLUPS = {_fractions(r)} of the (double) triad bound "
            f"({float(r['triad_gbs']):.1f} GB/s -> {float(r['bound_mlups']):.0f} MLUPS); even/odd AA steps alone "
            f"{float(r['even_mlups']):.0f}/{float(r['odd_mlups']):.0f} MLUPS; {float(r['bytes_per_node']):.0f} B/fluid node",
            "Palabos rows below, same run; goal >= 1/2 of the bound on 2 cores")


def _sphere(r):
    return ("lbflow kernel: simple cubic sphere array, MRT, body force",
            f"solid fraction {float(r['solid_fraction']):.3f}, {r['N']} nodes per cell (radius {float(r['radius']):.1f})",
            f"kappa error {100 * float(r['err_halfway']):+.1f} % (half-way walls), {100 * float(r['err_interpolated']):+.1f} % (interpolated), {r['steps']} steps",
            f"Zick & Homsy K = {r['K_zick_homsy']}")


SECTIONS = {"lbflow_kernel.csv": _speed, "lbflow_sphere_array.csv": _sphere}
