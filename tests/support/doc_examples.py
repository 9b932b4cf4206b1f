#!/usr/bin/env python3
"""Runs the command examples of one documentation page (README.md or docs/*.md) as a user
would: every example block, in the page's order, each command in turn, in one scratch folder.

    doc_examples.py PAGE --bin BIN --src SRC [--size small|full] [--list] [--keep DIR]

An example block is an indented or fenced code block whose first command is one of the
toolkit's programs, make, gnuplot, salloc or a script of scripts/; other blocks (file samples,
the source layout) are text. In a block, a line ending in '\\', '|' or '&&' continues on the
next; a transcript block ('$ command' then its output) also checks the output, line for line.
A command must exit 0 unless its comment announces another status ("exit 1", "exits 2").

EXAMPLES=small (make test's default) runs long examples at a reduced size by the rewrites of
SMALL_REWRITES below (docs/conventions.md lists them); EXAMPLES=full runs them as written.
make examples run on the checkout's Makefile (make -C) with BUILD set to the tests' build; `make test` itself runs
as `make -n test` (it is the command that runs this). Exit 0 when every command behaved as
announced, 1 otherwise (with each failure's command, status and the end of its stderr).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

PROGRAMS = ("rndmesh", "jam2d", "shellpack", "percolate", "lbflow", "kcfit")
COMMAND_WORDS = PROGRAMS + ("make", "gnuplot", "salloc", "parallel")
# make targets that the small size runs as `make -n` (their recipes are whole pipelines that
# other tests run piece by piece); the study's targets run for real, at STUDY=tiny.
DRY_MAKE_SMALL = ("run", "test", "jamming-figure", "shell-figures", "compress-figures",
                  "flow-figure", "percolation-figure", "jam2d-figures", "chamber-figures", "bench", "tables")
STUDY_SIZE_VARIABLES = ("STUDY", "N", "SEEDS", "VERTICES", "PHI", "DELTA", "FLOW_DELTA",
                        "REFINE", "FLOW_N", "FLOW_SEEDS")


def _shrink_seeds(m):
    first = int(m.group(2))
    return f"{m.group(1)}{first}:{min(int(m.group(3)), first + 15)}"


def _shrink_range(m):
    first, last, step = (float(v) for v in m.group(2, 3, 4))
    return f"{m.group(1)}{m.group(2)}:{min(last, first + step):g}:{m.group(4)}"


# (pattern, replacement) on a program's command line at EXAMPLES=small: fewer seeds, shells
# and bootstrap samples, coarser meshes and lattices, the first two targets of a range.
SMALL_REWRITES = [
    (re.compile(r"(--seeds\s+)(\d+):(\d+)"), _shrink_seeds),
    (re.compile(r"(-n\s+)(\d+)"), lambda m: f"{m.group(1)}{min(int(m.group(2)), 200)}"),
    (re.compile(r"(--level\s+)(\d+)"), lambda m: f"{m.group(1)}{min(int(m.group(2)), 3)}"),
    (re.compile(r"(--refine\s+)(\d+)"), lambda m: f"{m.group(1)}1"),
    (re.compile(r"(--bootstrap\s+)(\d+)"), lambda m: f"{m.group(1)}{min(int(m.group(2)), 50)}"),
    (re.compile(r"(--phi\s+)([0-9.]+):([0-9.]+):([0-9.]+)"), _shrink_range),
    (re.compile(r"(--dphi\s+)([0-9.]+):([0-9.]+):([0-9.]+)"), _shrink_range),
    (re.compile(r"(--box\s+)(\d+)"), lambda m: f"{m.group(1)}{min(int(m.group(2)), 6)}"),
    (re.compile(r"(--time\s+)([0-9.]+)"), lambda m: f"{m.group(1)}{min(float(m.group(2)), 2):g}"),
]


def example_blocks(text):
    """The page's example blocks: lists of (line number, line) with the indentation removed."""
    lines = text.split("\n")
    blocks, i = [], 0
    while i < len(lines):
        if lines[i].startswith("```"):
            j = i + 1
            while j < len(lines) and not lines[j].startswith("```"):
                j += 1
            blocks.append([(k + 1, lines[k]) for k in range(i + 1, j)])
            i = j + 1
        elif lines[i].startswith("    ") and (i == 0 or not lines[i - 1].strip()):
            j = i
            while j < len(lines) and (lines[j].startswith("    ") or
                                      (not lines[j].strip() and j + 1 < len(lines)
                                       and lines[j + 1].startswith("    "))):
                j += 1
            blocks.append([(k + 1, lines[k][4:]) for k in range(i, j)])
            i = j
        else:
            i += 1
    return [b for b in blocks if b and _is_command(b[0][1])]


