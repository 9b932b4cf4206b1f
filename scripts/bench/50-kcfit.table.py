"""Rows of the README benchmark table for kcfit."""


def _kcfit(r):
    stage, threads = r["stage"], r["threads"]
    what = {
        "fit_multistart": "kcfit: one fit of Eq. 5.8 (log loss), all 12 starting points",
        "fit_one_start": "kcfit: one fit of Eq. 5.8 (log loss), one starting point",
        "bootstrap_1000": f"kcfit --bootstrap 1000, Eq. 5.8, {threads} thread(s)",
        "scipy_curve_fit": "scipy curve_fit, same fit, one starting point (numerical Jacobian)",
        "scipy_curve_fit_analytic_jac": "scipy curve_fit, same fit, one starting point (analytic Jacobian)",
    }.get(stage, stage)
    if stage == "bootstrap_1000":
        figure = f"{float(r['seconds']):.2f} s ({float(r['fits_per_s']):,.0f} fits/s)"
    else:
        figure = f"{float(r['fits_per_s']):,.0f} fits/s ({1e3 * float(r['seconds']) / float(r['fits']):.2f} ms each)"
    ref = "thousands of bootstrap fits in seconds" if stage.startswith(("fit", "bootstrap")) else "(reference)"
    return (what, f"{r['points']} points", figure, ref)


SECTIONS = {"kcfit.csv": _kcfit}
