"""Rows of the README benchmark table for the study's campaign (make study), one per stage."""


def _stage(r):
    what = {"mesh": "rndmesh icosa", "jam": "shellpack jam", "compress": "shellpack compress to phi = 0.8",
            "analyze": "shellpack analyze", "percolate": "percolate, one packing at one delta",
            "flow": "lbflow, one cluster"}.get(r["stage"], r["stage"])
    return (f"make study STUDY=demo (-j2), {what}", f"{r['tasks']} tasks",
            f"{float(r['total_s']):.1f} s in all, {float(r['mean_s']):.2f} s per task, longest {float(r['longest_s']):.1f} s",
            f"whole campaign {float(r['campaign_wall_s']):.0f} s wall")


SECTIONS = {"study.csv": _stage}