def _is_command(line):
    words = line.removeprefix("$ ").split()
    return bool(words) and (words[0] in COMMAND_WORDS or words[0].startswith("scripts/"))


def _strip_comment(line):
    """The line without its trailing '# ...' comment (a '#' outside quotes after a space)."""
    quote = None
    for k, c in enumerate(line):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c == "#" and (k == 0 or line[k - 1] in " \t"):
            return line[:k].rstrip(), line[k + 1:].strip()
    return line.rstrip(), ""


def commands(block):
    """(line number, command, comment, expected output lines or None) of one block."""
    out, k = [], 0
    transcript = block[0][1].startswith("$ ")
    while k < len(block):
        number, line = block[k]
        if transcript:
            if not line.startswith("$ "):
                k += 1
                continue
            line = line[2:]
        code, comment = _strip_comment(line)
        parts, notes = [code], [comment]
        while re.search(r"(\\|\||&&)$", parts[-1]) and k + 1 < len(block):
            k += 1
            code, comment = _strip_comment(block[k][1])
            parts[-1] = parts[-1].removesuffix("\\").rstrip()
            parts.append(code.strip())
            notes.append(comment)
        expected = None
        if transcript:
            expected = []
            while k + 1 < len(block) and not block[k + 1][1].startswith("$ "):
                k += 1
                expected.append(block[k][1])
        if " ".join(parts).strip():
            out.append((number, " ".join(parts), " ".join(n for n in notes if n), expected))
        k += 1
    return out


def announced_status(comment):
    m = re.search(r"\bexits?\s+(\d+)", comment)
    return int(m.group(1)) if m else 0


