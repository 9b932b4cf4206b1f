#!/usr/bin/python3
"""study_report.py --dir D --study NAME --bin BIN --params K=V ...: the campaign's report.

Gathers every finished target into D/tables/<stage>.csv (study_tables.py: provenance
checked), fits them with kcfit into D/fits/ (study_fits.py), draws the thesis's figures into
D/figures/*.png and writes D/report.html: the figures, Table S5.1 and the other numbers beside
the thesis's, the campaign's parameters, the tools' versions and the wall time of every stage.
Whatever has not finished yet is said to be missing; the page never needs the network.
"""
import argparse
import glob
import html
import math
import os
import subprocess
import sys
from collections import defaultdict

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study_tables as st  # noqa: E402
from study_fits import fmt, run_kcfit  # noqa: E402
import thesis_values as tv  # noqa: E402

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

plt.rcParams.update({"figure.dpi": 110, "font.size": 10, "axes.grid": True, "grid.alpha": 0.3,
                     "legend.fontsize": 8, "legend.frameon": False})


def num(r, k):
    try:
        return float(r[k])
    except (KeyError, ValueError):
        return float("nan")


def mean_err(values):
    v = np.array([x for x in values if x == x])
    if len(v) == 0:
        return float("nan"), float("nan"), 0
    return v.mean(), (v.std(ddof=1) / math.sqrt(len(v)) if len(v) > 1 else float("nan")), len(v)


def fit_text(f):
    """A fit's parameters but the prefactor C ('phi_c = 0.146 ± 0.003, gamma = ...'); C alone when
    it is the only one fitted."""
    shown = {k: v for k, v in f.params.items() if k != "C"} or f.params
    return ", ".join(f"{k} = {fmt(*v)}" for k, v in shown.items())


