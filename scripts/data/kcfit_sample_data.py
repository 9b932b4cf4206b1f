#!/usr/bin/python3
"""Writes the SYNTHETIC sample tables of data/kcfit/ (not simulation results): points drawn
from the laws the thesis fitted (Table S5.1, N = 50, delta = 0.04) with noise, so that kcfit's
demo and tests have percolate/lbflow-like input before those tools exist.
    /usr/bin/python3 scripts/data/kcfit_sample_data.py data/kcfit
Prefactors C are not printed in the thesis; the values here are illustrative."""
import math
import random
import sys

out = sys.argv[1] if len(sys.argv) > 1 else "data/kcfit"
rng = random.Random(20261123)
head = ("# synthetic=1\n# source=scripts/data/kcfit_sample_data.py (not simulation output)\n")

with open(f"{out}/flow_synthetic.csv", "w") as f:
    f.write(head)
    f.write("# law_permeability=50 (phi - 0.146)^(0.83 + 0.76) phi^2 / (1 - phi)^2 x lognormal(0.15)\n")
    f.write("# law_tortuosity=0.74 (phi - 0.124)^-0.38 + normal(0.02)\n")
    f.write("# law_hydraulic_radius=1.0 phi / (1 - phi) x (1 + normal(0.03))\n")
    f.write("porosity,permeability,tortuosity,hydraulic_radius\n")
    for i in range(120):
        phi = 0.16 + 0.29 * rng.random()
        k = 50 * (phi - 0.146) ** 1.59 * phi**2 / (1 - phi) ** 2 * math.exp(rng.gauss(0, 0.15))
        tau = 0.74 * (phi - 0.124) ** -0.38 + rng.gauss(0, 0.02)
        rh = phi / (1 - phi) * (1 + rng.gauss(0, 0.03))
        f.write(f"{phi!r},{k!r},{tau!r},{rh!r}\n")

with open(f"{out}/threshold_synthetic.csv", "w") as f:
    f.write(head)
    f.write("# law=phi_c(delta) = 0.035 + 3.67 delta^1.1, Table S5.1's N = 50 law, rounded to 4 decimals\n")
    f.write("delta,phi_c\n")
    for d, p in [(0.03, 0.1125), (0.04, 0.1414), (0.05, 0.1710), (0.06, 0.2012), (0.07, 0.2319)]:
        f.write(f"{d},{p}\n")

with open(f"{out}/percolation_synthetic.csv", "w") as f:
    f.write(head)
    f.write("# law=P(percolates) = 1 / (1 + exp(-(phi - 0.141) / 0.01)), one Bernoulli draw per packing\n")
    f.write("# delta=0.04\n")
    f.write("porosity,percolates\n")
    for i in range(200):
        phi = 0.08 + 0.14 * rng.random()
        p = 1 / (1 + math.exp(-(phi - 0.141) / 0.01))
        f.write(f"{phi!r},{1 if rng.random() < p else 0}\n")
