"""Markdown of scripts/tables/thesis.sh's CSV files: ours beside the printed values."""
import csv
import sys

out, seed = sys.argv[1], sys.argv[2]


def table(name, title):
    rows = list(csv.DictReader(open(f"{out}/{name}.csv")))
    print(f"{title} (seed {seed}; printed values in parentheses)\n")
    print("| r_v | N | T_end | q_A | q_theta | q |\n|---|---|---|---|---|---|")
    for r in rows:
        cells = " | ".join(f"{float(r[k]):.3f} ({float(r['thesis_' + k]):.3f})" for k in ("q_A", "q_theta", "q"))
        print(f"| {r.get('r_v', '0.1')} | {r['N']} | {r['T_end']} | {cells} |")
    print()


table("table_a5", "Table A.5, R = 2.5")
table("table_a6", "Table A.6, N = 2500, r_v = 0.1, R = 2.5")
