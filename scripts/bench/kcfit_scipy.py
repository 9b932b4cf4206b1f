"""Times scipy.optimize.curve_fit (thesis 5.5.6's tool) on the data of bench_fit: Eq. 5.8 on
ln kappa from (C, phi_c, gamma) = (40, 0.14, 1), with curve_fit's finite-difference Jacobian
(as a user would call it) and with the analytic one. Reads the CSV of `bench_fit data` on
stdin; prints rows stage,model,points,threads,fits,seconds,fits_per_s."""
import sys
import time
import warnings

import numpy as np
from scipy.optimize import curve_fit

warnings.simplefilter("ignore")
data = np.loadtxt(sys.stdin, delimiter=",", skiprows=1)
x, y = data[:, 0], np.log(data[:, 1])


def f(x, c, pc, g):
    return np.log(c) + (g + 0.76) * np.log(x - pc) + 2 * np.log(x) - 2 * np.log(1 - x)


def jac(x, c, pc, g):
    return np.column_stack([np.full_like(x, 1 / c), -(g + 0.76) / (x - pc), np.log(x - pc)])


for stage, kw in (("scipy_curve_fit", {}), ("scipy_curve_fit_analytic_jac", {"jac": jac})):
    fits, t0 = 0, time.perf_counter()
    while time.perf_counter() - t0 < 1.0 or fits < 10:
        curve_fit(f, x, y, p0=[40, 0.14, 1.0], **kw)
        fits += 1
    dt = time.perf_counter() - t0
    print(f"{stage},kc-percolation,{x.size},1,{fits},{dt:.6f},{fits / dt:.1f}")
