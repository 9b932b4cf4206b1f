#!/usr/bin/env python3
"""The Fig. 4.5b table of `shellpack compress --walls` runs: at each target phi of the runs'
compress.csv files (the rows where a packing OFF was written, phi a multiple of 0.05), the
wall pressure P, the coverage Theta, P/Theta and the mean turgor <Pi>, side by side.

usage: scripts/tables/compress_walls.py LABEL=compress.csv [LABEL=compress.csv ...]  (markdown to stdout)
"""
import csv
import sys


def rows_of(path):
    meta = {}
    lines = []
    with open(path) as f:
        for line in f:
            if line.startswith('# '):
                key, _, value = line[2:].strip().partition('=')
                meta[key] = value
            else:
                lines.append(line)
    return meta, list(csv.DictReader(lines))


def main(argv):
    if len(argv) < 2 or any('=' not in a for a in argv[1:]):
        sys.exit(__doc__)
    runs = []
    for arg in argv[1:]:
        label, path = arg.split('=', 1)
        meta, rows = rows_of(path)
        p0 = float(meta['P0'])
        table = {}
        for r in rows:
            phi = float(r['phi'])
            if abs(phi * 20 - round(phi * 20)) < 1e-9 and r['wall_pressure_over_coverage_E'] not in ('', 'nan'):
                table[round(phi, 2)] = r
        runs.append((label, p0, table))
    head = '| φ |' + ''.join(f' {l}: P/E | Θ | P/Θ (E) | ⟨Π⟩ (E) | (P/Θ)/⟨Π⟩ |' for l, _, _ in runs)
    print(head)
    print('|---|' + '---|---|---|---|---|' * len(runs))
    for phi in sorted(set().union(*[t.keys() for _, _, t in runs])):
        line = f'| {phi:.2f} |'
        for _, p0, t in runs:
            r = t.get(phi)
            if r is None:
                line += ' | | | | |'
                continue
            P, theta, ratio = float(r['wall_pressure_E']), float(r['coverage']), float(r['wall_pressure_over_coverage_E'])
            pi = float(r['turgor_mean_P0']) * p0
            line += f' {P:.3g} | {theta:.3f} | {ratio:.3g} | {pi:.3g} | {ratio / pi:.3f} |'
        print(line)


if __name__ == '__main__':
    main(sys.argv)
