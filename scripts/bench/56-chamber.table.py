"""Rows of the README benchmark table for jam2d chamber (scripts/bench/56-chamber.sh)."""


def _row(r):
    feedback = "no feedback" if r["P0"] == "inf" else f"feedback P0 = {r['P0']} k"
    load = ", another process busy on one core" if r["load"] == "busy" else ""
    return (
        f"jam2d chamber, {r['integrator']}, {r['threads']} thread(s){load}",
        f"6 x 16 sigma, {feedback}, mu = {r['mobility']}, {r['cells']} cells",
        f"{float(r['generations_per_second']):.3g} generation times per second "
        f"(500 in {float(r['minutes_for_500_generations']):.3g} min)",
        "Fig. 2.2 series: 500 generation times in < 5 min",
    )


SECTIONS = {"chamber_speed.csv": _row}
