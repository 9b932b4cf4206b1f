"""Rows of the README benchmark table for shellpack compress (scripts/bench/25-compress.sh)."""

SECTIONS = {
    "compress_steps.csv": lambda r: (
        f"shellpack compress: box steps after jamming, {r['threads']} thread(s)",
        f"{r['shells']} shells x {r['vertices_per_shell']} vertices, phi {r['phi_start']} -> {r['phi_end']} "
        f"({r['steps']} steps of 0.004 D0)",
        f"{float(r['seconds_per_step']):.2f} s per step, {float(r['iterations_per_s']):.0f} FIRE iterations/s, "
        f"{r['volume_updates']} volume updates",
        "thesis: days per compression; target 50 x 2562 to phi 0.95 in < 30 min on 2 cores"),
    "compress_whole.csv": lambda r: (
        f"shellpack compress: a whole compression, {r['contact']}, {r['threads']} thread(s)",
        f"{r['shells']} shells x {r['vertices_per_shell']} vertices, phi_J {r['phi_start']} -> {r['phi_end']} "
        f"({r['steps']} box steps)",
        f"{float(r['wall_seconds']):.0f} s wall, {r['fire_iterations']} FIRE iterations, "
        f"{r['volume_updates']} volume updates",
        "thesis: days per compression"),
    "compress_thesis.csv": lambda r: (
        f"shellpack compress: the thesis-sized compression ({r['options']}), {r['threads']} threads",
        f"{r['shells']} shells x {r['vertices_per_shell']} vertices, phi_J {r['phi_start']} -> 0.95 "
        f"({r['steps']} box steps)",
        f"{r['wall_minutes']} min wall, {r['fire_iterations']} FIRE iterations; phi 0.75 / 0.8 / 0.9 / 0.95 at "
        f"{r['minutes_to_0.75']} / {r['minutes_to_0.8']} / {r['minutes_to_0.9']} / {r['minutes_to_0.95']} min",
        "target < 30 min on 2 cores (the thesis: days)"),
}