class Runner:
    def __init__(self, args, scratch):
        self.bin, self.src, self.size, self.scratch = args.bin, args.src, args.size, scratch
        self.build = os.path.dirname(os.path.abspath(self.bin))
        self.env = dict(os.environ, PATH=f"{self.bin}:{os.environ['PATH']}", OMP_NUM_THREADS="2")
        # mpirun as the pages write it (docs/lbflow.md, "Across machines"): more ranks than this
        # machine's cores, as root too, PMIx without munge; -q's quiet as the default.
        self.env.update(OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_ALLOW_RUN_AS_ROOT="1",
                        OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", PMIX_MCA_psec="native")
        self.slurm = None

    def rewrite(self, command):
        """The command as this size runs it, and the folder it runs in."""
        if self.size == "small":
            for pattern, replacement in SMALL_REWRITES:
                command = pattern.sub(replacement, command)
            command = re.sub(r"--sshlogin\s+\S+", "--sshlogin 2/:", command)
            command = re.sub(r"\bsalloc\s+-N\s*\d+", "salloc -N1", command)
            command = re.sub(r"-c\s*\d+(\s+--exclusive)", r"-c1\1", command)
            command = re.sub(r"(make\b.*?)-j\s*\d+", r"\1-j2", command)
        if re.search(r"(^|&&\s*|\s)make\s", " " + command):
            command = self.make_command(command)
        if command.startswith("salloc"):
            self.start_slurm()
        return command

    def make_command(self, command):
        def one(m):
            words = m.group(2).split()
            targets = [w for w in words if not w.startswith("-") and "=" not in w]
            extra = [f"BUILD={self.build}", f"OUT={self.scratch}/out"]
            dry = "test" in targets or (self.size == "small" and
                                        any(t in DRY_MAKE_SMALL for t in targets))
            if any(t.startswith("study") for t in targets):
                extra += [f"STUDY_DIR={self.scratch}/study", f"DOCS_DIR={self.scratch}/docs", "THREADS=1"]
                if self.size == "small":
                    words = [w for w in words if w.split("=")[0] not in STUDY_SIZE_VARIABLES]
                    extra.append("STUDY=tiny")
            return (m.group(1) + f"make -C {self.src} --no-print-directory " + ("-n " if dry else "")
                    + " ".join(words + extra))
        # a make command ends at a redirection, a pipe or '&&'
        return re.sub(r"(^|\s)make\s+([^|&>]*)", one, command)

    def start_slurm(self):
        if self.slurm:
            return
        self.slurm = os.path.join(self.scratch, "slurm")
        subprocess.run([os.path.join(self.src, "scripts/study/slurm_local.sh"), "start",
                        self.slurm], check=True, stdout=subprocess.DEVNULL)
        self.env["SLURM_CONF"] = os.path.join(self.slurm, "slurm.conf")

    def stop(self):
        if self.slurm:
            subprocess.run([os.path.join(self.src, "scripts/study/slurm_local.sh"), "stop",
                            self.slurm], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)

    def run(self, page, number, command, comment, expected):
        want = announced_status(comment)
        actual = self.rewrite(command)
        start = time.monotonic()
        try:
            p = subprocess.run(["bash", "-o", "pipefail", "-c", actual], cwd=self.scratch, env=self.env,
                               stdin=subprocess.DEVNULL, capture_output=True, text=True,
                               timeout=600)
            status, stdout, stderr = p.returncode, p.stdout, p.stderr
        except subprocess.TimeoutExpired:
            status, stdout, stderr = "timeout", "", "no exit after 600 s"
        seconds = time.monotonic() - start
        problem = None
        if status != want:
            problem = f"exited {status}, the text announces {want}"
        elif expected is not None:
            got = [l for l in (stdout + stderr).split("\n") if l]
            if got != [l for l in expected if l]:
                problem = "output differs from the page's:\n    " + "\n    ".join(got)
        shown = actual if actual == command else f"{actual}\n      (as written: {command})"
        print(f"{'FAIL' if problem else 'ok  '} {page}:{number} {seconds:6.1f} s  {shown}")
        if problem:
            tail = "\n    ".join(stderr.strip().split("\n")[-8:])
            print(f"    {problem}\n    {tail}")
        return problem is None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("page")
    ap.add_argument("--bin", required=True)
    ap.add_argument("--src", required=True)
    ap.add_argument("--size", choices=("small", "full"), default="small")
    ap.add_argument("--list", action="store_true", help="print the commands, run nothing")
    ap.add_argument("--keep", help="run in this folder and keep it")
    args = ap.parse_args()
    page = os.path.relpath(args.page, args.src)
    with open(args.page) as f:
        blocks = example_blocks(f.read())
    todo = [c for b in blocks for c in commands(b)]
    if not todo:
        print(f"{page}: no command examples")
        return 0
    if args.list:
        for number, command, comment, _ in todo:
            print(f"{page}:{number}: {command}" + (f"   # exit {announced_status(comment)}"
                                                    if announced_status(comment) else ""))
        return 0
    scratch = args.keep or tempfile.mkdtemp(prefix="examples.")
    os.makedirs(scratch, exist_ok=True)
    for name in ("scripts", "data"):  # the checkout's scripts and samples, as the pages name them
        if not os.path.exists(os.path.join(scratch, name)):
            os.symlink(os.path.join(args.src, name), os.path.join(scratch, name))
    runner = Runner(args, os.path.abspath(scratch))
    try:
        ok = [runner.run(page, *c) for c in todo]
    finally:
        runner.stop()
        if not args.keep:
            shutil.rmtree(scratch, ignore_errors=True)
    print(f"{page}: {sum(ok)} of {len(ok)} examples ran as the page says ({args.size} size)")
    return 0 if all(ok) else 1


if __name__ == "__main__":
    sys.exit(main())
