#!/usr/bin/env bash
# OVITO and ASE read shellpack's jammed packings: ASE (Debian python3-ase) gets the periodic
# cell, positions, radii and contact counts, and the contacts it recomputes from them are
# the 3N - 2 that shellpack reports.
#   bash shellpack_ase.sh --list | CASE     (needs CMP_BIN)
set -uo pipefail
if [[ ${1:-} == --list ]]; then echo ase_reads_jammed_packing; exit 0; fi
bin=${CMP_BIN:?set CMP_BIN}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$bin/shellpack" jam -N 30 --seed 2 -o "$work/jammed.xyz" -q >"$work/jam.csv" || exit 1
/usr/bin/python3 - "$work/jammed.xyz" <<'PY'
import sys
import numpy as np
from ase.io import read

atoms = read(sys.argv[1], format="extxyz")
assert len(atoms) == 30, len(atoms)
assert atoms.pbc.all(), atoms.pbc
cell = atoms.cell.array
assert np.allclose(cell, np.diag(np.diag(cell))) and cell[0, 0] > 0, cell
radius = atoms.arrays["radius"]
contacts = atoms.arrays["contacts"]
# Contacts recomputed from what ASE read: minimum-image overlaps.
pos = atoms.positions
d = pos[:, None, :] - pos[None, :, :]
L = np.diag(cell)
d -= L * np.round(d / L)
r = np.linalg.norm(d, axis=2)
touching = (r < radius[:, None] + radius[None, :]) & ~np.eye(len(atoms), dtype=bool)
assert touching.sum() // 2 == 3 * 30 - 2, touching.sum() // 2
assert (touching.sum(axis=1) == contacts).all()
phi = 4 / 3 * np.pi * (radius ** 3).sum() / np.prod(L)
assert abs(phi - float(atoms.info["phi"])) < 1e-12, (phi, atoms.info["phi"])
print("ASE read", len(atoms), "spheres, phi", phi, "contacts", touching.sum() // 2)
PY