class Report:
    def __init__(self, args):
        self.a = args
        self.d = args.dir
        self.kcfit = os.path.join(args.bin, "kcfit")
        self.sections = []
        self.problems = []
        self.comparisons = []   # (quantity, thesis, ours, reason)
        for sub in ("tables", "fits", "figures"):
            os.makedirs(os.path.join(self.d, sub), exist_ok=True)

    # ---- tables -------------------------------------------------------------------------
    def gather(self):
        self.tables, self.versions = {}, {}
        for stage in st.STAGES:
            header, rows, versions, files = st.gather(self.d, stage, self.a.allow_mixed, self.problems)
            self.versions[stage] = versions
            path = os.path.join(self.d, "tables", stage + ".csv")
            if header:
                st.write_table(path, header, rows, [f"study={self.a.study}", f"files={len(files)}"] +
                               [f"version={v}" for v in versions])
            elif os.path.exists(path):
                os.remove(path)
            self.tables[stage] = st.as_records(header, rows)

    def table(self, stage):
        return os.path.join(self.d, "tables", stage + ".csv")

    def fit(self, label, stage, args, name):
        if not self.tables.get(stage):
            return None
        return run_kcfit(self.kcfit, label, [self.table(stage)] + args, os.path.join(self.d, "fits", name + ".csv"))

    # ---- figures ------------------------------------------------------------------------
    def save(self, fig, name, caption):
        path = os.path.join(self.d, "figures", name + ".png")
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
        self.sections.append(("figure", name, caption))

    def note(self, title, text):
        self.sections.append(("note", title, text))

    # ---- Chapter 4 ----------------------------------------------------------------------
    def chapter4(self):
        rows = self.tables.get("structure")
        comp = self.tables.get("compress")
        if not rows:
            self.note("Chapter 4", "No shell packing has been analysed yet (analyze/ is empty).")
            return
        phi_j = {}
        for f in glob.glob(os.path.join(self.d, "compress", "N*_s*", "compress.csv")):
            meta = st.read_csv(f)[0]
            phi_j[os.path.basename(os.path.dirname(f))] = float(meta.get("phi_J", "nan"))
        groups = defaultdict(lambda: defaultdict(list))
        for r in rows:
            target = os.path.basename(r["file"])[len("pack_"):-len(".off")]
            key = (int(r["particles"]), float(target))
            dphi = num(r, "phi") - phi_j.get(r["run"], float("nan"))
            for col in ("Z", "dZ", "delta_eps_mean", "turgor_mean_P0", "dphi"):
                groups[key][col].append(dphi if col == "dphi" else num(r, col))
        ns = sorted({k[0] for k in groups})
        fig, axes = plt.subplots(2, 2, figsize=(9, 7))
        panels = [("dZ", "ΔZ = Z − (6 − 4/N)", True), ("delta_eps_mean", "δε (reduced aspect ratio)", True),
                  ("turgor_mean_P0", "⟨Π⟩/Π₀", False), ("Z", "Z", False)]
        for ax, (col, label, loglog) in zip(axes.flat, panels):
            for n in ns:
                keys = sorted(k for k in groups if k[0] == n)
                x = [mean_err(groups[k]["dphi"])[0] for k in keys] if loglog else [k[1] for k in keys]
                m = [mean_err(groups[k][col]) for k in keys]
                ax.errorbar(x, [v[0] for v in m], yerr=[0 if v[1] != v[1] else v[1] for v in m], marker="o", ms=3,
                            capsize=2, label=f"N = {n} ({max(v[2] for v in m)} packings)")
            ax.set_xlabel("δφ = φ − φ_J" if loglog else "φ (volume fraction)")
            ax.set_ylabel(label)
            if loglog:
                ax.set_xscale("log")
                ax.set_yscale("log")
            ax.legend()
        self.save(fig, "ch4_structure", "Chapter 4 (Figs 4.3-4.6, S4.1): ΔZ and δε against δφ, ⟨Π⟩/Π₀ and Z "
                  "against φ, mean ± standard error over the seeds of each N.")
        # ΔZ ~ δφ^β near jamming, from every box step of the compressions of the largest N
        n = ns[-1]
        steps = [r for r in comp or [] if int(r["particles"]) == n]
        x = np.array([num(r, "dphi") for r in steps])
        y = np.array([num(r, "dZ") for r in steps])
        ok = (x > 0) & (x < 0.15) & (y > 0) & np.isfinite(x) & np.isfinite(y)
        if ok.sum() > 3:
            (beta, c), cov = np.polyfit(np.log(x[ok]), np.log(y[ok]), 1, cov=True)
            self.comparisons.append(("ΔZ ∼ δφ^β for δφ < 0.15, β (Fig. 4.3b)", tv.BETA_DZ,
                                     f"{fmt(beta, math.sqrt(cov[0][0]))} (N = {n}, {ok.sum()} box steps)",
                                     "least squares of ln ΔZ on ln δφ over every box step with δφ < 0.15 of "
                                     "every compression (compress.csv); the thesis fitted averages"))
        top = max(k for k in groups if k[0] == n)
        t = mean_err(groups[top]["turgor_mean_P0"])
        low = min(k for k in groups if k[0] == n)
        t0 = mean_err(groups[low]["turgor_mean_P0"])
        self.comparisons.append((f"⟨Π⟩/Π₀ from φ = {low[1]:g} to {top[1]:g} (N = {n})", tv.TURGOR_RATIO,
                                 f"{fmt(t0[0], t0[1])} → {fmt(t[0], t[1])}", "the same trend"))

    # ---- Chapter 5: percolation ---------------------------------------------------------
    def percolation(self):
        rows = self.tables.get("percolate")
        if not rows:
            self.note("Percolation", "No percolate row yet (perc/ is empty).")
            return
        deltas = sorted({float(r["delta"]) for r in rows})
        ns = sorted({int(r["particles"]) for r in rows})
        self.sig = {}
        for n in ns:
            for d in deltas:
                f = self.fit(f"sigmoid N={n} δ={d:g}", "percolate",
                             ["--model", "sigmoid", "--where", f"particles={n}", "--where", f"delta={d:g}"],
                             f"sigmoid_N{n}_d{d:g}")
                self.sig[(n, d)] = f
        fd = float(self.a.flow_delta)
        fig, axes = plt.subplots(1, 2, figsize=(10, 4))
        for ax, pick, title in ((axes[0], [(n, fd) for n in ns], f"δ = {fd:g} D₀, each N (Fig. 5.2B)"),
                                (axes[1], [(ns[-1], d) for d in deltas], f"N = {ns[-1]}, each δ (Fig. 5.2C)")):
            for key in pick:
                # binned by the packings' target phi (every seed's packing at one phi is one bin)
                pts = [(1 - float(r["phi_target"]), num(r, "percolates")) for r in rows
                       if int(r["particles"]) == key[0] and abs(float(r["delta"]) - key[1]) < 1e-9]
                if not pts:
                    continue
                bins = np.array(sorted({p[0] for p in pts}))
                prob = [np.mean([p[1] for p in pts if p[0] == b]) for b in bins]
                label = f"N = {key[0]}" if ax is axes[0] else f"δ = {key[1]:g}"
                line = ax.plot(bins, prob, "o", ms=4, label=label)[0]
                f = self.sig.get(key)
                if f and f.ok:
                    pc, w = f.value("phi_c")[0], f.value("width")[0]
                    xs = np.linspace(bins.min(), bins.max(), 200)
                    ax.plot(xs, 1 / (1 + np.exp(-(xs - pc) / w)), color=line.get_color(), lw=1)
            ax.set_xlabel("porosity φ")
            ax.set_ylabel("percolation probability")
            ax.set_title(title)
            ax.legend()
        self.save(fig, "fig5_2bc", "Percolation probability against porosity (points: fraction of the packings "
                  "whose pore cluster spans x; lines: maximum-likelihood sigmoids fitted to the 0/1 outcomes).")
        # phi_c(delta) and the continuum extrapolation, per N
        import csv as _csv
        thr_rows = []
        for (n, d), f in sorted(self.sig.items()):
            if f.ok:
                pc = f.value("phi_c")
                thr_rows.append([n, d, pc[0], pc[1]])
        path = os.path.join(self.d, "fits", "phi_c.csv")
        with open(path, "w", newline="") as fh:
            w = _csv.writer(fh, lineterminator="\n")
            w.writerow(["particles", "delta", "phi_c", "phi_c_error"])
            w.writerows(thr_rows)
        fig, ax = plt.subplots(figsize=(5.5, 4))
        self.threshold = {}
        for n in ns:
            pts = [r for r in thr_rows if r[0] == n]
            if not pts:
                continue
            line = ax.errorbar([p[1] for p in pts], [p[2] for p in pts], yerr=[p[3] for p in pts], fmt="o", ms=4,
                               capsize=2, label=f"N = {n}")
            f = run_kcfit(self.kcfit, f"threshold N={n}", [path, "--model", "threshold", "--where", f"particles={n}"],
                          os.path.join(self.d, "fits", f"threshold_N{n}.csv")) if len(pts) >= 4 else None
            self.threshold[n] = f
            if f and f.ok:
                xs = np.linspace(0, max(p[1] for p in pts) * 1.05, 100)
                a, b, s = f.value("A")[0], f.value("beta")[0], f.value("phi_c_star")[0]
                ax.plot(xs, s + a * xs ** b, color=line[0].get_color(), lw=1)
        ax.set_xlabel("voxel side δ [D₀]")
        ax.set_ylabel("percolation threshold φ_c (porosity)")
        ax.set_xlim(left=0)
        ax.legend()
        self.save(fig, "fig5_2d", "φ_c(δ) from the sigmoid fits (± their standard errors) and "
                  "φ_c(δ) = φ_c* + A δ^β extrapolated to the continuum, δ → 0 (Fig. 5.2D).")
        for n in ns:
            d04 = self.sig.get((n, 0.04))
            if d04 is not None:
                self.comparisons.append((f"φ_c(δ = 0.04), N = {n}", tv.PHI_C_D04.get(n, "–"),
                                         fmt(*d04.value("phi_c")) if d04.ok else f"no fit: {d04.error}",
                                         tv.REASON_PHI_C))
            f = self.threshold.get(n)
            if f is not None:
                ours = (f"φ_c* = {fmt(*f.value('phi_c_star'))}, A = {fmt(*f.value('A'))}, β = {fmt(*f.value('beta'))}"
                        if f.ok else f"no fit: {f.error}")
                self.comparisons.append((f"Table S5.1, Fig. 5.2D, N = {n}", tv.THRESHOLD.get(n, "–"), ours,
                                         tv.REASON_THRESHOLD))

    def hydraulic_radius(self):
        rows = [r for r in self.tables.get("percolate") or [] if r["percolates"] == "1"
                and abs(float(r["delta"]) - float(self.a.flow_delta)) < 1e-9]
        if not rows:
            return
        f = self.fit("R_h", "percolate", ["--model", "hydraulic-radius", "--where", "percolates=1",
                                          "--where", f"delta={self.a.flow_delta}"], "hydraulic_radius")
        fig, ax = plt.subplots(figsize=(5.5, 4))
        for n in sorted({int(r["particles"]) for r in rows}):
            pts = [(num(r, "porosity"), num(r, "rh_sites_d0")) for r in rows if int(r["particles"]) == n]
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=3, label=f"N = {n}")
        if f and f.ok:
            xs = np.linspace(0.01, max(num(r, "porosity") for r in rows) * 1.05, 100)
            ax.plot(xs, f.value("C")[0] * xs / (1 - xs), "k-", lw=1, label=f"C φ/(1−φ), C = {fmt(*f.value('C'))}")
        ax.set_xlabel("porosity φ")
        ax.set_ylabel("hydraulic radius R_h [D₀]")
        ax.legend()
        self.save(fig, "fig5_3", f"Hydraulic radius of the percolating cluster (cluster sites over surface sites, "
                  f"δ = {self.a.flow_delta} D₀) against porosity, with Eq. 5.6 fitted (Fig. 5.3).")

    # ---- Chapter 5: flow ----------------------------------------------------------------
    def flow(self):
        rows = self.tables.get("flow")
        if not rows:
            self.note("Flow", "No lbflow row yet (flow/ is empty).")
            return
        ms = sorted({int(r["refine"]) for r in rows})
        n = max(int(r["particles"]) for r in rows)
        m_fit = ms[-1]
        where = ["--where", f"particles={n}", "--where", f"refine={m_fit}"]
        tau = {m: self.fit(f"tortuosity M={m}", "flow", ["--model", "tortuosity", "--where", f"particles={n}",
                                                         "--where", f"refine={m}"], f"tortuosity_M{m}") for m in ms}
        fig, ax = plt.subplots(figsize=(5.5, 4))
        for m in ms:
            pts = sorted((num(r, "porosity"), num(r, "tortuosity")) for r in rows
                         if int(r["refine"]) == m and int(r["particles"]) == n)
            line = ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=3, label=f"M = {m}")[0]
            f = tau[m]
            if f and f.ok:
                pc, c = f.value("phi_c")[0], f.value("C")[0]
                xs = np.linspace(max(pc + 1e-3, min(p[0] for p in pts) - 0.03), max(p[0] for p in pts), 200)
                ax.plot(xs, c * (xs - pc) ** -0.38, color=line.get_color(), lw=1)
        taus = [num(r, "tortuosity") for r in rows if int(r["particles"]) == n]
        top = max(3.0, 1.3 * max(taus))
        xs = np.linspace(0.205, 0.5, 200)
        ya = tv.ahmadi(xs)
        ax.plot(xs[ya < top], ya[ya < top], "k--", lw=1, label="Ahmadi et al., B = 1.16")
        ax.set_ylim(1, top)
        ax.set_xlabel("porosity φ")
        ax.set_ylabel("hydraulic tortuosity τ_H")
        ax.legend()
        self.save(fig, "fig5_4", f"Tortuosity of the flow through the percolating cluster (N = {n}, "
                  f"δ = {self.a.flow_delta} D₀) for each refinement M, with τ_H = C_τ(φ − φ_c)^−0.38 fitted "
                  "(lines) and the Ahmadi curve (Fig. 5.4).")
        free = self.fit(f"tortuosity, free exponent, M={m_fit}", "flow", ["--model", "tortuosity", "--free", "e"] + where,
                        f"tortuosity_free_M{m_fit}")
        if free is not None:
            self.comparisons.append((f"τ_H ∼ (φ − φ_c)^e, e free (M = {m_fit})", "−0.38 (Eq. 5.7, ν(1−D))",
                                     (f"e = {fmt(*free.value('e'))}, φ_c = {fmt(*free.value('phi_c'))}" if free.ok
                                      else f"no fit: {free.error}"), tv.REASON_TAU))
        t = tau[m_fit]
        if t is not None:
            self.comparisons.append((f"Table S5.1, Fig. 5.4B: φ_c of the tortuosity law (M = {m_fit})",
                                     "0.124 ± 0.004", fmt(*t.value("phi_c")) if t.ok else f"no fit: {t.error}",
                                     tv.REASON_TAU))
        # permeability: every model of Table S5.1
        models = []
        for loss, figname in (("log", "5.5 / S5.5 A (log)"), ("linear", "S5.5 B (linear)")):
            for model in ("kc-percolation", "kc-fixed", "power"):
                models.append((figname, model, loss, []))
        for loss, figname in (("log", "S5.5 C (log, φ_c fixed)"), ("linear", "S5.5 D (linear, φ_c fixed)")):
            for model in ("kc-percolation", "kc-fixed", "power"):
                models.append((figname, model, loss, ["--fix", "phi_c=0.141"]))
        models.append(("classical KC (log)", "kc-classical", "log", []))
        fits = []
        for figname, model, loss, extra in models:
            f = self.fit(f"{model} {loss}", "flow", ["--model", model, "--loss", loss, "--y", "permeability_d02"] +
                         where + extra, f"kappa_{model}_{loss}{'_fixed' if extra else ''}")
            fits.append((figname, model, loss, extra, f))
        self.kappa_fits = fits
        fig, ax = plt.subplots(figsize=(6, 4.5))
        pts = sorted((num(r, "porosity"), num(r, "permeability_d02")) for r in rows
                     if int(r["refine"]) == m_fit and int(r["particles"]) == n)
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", ms=3, color="k", label=f"lbflow, N = {n}, M = {m_fit}")
        xs_all = np.linspace(min(p[0] for p in pts), max(p[0] for p in pts), 200)
        for figname, model, loss, extra, f in fits:
            if not (f and f.ok) or loss != "log" or extra:
                continue
            c = f.value("C")[0]
            pc = f.value("phi_c")[0] if "phi_c" in f.params else 0
            xs = xs_all[xs_all > pc]
            if model == "kc-percolation":
                y = c * (xs - pc) ** (f.value("gamma")[0] + 0.76) * xs ** 2 / (1 - xs) ** 2
            elif model == "kc-fixed":
                y = c * (xs - pc) ** 2.52 * xs ** 2 / (1 - xs) ** 2
            elif model == "power":
                y = c * (xs - pc) ** f.value("e")[0]
            else:
                y = c * xs ** 3 / (1 - xs) ** 2
            ax.plot(xs, y, lw=1, label=tv.MODEL_LABEL[model])
        ax.set_yscale("log")
        ax.set_xlabel("porosity φ")
        ax.set_ylabel("permeability κ [D₀²]")
        ax.legend()
        self.save(fig, "fig5_5", "Permeability against porosity with every model of Table S5.1 fitted by the log "
                  "error (Fig. 5.5); the linear-error and fixed-φ_c fits are in the table below.")
        # refinement: kappa and tau against M
        if len(ms) > 1:
            fig, axes = plt.subplots(1, 2, figsize=(9, 3.8))
            for m in ms:
                pts = sorted((num(r, "porosity"), num(r, "permeability_d02"), num(r, "tortuosity")) for r in rows
                             if int(r["refine"]) == m and int(r["particles"]) == n)
                axes[0].plot([p[0] for p in pts], [p[1] for p in pts], "o-", ms=3, lw=0.6, label=f"M = {m}")
                axes[1].plot([p[0] for p in pts], [p[2] for p in pts], "o-", ms=3, lw=0.6, label=f"M = {m}")
            axes[0].set_yscale("log")
            for ax, lab in zip(axes, ("permeability κ [D₀²]", "tortuosity τ_H")):
                ax.set_xlabel("porosity φ")
                ax.set_ylabel(lab)
                ax.legend()
            self.save(fig, "fig_s5_4", "The same clusters at refinements M = 1, 2, 3 (Figs 5.4A, S5.4): κ in D₀² "
                      "converges with M, and M = 1 fails in the narrow throats near φ_c.")

    # ---- the rendered packing ------------------------------------------------------------
    def picture(self):
        script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "render_packing.py")
        flows = self.tables.get("flow") or []
        if not flows:
            return
        r = sorted(flows, key=lambda r: (-int(r["particles"]), num(r, "porosity")))[len(flows) // 2]
        packing = os.path.join(self.d, "compress", r["run"], f"pack_{r['phi_target']}.off")
        cluster = os.path.join(self.d, "perc", r["run"], f"d{self.a.flow_delta}", f"{r['phi_target']}.vtk")
        out = os.path.join(self.d, "figures", "fig5_2a.png")
        field = os.path.join(self.d, "fig5_2a_flow.vtk")  # lbflow's field, for ParaView too
        lb = subprocess.run([os.path.join(self.a.bin, "lbflow"), cluster, "--refine", "1", "--vtk", field, "-o", os.devnull,
                             "-q"], capture_output=True, text=True)
        cmd = [sys.executable, script, packing, cluster, out] + ([field] if lb.returncode == 0 else [])
        if not os.environ.get("DISPLAY"):
            cmd = ["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24"] + cmd
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode == 0 and os.path.exists(out):
            self.sections.append(("figure", "fig5_2a", f"One compressed packing ({r['run']}, φ = {r['phi_target']}, "
                                  f"porosity {num(r, 'porosity'):.3f}): the shells and the percolating pore "
                                  f"cluster at δ = {self.a.flow_delta} D₀ with streamlines of the flow through it, coloured by "
                                  f"speed (lbflow, M = 1; Fig. 5.2A)."))
        else:
            self.note("Fig. 5.2A", "The rendering failed: " + html.escape((p.stderr or p.stdout).strip()[-300:]))

    # ---- cost ---------------------------------------------------------------------------
    def cost(self):
        times = defaultdict(list)
        for stage in ("mesh", "jam", "compress", "analyze", "percolate", "flow"):
            f = os.path.join(self.d, "log", stage + ".csv")
            last = {}
            if os.path.exists(f):
                for line in open(f):
                    p = line.strip().split(",")
                    if len(p) >= 3:
                        last[p[1]] = float(p[2])
            times[stage] = list(last.values())
        self.times = times

    # ---- the page -----------------------------------------------------------------------
    def write(self):
        e = html.escape
        out = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>The study: flow through squeezed shells</title>",
               "<style>body{font-family:sans-serif;max-width:1000px;margin:2em auto;line-height:1.4}"
               "table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #bbb;padding:3px 8px;"
               "font-size:90%;text-align:left}img{max-width:100%}code{background:#f3f3f3}</style></head><body>",
               f"<h1>The thesis's study, STUDY={e(self.a.study)}</h1>",
               "<p>How flow through a packing of elastic shells falls as it is squeezed (thesis Chapters 4 and 5), "
               "computed with this toolkit's own shells: jammed packings (shellpack jam) become pressurised shells "
               "squeezed towards confluence (shellpack compress), their pore space is voxelised (percolate) and the "
               "Stokes flow through the percolating cluster solved (lbflow), then fitted (kcfit).</p>"]
        if self.problems:
            out.append("<h2>Mixed campaign</h2><p>These files were accepted with ALLOW_MIXED=1:</p><ul>" +
                       "".join(f"<li>{e(p)}</li>" for p in self.problems) + "</ul>")
        out.append("<h2>Beside the thesis</h2><table><tr><th>quantity</th><th>thesis</th><th>ours</th>"
                   "<th>why they differ</th></tr>")
        for q, t, o, why in self.comparisons:
            out.append(f"<tr><td>{e(q)}</td><td>{e(str(t))}</td><td>{e(str(o))}</td><td>{e(why)}</td></tr>")
        out.append("</table>")
        if getattr(self, "kappa_fits", None):
            out.append("<h2>Table S5.1: permeability models</h2><table><tr><th>figure</th><th>model</th>"
                       "<th>thesis</th><th>ours</th><th>R² (loss space)</th></tr>")
            for figname, model, loss, extra, f in self.kappa_fits:
                thesis = tv.TABLE_S51.get((figname, model), "–")
                if f is None:
                    continue
                if f.ok:
                    ours = fit_text(f)
                    r2 = f.meta.get("r2", "")
                else:
                    ours, r2 = "no fit: " + f.error, ""
                out.append(f"<tr><td>{e(figname)}</td><td>{e(tv.MODEL_LABEL[model])}</td><td>{e(thesis)}</td>"
                           f"<td>{e(ours)}</td><td>{e(r2[:6])}</td></tr>")
            out.append("</table><p>" + e(tv.REASON_KAPPA) + "</p>")
        for kind, name, text in self.sections:
            if kind == "figure":
                out.append(f"<figure><img src='figures/{name}.png' alt='{e(name)}'><figcaption>{e(text)}</figcaption></figure>")
            else:
                out.append(f"<h3>{e(name)}</h3><p>{e(text)}</p>")
        out.append("<h2>Cost</h2><table><tr><th>stage</th><th>tasks done</th><th>total [s]</th>"
                   "<th>mean per task [s]</th><th>longest [s]</th></tr>")
        for stage, ts in self.times.items():
            if ts:
                out.append(f"<tr><td>{stage}</td><td>{len(ts)}</td><td>{sum(ts):.0f}</td>"
                           f"<td>{sum(ts) / len(ts):.1f}</td><td>{max(ts):.1f}</td></tr>")
        out.append("</table>")
        total = sum(sum(ts) for ts in self.times.values())
        longest = max((max(ts) for ts in self.times.values() if ts), default=0)
        out.append(f"<p>Wall time of every task added up: {total / 3600:.2f} h on this machine's 2 cores "
                   f"(tasks run one after another with their threads). On k cluster nodes, each running one task at a "
                   f"time, the campaign takes about max(total/k, longest task) per stage: " +
                   ", ".join(f"k = {k}: {max(total / k, longest) / 3600:.2f} h" for k in (4, 16, 64)) + ".</p>")
        out.append("<h2>Campaign</h2><table>" + "".join(
            f"<tr><td>{e(p.split('=', 1)[0])}</td><td><code>{e(p.split('=', 1)[1])}</code></td></tr>"
            for p in self.a.params) + "</table><p>Tools:</p><ul>" +
            "".join(f"<li>{e(v)}</li>" for vs in self.versions.values() for v in vs) + "</ul>")
        out.append("<p>Tables: <code>tables/</code> (one per stage), fits: <code>fits/</code> (kcfit's CSVs).</p>")
        out.append("</body></html>")
        path = os.path.join(self.d, "report.html")
        with open(path + ".tmp", "w") as f:
            f.write("\n".join(out))
        os.replace(path + ".tmp", path)
        self.write_summary()
        return path

    def write_summary(self):
        """summary.md: the numbers beside the thesis's as a Markdown table (for the docs)."""
        lines = [f"Numbers of the study's `STUDY={self.a.study}` campaign beside the thesis's "
                 "(generated by `make study-report` with the report; do not edit).", "",
                 "| quantity | thesis | ours | why they differ |", "|---|---|---|---|"]
        for q, t, o, why in self.comparisons:
            lines.append(f"| {q} | {t} | {o} | {why} |")
        for figname, model, loss, extra, f in getattr(self, "kappa_fits", []):
            if f is None:
                continue
            ours = (fit_text(f) + f", R² (loss space) = {float(f.meta.get('r2', 'nan')):.3f}" if f.ok
                    else "no fit: " + f.error)
            lines.append(f"| Table S5.1, {figname}, {tv.MODEL_LABEL[model]} | "
                         f"{tv.TABLE_S51.get((figname, model), '–')} | {ours} | {tv.REASON_KAPPA_SHORT} |")
        with open(os.path.join(self.d, "summary.md"), "w") as f:
            f.write("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--dir", required=True)
    ap.add_argument("--study", default="default")
    ap.add_argument("--bin", required=True)
    ap.add_argument("--flow-delta", dest="flow_delta", default=None)
    ap.add_argument("--allow-mixed", action="store_true")
    ap.add_argument("--params", nargs="*", default=[])
    a = ap.parse_args()
    params = dict(p.split("=", 1) for p in a.params)
    if a.flow_delta is None:
        a.flow_delta = params.get("FLOW_DELTA", "0.04")
    a.allow_mixed = a.allow_mixed or os.environ.get("ALLOW_MIXED") == "1"
    r = Report(a)
    try:
        r.gather()
    except st.Mismatch as m:
        print("study: the campaign mixes results that do not belong together:", file=sys.stderr)
        print("\n".join("study: " + l for l in str(m).splitlines()), file=sys.stderr)
        print("study: remove those files (make study remakes them) or rerun with ALLOW_MIXED=1", file=sys.stderr)
        sys.exit(2)
    r.chapter4()
    r.percolation()
    r.hydraulic_radius()
    r.flow()
    r.picture()
    r.cost()
    print(f"study: report {r.write()}", file=sys.stderr)


if __name__ == "__main__":
    main()
