"""percolate's labelling against scipy.ndimage.label (what the thesis used, 5.2.2).

Driven by percolate_scipy.sh: python3 percolate_scipy.py write CASE FOLDER writes random
images and images.txt; test_voxel "[.scipy]" labels them; python3 percolate_scipy.py check
CASE FOLDER compares component for component. Exits non-zero on the first mismatch.
"""
import os
import sys

import numpy as np
from scipy import ndimage

SHAPES = [(1, 1, 1), (37, 23, 19), (64, 64, 64), (5, 80, 3), (96, 48, 32)]
POROSITIES = [0.2, 0.3116, 0.35, 0.6]


def images(case):
    """(name, image [z, y, x], connectivity, periodic xyz) of a case."""
    rng = np.random.default_rng({"six": 1, "eighteen": 2, "twentysix": 3, "periodic": 4}[case])
    conn = {"six": 6, "eighteen": 18, "twentysix": 26, "periodic": 6}[case]
    out = []
    for s, (nx, ny, nz) in enumerate(SHAPES):
        for p in POROSITIES:
            img = (rng.random((nz, ny, nx)) < p).astype(np.uint8)
            out.append((f"img{s}_{int(p * 1e4)}", img, conn, "011" if case == "periodic" else "000"))
    return out


def periodic_reference(img, periodic_xyz):
    """scipy has no periodic option: label, then merge labels across periodic faces."""
    lab, n = ndimage.label(img)
    parent = list(range(n + 1))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    # axis order of the array is (z, y, x); periodic_xyz is "xyz"
    for axis_xyz, flag in enumerate(periodic_xyz):
        if flag != "1":
            continue
        ax = 2 - axis_xyz
        lo = np.take(lab, 0, axis=ax)
        hi = np.take(lab, -1, axis=ax)
        for a, b in zip(lo.ravel(), hi.ravel()):
            if a and b:
                ra, rb = find(a), find(b)
                if ra != rb:
                    parent[max(ra, rb)] = min(ra, rb)
    roots = np.array([find(i) for i in range(n + 1)])
    return roots[lab]


def same_partition(a, b):
    a, b = a.ravel(), b.ravel()
    if not np.array_equal(a == 0, b == 0):
        return False
    pairs = np.unique(np.stack([a[a > 0], b[b > 0]]), axis=1)
    return len(np.unique(pairs[0])) == pairs.shape[1] == len(np.unique(pairs[1]))


def main():
    mode, case, folder = sys.argv[1:4]
    imgs = images(case)
    if mode == "write":
        with open(os.path.join(folder, "images.txt"), "w") as f:
            for name, img, conn, per in imgs:
                img.tofile(os.path.join(folder, name + ".u8"))
                nz, ny, nx = img.shape
                f.write(f"{name} {nx} {ny} {nz} {conn} {per}\n")
        return
    identical = 0
    for name, img, conn, per in imgs:
        ours = np.fromfile(os.path.join(folder, name + ".i32"), dtype=np.int32).reshape(img.shape)
        if per == "000":
            rank = {6: 1, 18: 2, 26: 3}[conn]
            ref, n = ndimage.label(img, structure=ndimage.generate_binary_structure(3, rank))
        else:
            ref = periodic_reference(img, per)
            n = len(np.unique(ref[ref > 0]))
        assert ours.max() == n, f"{name}: {ours.max()} components, scipy {n}"
        assert same_partition(ours, ref), f"{name}: partitions differ"
        identical += np.array_equal(ours, ref)
    print(f"{case}: {len(imgs)} images, same components as scipy.ndimage.label in all, "
          f"identical numbering in {identical}")


if __name__ == "__main__":
    main()
