"""The study's fits, each one kcfit call on the campaign's tables (thesis Table S5.1, Fig. 5.2-5.5).

A fit that cannot be made (too few points, every packing percolating or none, a perfectly
separated group) is recorded with kcfit's own message instead of its parameters, so the
report says why a number is missing rather than dropping it.
"""
import csv
import math
import io
import subprocess


class Fit:
    """One kcfit result: parameters {name: (value, error)}, the comment lines, or the failure."""

    def __init__(self, label, argv):
        self.label, self.argv = label, argv
        self.params, self.meta, self.error, self.rows = {}, {}, None, []

    def value(self, name):
        return self.params.get(name, (float("nan"), float("nan")))

    @property
    def ok(self):
        return self.error is None


def run_kcfit(kcfit, label, args, out_path=None):
    """kcfit ARGS -q -o OUT: a Fit, parsed from kcfit's CSV (one fit or grouped rows)."""
    argv = [kcfit] + args + ["-q", "-o", out_path or "-"]
    fit = Fit(label, argv)
    p = subprocess.run(argv, capture_output=True, text=True)
    if p.returncode != 0:
        fit.error = (p.stderr.strip().splitlines() or ["kcfit failed"])[-1].replace("kcfit: ", "")
        return fit
    text = open(out_path).read() if out_path else p.stdout
    lines = [l for l in text.splitlines() if l.strip()]
    for l in lines:
        if l.startswith("#"):
            k, _, v = l[1:].strip().partition("=")
            fit.meta[k.strip()] = v
    body = [l for l in lines if not l.startswith("#")]
    rows = list(csv.DictReader(io.StringIO("\n".join(body))))
    fit.rows = rows
    if rows and "parameter" in rows[0]:
        for r in rows:
            fit.params[r["parameter"]] = (float(r["value"]), float(r["stderr"]))
    return fit


def fmt(value, error=None, digits=3):
    """'0.146 ± 0.003' (the error to 1-2 significant digits, the value to match)."""
    if value != value:
        return "–"
    if error is None or error != error or error == 0:
        return f"{value:.{digits}g}"
    if math.isinf(error):
        return f"{value:.{digits}g} ± ∞"
    decimals = max(0, -int(math.floor(math.log10(abs(error)))) + (1 if abs(error) / 10 ** math.floor(math.log10(abs(error))) < 2 else 0))
    return f"{value:.{decimals}f} ± {error:.{decimals}f}"
