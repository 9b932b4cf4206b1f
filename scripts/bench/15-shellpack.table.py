"""Rows of the README benchmark table for shellpack (scripts/bench/15-shellpack.sh)."""

SECTIONS = {
    "shellpack_jam.csv": lambda r: (
        f"`{r['command']}`: one jammed packing, max|f| 1e-15",
        f"N = {r['N']}, " + ("defaults: rattler-free isostatic (with retries)" if r['accepted'] == "rattler_free_isostatic" else "any jammed packing accepted"),
        f"{float(r['seconds_per_packing']):.3g} s per packing ({float(r['rejected_per_packing']):.1f} rejected tries each), "
        f"{float(r['particle_iterations_per_s']) / 1e6:.1f} M particle-iterations/s",
        "(thesis code: not reported)"),
    "shellpack_fire_lammps.csv": lambda r: (
        "FIRE, Hertzian spheres at phi = 0.66 to max|f_i| 1e-12, 1 core", f"N = {r['N']}",
        f"{float(r['ours_seconds']):.3f} s, {r['ours_iterations']} iterations, "
        f"{float(r['ours_particle_iterations_per_s']) / 1e6:.1f} M particle-it/s",
        f"LAMMPS in the same run: {float(r['lammps_seconds']):.3f} s, {r['lammps_iterations']} iterations, "
        f"{float(r['lammps_particle_iterations_per_s']) / 1e6:.1f} M particle-it/s; ours {float(r['speedup_time']):.1f}x faster"),
    "shellpack_fire_threads.csv": lambda r: (
        f"FIRE, Hertzian spheres at phi = 0.66 to max|f_i| 1e-12, {r['threads']} thread(s)", f"N = {r['N']}",
        f"{float(r['seconds']):.3f} s, {r['iterations']} iterations, "
        f"{float(r['particle_iterations_per_s']) / 1e6:.1f} M particle-it/s",
        "(same path on any thread count; parallel from N = 2048)"),
}
