"""kcfit against scipy.optimize.curve_fit, the routine thesis 5.5.6 used: the same synthetic
data through both, parameters and standard errors (curve_fit's default, absolute_sigma=False)
compared to 1e-6 relative. The log loss is curve_fit on ln y with ln f as the model.
    /usr/bin/python3 kcfit_scipy.py --list
    /usr/bin/python3 kcfit_scipy.py CASE KCFIT WORKDIR"""
import csv
import subprocess
import sys

np = None  # numpy and scipy are imported by run(), so that --list works without them

RTOL = 1e-6


def kc_perc(x, c, pc, g):
    return c * (x - pc) ** (g + 0.76) * x**2 / (1 - x) ** 2


def kc_perc_jac(x, c, pc, g):
    f = kc_perc(x, c, pc, g)
    return np.column_stack([f / c, -f * (g + 0.76) / (x - pc), f * np.log(x - pc)])


def kc_fixed(x, c, pc):
    return c * (x - pc) ** 2.52 * x**2 / (1 - x) ** 2


def kc_fixed_jac(x, c, pc):
    f = kc_fixed(x, c, pc)
    return np.column_stack([f / c, -f * 2.52 / (x - pc)])


def power(x, c, pc, e):
    return c * (x - pc) ** e


def power_jac(x, c, pc, e):
    f = power(x, c, pc, e)
    return np.column_stack([f / c, -f * e / (x - pc), f * np.log(x - pc)])


def classical(x, c):
    return c * x**3 / (1 - x) ** 2


def classical_jac(x, c):
    return np.column_stack([x**3 / (1 - x) ** 2])


def hydraulic(x, c):
    return c * x / (1 - x)


def hydraulic_jac(x, c):
    return np.column_stack([x / (1 - x)])


def threshold(x, s, a, b):
    return s + a * x**b


def threshold_jac(x, s, a, b):
    return np.column_stack([np.ones_like(x), x**b, a * x**b * np.log(x)])


def sigmoid(x, pc, w):
    return 1 / (1 + np.exp(-(x - pc) / w))


def sigmoid_jac(x, pc, w):
    f = sigmoid(x, pc, w)
    return np.column_stack([-f * (1 - f) / w, -f * (1 - f) * (x - pc) / w**2])


def fixing(f, jac, index, value, keep):
    """Model and Jacobian with parameter `index` held at value; keep: free columns."""
    def g(x, *p):
        q = list(p)
        q.insert(index, value)
        return f(x, *q)

    def gj(x, *p):
        q = list(p)
        q.insert(index, value)
        return jac(x, *q)[:, keep]

    return g, gj


def data(kind, n, seed):
    rng = np.random.default_rng(seed)
    if kind == "kappa":
        x = rng.uniform(0.16, 0.45, n)
        return x, kc_perc(x, 50.0, 0.146, 0.83) * np.exp(rng.normal(0, 0.15, n))
    if kind == "kappa_additive":
        x = rng.uniform(0.16, 0.45, n)
        y = kc_perc(x, 50.0, 0.146, 0.83)
        return x, y + rng.normal(0, 0.002 * y.max(), n)
    if kind == "tau":
        x = rng.uniform(0.14, 0.45, n)
        return x, power(x, 0.74, 0.124, -0.38) + rng.normal(0, 0.02, n)
    if kind == "rh":
        x = rng.uniform(0.1, 0.45, n)
        return x, hydraulic(x, 1.0) * (1 + rng.normal(0, 0.03, n))
    if kind == "threshold":
        x = np.array([0.03, 0.04, 0.05, 0.06, 0.07])
        return x, np.array([0.1125, 0.1414, 0.1710, 0.2012, 0.2319])
    if kind == "probability":
        x = np.linspace(0.08, 0.22, 29)
        return x, np.clip(sigmoid(x, 0.141, 0.01) + rng.normal(0, 0.04, x.size), 0, 1)
    if kind == "probability_weighted":  # binned fractions of 40 packings, binomial errors
        x = np.linspace(0.10, 0.18, 17)
        p = rng.binomial(40, sigmoid(x, 0.141, 0.01)) / 40
        return x, p, np.sqrt(np.maximum(p * (1 - p), 0.02) / 40)
    raise ValueError(kind)


