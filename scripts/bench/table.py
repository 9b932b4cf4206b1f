"""Turns the CSV files of scripts/bench/run.sh into the Markdown table of the README."""
import csv
import importlib.util
import sys
from pathlib import Path


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


out, machine, stamp = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
print(f"Measured by `make bench` on {machine}, {stamp}.\n")
print("| work | size | figure | reference |")
print("|---|---|---|---|")
# Each tool's rows come from NN-<tool>.table.py of this folder, in the order of NN (that of
# the benchmarks, NN-<tool>.sh): a SECTIONS map from a CSV file of its benchmark to a row
# formatter; files that are absent are skipped.
here = Path(__file__).parent
for path in sorted(here.glob("[0-9][0-9]-*.table.py")):
    tool = path.name.removesuffix(".table.py").split("-", 1)[1]
    spec = importlib.util.spec_from_file_location(f"bench_table_{tool}", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    for name, row in module.SECTIONS.items():
        if (out / name).exists():
            for r in rows(out / name):
                cells = row(r)
                if cells:  # a formatter may fold a row into another
                    print("| " + " | ".join(cells) + " |")
