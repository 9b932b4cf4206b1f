#!/usr/bin/env python3
"""Prints one line per file, "name sha256", of its content with the run-dependent parts taken out,
for tests/tools/golden_outputs.sh: what a seeded command computes must not change when the code
is reorganised, but the version in provenance lines, timings and thread counts may.

Taken out: the program's version (x.y.z-<commit>[-dirty]); comment or header lines naming
a time, date, host or thread count; CSV columns of wall time (seconds, *_seconds, *_s);
key=value fields of those names inside an extended-XYZ comment line; the checkout's path
(--src, in commands that name its data files); a legacy VTK file's title line (the provenance,
cut at 256 characters, so where it is cut moves with the lengths of the version and the path).
Usage: golden_hash.py [--src DIR] FILE..."""
import hashlib
import re
import sys

VERSION = re.compile(rb"\b\d+\.\d+\.\d+-[0-9a-f]{4,40}(-dirty)?\b")
TIMED_KEYS = rb"(seconds|wall_seconds|elapsed|elapsed_s|time_s|date|host|machine|threads|thread_count)"
TIMED_LINE = re.compile(rb"^#\s*" + TIMED_KEYS + rb"\s*[=:]")
TIMED_FIELD = re.compile(rb"\b" + TIMED_KEYS + rb"=(\"[^\"]*\"|\S+)")
TIMED_COLUMN = re.compile(r"^(seconds|wall_seconds|elapsed_s|time_s|.*_seconds)$")


def normalise(data: bytes) -> bytes:
    out = []
    lines = data.split(b"\n")
    drop = None  # indices of CSV columns to drop, once the header is seen
    for line in lines:
        line = VERSION.sub(b"VERSION", line)
        if line.startswith(b"#"):
            if TIMED_LINE.match(line):
                continue
            out.append(TIMED_FIELD.sub(b"", line))
            continue
        if drop is None and b"," in line and not line[:1].isdigit() and line[:1] not in b"-+.":
            names = line.decode("utf-8", "replace").split(",")
            drop = {i for i, n in enumerate(names) if TIMED_COLUMN.match(n.strip())}
        if drop:
            cells = line.split(b",")
            line = b",".join(c for i, c in enumerate(cells) if i not in drop)
        out.append(TIMED_FIELD.sub(b"", line))
    return b"\n".join(out)


def main() -> None:
    args = sys.argv[1:]
    src = None
    if args[:1] == ["--src"]:
        src, args = args[1].rstrip("/").encode(), args[2:]
    for path in args:
        with open(path, "rb") as f:
            data = f.read()
        if src:
            data = data.replace(src, b"SRC")
        if data.startswith(b"# vtk DataFile"):
            head, title, rest = data.split(b"\n", 2)
            data = head + b"\n" + rest
        binary = b"\0" in data[:4096]
        digest = hashlib.sha256(VERSION.sub(b"VERSION", data) if binary else normalise(data)).hexdigest()[:16]
        print(path, digest)


if __name__ == "__main__":
    main()