# case: (data, model, loss, kcfit extra args, f, jac, p0, free parameter names)
_tau_fixed = fixing(power, power_jac, 2, -0.38, [0, 1])
_kc_pc = fixing(kc_perc, kc_perc_jac, 1, 0.141, [0, 2])
_pow_pc = fixing(power, power_jac, 1, 0.141, [0, 2])
CASES = {
    "kc_percolation_log": ("kappa", "kc-percolation", "log", [], kc_perc, kc_perc_jac, [50, 0.146, 0.83], ["C", "phi_c", "gamma"]),
    "kc_percolation_linear": ("kappa_additive", "kc-percolation", "linear", [], kc_perc, kc_perc_jac, [50, 0.146, 0.83], ["C", "phi_c", "gamma"]),
    "kc_percolation_fixed_phi_c_log": ("kappa", "kc-percolation", "log", ["--fix", "phi_c=0.141"], *_kc_pc, [50, 0.83], ["C", "gamma"]),
    "kc_fixed_log": ("kappa", "kc-fixed", "log", [], kc_fixed, kc_fixed_jac, [100, 0.1], ["C", "phi_c"]),
    "power_log": ("kappa", "power", "log", [], power, power_jac, [200, 0.12, 3.5], ["C", "phi_c", "e"]),
    "power_linear": ("kappa_additive", "power", "linear", [], power, power_jac, [200, 0.12, 3.5], ["C", "phi_c", "e"]),
    "power_fixed_phi_c_linear": ("kappa_additive", "power", "linear", ["--fix", "phi_c=0.141"], *_pow_pc, [100, 3.0], ["C", "e"]),
    "kc_classical_log": ("kappa", "kc-classical", "log", [], classical, classical_jac, [10], ["C"]),
    "kc_classical_linear": ("kappa_additive", "kc-classical", "linear", [], classical, classical_jac, [10], ["C"]),
    "tortuosity_linear": ("tau", "tortuosity", "linear", [], *_tau_fixed, [0.74, 0.124], ["C", "phi_c"]),
    "tortuosity_free_linear": ("tau", "tortuosity", "linear", ["--free", "e"], power, power_jac, [0.74, 0.124, -0.38], ["C", "phi_c", "e"]),
    "hydraulic_radius_linear": ("rh", "hydraulic-radius", "linear", [], hydraulic, hydraulic_jac, [1.0], ["C"]),
    "hydraulic_radius_log": ("rh", "hydraulic-radius", "log", [], hydraulic, hydraulic_jac, [1.0], ["C"]),
    "threshold_linear": ("threshold", "threshold", "linear", [], threshold, threshold_jac, [0.035, 3.67, 1.1], ["phi_c_star", "A", "beta"]),
    "sigmoid_linear": ("probability", "sigmoid", "linear", [], sigmoid, sigmoid_jac, [0.141, 0.01], ["phi_c", "width"]),
    "sigmoid_weighted_linear": ("probability_weighted", "sigmoid", "linear", ["--sigma", "s"], sigmoid, sigmoid_jac, [0.141, 0.01], ["phi_c", "width"]),
}


def scipy_fit(f, jac, x, y, p0, loss, sigma=None):
    from scipy.optimize import curve_fit
    kw = dict(p0=p0, ftol=1e-14, xtol=1e-14, gtol=1e-14, maxfev=100000, sigma=sigma)
    if loss == "log":
        popt, pcov = curve_fit(lambda x, *p: np.log(f(x, *p)), x, np.log(y),
                               jac=lambda x, *p: jac(x, *p) / f(x, *p)[:, None], **kw)
    else:
        popt, pcov = curve_fit(f, x, y, jac=jac, **kw)
    return popt, np.sqrt(np.diag(pcov))


def run(case, kcfit, work):
    global np
    import numpy
    np = numpy
    kind, model, loss, extra, f, jac, p0, names = CASES[case]
    x, y, *sigma = data(kind, 150, seed=sum(map(ord, case)))
    sigma = sigma[0] if sigma else None
    path = f"{work}/{case}.csv"
    with open(path, "w") as fh:
        fh.write("# case=" + case + ("\nx,y,s\n" if sigma is not None else "\nx,y\n"))
        for i, (a, b) in enumerate(zip(x, y)):
            fh.write(f"{a!r},{b!r}" + (f",{sigma[i]!r}\n" if sigma is not None else "\n"))
    out = subprocess.run([kcfit, path, "--model", model, "--x", "x", "--y", "y", "--loss", loss, "-q", *extra],
                         check=True, capture_output=True, text=True).stdout
    rows = {r["parameter"]: r for r in csv.DictReader(l for l in out.splitlines() if not l.startswith("#"))}
    popt, perr = scipy_fit(f, jac, x, y, p0, loss, sigma)
    bad = []
    for k, name in enumerate(names):
        v, e = float(rows[name]["value"]), float(rows[name]["stderr"])
        rv, re = abs(v - popt[k]) / abs(popt[k]), abs(e - perr[k]) / abs(perr[k])
        print(f"{case}: {name} kcfit {v:.12g} ± {e:.6g}, curve_fit {popt[k]:.12g} ± {perr[k]:.6g}; "
              f"relative differences {rv:.1e}, {re:.1e}")
        if not (rv <= RTOL and re <= RTOL):
            bad.append(name)
    if bad:
        sys.exit(f"{case}: kcfit and curve_fit differ by more than {RTOL} in {', '.join(bad)}")


if __name__ == "__main__":
    if sys.argv[1] == "--list":
        print("\n".join(CASES))
    else:
        run(*sys.argv[1:4])
