"""The campaign's results gathered into one table per stage, with their provenance checked.

Every finished target of a stage (compress/*/compress.csv, analyze/*.csv, perc/*/*/*.csv,
flow/*/*/*.csv) is one CSV written by one of the programs; its rows go into tables/<stage>.csv
behind the columns that its path carries (run, particles, seed, and phi_target for one packing),
so kcfit and the report read one file per stage. Files of one stage must share the program's
version (the campaign copies its tools once, study.mk) and their header; a target made under
other campaign parameters than the current ones (the timing log records the parameters' hash)
is named. Either mismatch stops the report (exit 2) unless allow_mixed is set.
"""
import csv
import glob
import hashlib
import os
import re


class Mismatch(Exception):
    pass


def read_csv(path):
    """(comment lines as {key: value}, header, rows as lists of strings) of one tool's CSV."""
    meta, header, rows = {}, None, []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("#"):
                key, _, value = line[1:].strip().partition("=")
                meta[key.strip()] = value
                continue
            if header is None:
                header = next(csv.reader([line]))
            elif line.strip():
                rows.append(next(csv.reader([line])))
    return meta, header, rows


def version_of(meta):
    """'percolate 0.1.0-b8a4cc3' from '# provenance=percolate 0.1.0-b8a4cc3: command line'."""
    return meta.get("provenance", "").split(":")[0].strip()


RUN = re.compile(r"N(\d+)_s(\d+)")


def run_columns(path, root):
    """run, particles, seed (and phi_target for one packing's row) from a target's path; a
    column the tool writes itself (percolate's particles) is not repeated."""
    rel = os.path.relpath(path, root)
    m = RUN.search(rel)
    cols = {"run": m.group(0), "particles": m.group(1), "seed": m.group(2)}
    stem = os.path.splitext(os.path.basename(path))[0]
    if re.fullmatch(r"[0-9.eE+-]+", stem):
        cols["phi_target"] = stem
    return cols


STAGES = {
    "compress": "compress/N*_s*/compress.csv",
    "structure": "analyze/N*_s*.csv",
    "percolate": "perc/N*_s*/d*/*.csv",
    "flow": "flow/N*_s*/M*/*.csv",
}
# the timing log's stage name of each table (timed.sh, study.mk)
LOG_STAGE = {"compress": "compress", "structure": "analyze", "percolate": "percolate", "flow": "flow"}


def params_hashes(root):
    """{stage: hash of its parameters file} as study.mk wrote them for this make."""
    out = {}
    for stage, name in LOG_STAGE.items():
        f = os.path.join(root, "params", {"analyze": "compress"}.get(name, name) + ".txt")
        out[stage] = hashlib.sha1(open(f, "rb").read()).hexdigest()[:12] if os.path.exists(f) else ""
    return out


def made_with(root):
    """{target path: parameters hash} from the timing logs, the last success of each target."""
    out = {}
    for f in glob.glob(os.path.join(root, "log", "*.csv")):
        for line in open(f):
            parts = line.strip().split(",")
            if len(parts) >= 4:
                out[os.path.normpath(parts[1])] = parts[3]
    return out


def gather(root, stage, allow_mixed=False, problems=None):
    """One stage's table: (header, rows, versions, files). Mismatches are raised (or, with
    allow_mixed, appended to problems)."""
    files = sorted(glob.glob(os.path.join(root, STAGES[stage])))
    header, rows, versions = None, [], {}
    hashes, made = params_hashes(root), made_with(root)
    issues = []
    for path in files:
        meta, h, body = read_csv(path)
        if h is None:
            continue
        versions.setdefault(version_of(meta), []).append(path)
        if header is None:
            header = h
        elif h != header:
            issues.append(f"{path}: its columns differ from those of {files[0]}")
            continue
        recorded = made.get(os.path.normpath(path))
        if recorded and hashes[stage] and recorded != hashes[stage]:
            issues.append(f"{path}: made with other campaign parameters than the current ones "
                          f"(params/{LOG_STAGE[stage]}.txt changed since; make study remakes it)")
        cols = {k: v for k, v in run_columns(path, root).items() if k not in h}
        if stage == "structure":
            cols.pop("phi_target", None)
        for r in body:
            rows.append(list(cols.values()) + r)
        lead = list(cols.keys())
    if len(versions) > 1:
        issues.append(f"{stage}: made by {len(versions)} versions of the program: " +
                      "; ".join(f"{v} ({len(p)} files, e.g. {p[0]})" for v, p in versions.items()))
    if issues:
        if not allow_mixed:
            raise Mismatch("\n".join(issues))
        if problems is not None:
            problems.extend(issues)
    if header is None:
        return None, [], versions, files
    return lead + header, rows, versions, files


def write_table(path, header, rows, comments):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        for c in comments:
            f.write(f"# {c}\n")
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(rows)
    os.replace(tmp, path)


def as_records(header, rows):
    return [dict(zip(header, r)) for r in rows] if header else []
