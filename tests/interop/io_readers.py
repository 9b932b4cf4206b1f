"""Checks of lib/io files with the readers users have (ASE, meshio), and files those write.

Driven by io_readers.sh: python3 io_readers.py CHECK FOLDER. The expected values are the
formulas of tests/io/test_interop.cpp, evaluated with the same IEEE doubles, so comparisons
are exact. Exits non-zero (AssertionError) on the first mismatch.
"""
import math
import os
import sys

import numpy as np


def octahedron(shift_x):
    d = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    V = np.array([[d[i][k] / 3.0 + 0.1 + (shift_x if k == 0 else 0.0) for k in range(3)]
                  for i in range(6)])
    F = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4],
                  [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return V, F


def same_bits(a, b):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and a.tobytes() == b.tobytes()


def check_ase_xyz(folder):
    import ase.io
    frames = ase.io.read(os.path.join(folder, "frames.xyz"), index=":", format="extxyz")
    assert len(frames) == 3, f"ASE read {len(frames)} frames, expected 3"
    for f, atoms in enumerate(frames):
        n = 4 + f
        assert len(atoms) == n, f"frame {f}: {len(atoms)} atoms, expected {n}"
        assert atoms.get_chemical_symbols() == ["O" if i % 2 else "H" for i in range(n)]
        pos = np.array([[i * 0.1 + f, i / 3.0, 1e-8 * (i + 1) if i % 2 else -0.0]
                        for i in range(n)])
        assert same_bits(atoms.positions, pos), f"frame {f}: positions\n{atoms.positions}"
        cell = np.array([[10.0 / 3.0, 0, 0], [0.1, 5.0 + f, 0], [0, 0, 7.25]])
        assert same_bits(atoms.cell.array, cell), f"frame {f}: cell\n{atoms.cell.array}"
        assert list(atoms.pbc) == [True, False, True], f"frame {f}: pbc {atoms.pbc}"
        radius = np.array([0.5 + 1e-8 * i for i in range(n)])
        assert same_bits(atoms.arrays["radius"], radius), f"frame {f}: radius"
        shell = atoms.arrays["shell"]
        assert shell.dtype.kind == "i", f"shell column read as {shell.dtype}"
        assert list(shell) == [7 * i - 3 - f for i in range(n)], f"frame {f}: shell {shell}"
        assert atoms.info["tool"] == "cmp-test", atoms.info
        assert atoms.info["step"] == f, atoms.info
        assert atoms.info["note"] == "two words", atoms.info
    print("ASE read 3 frames: symbols, positions, cell, pbc, radius, shell, info exact")


def check_meshio_off(folder):
    import meshio
    V, F = octahedron(0.0)
    m = meshio.read(os.path.join(folder, "octahedron.off"))
    assert same_bits(m.points, V), f"points\n{m.points}"
    cells = m.get_cells_type("triangle")
    assert np.array_equal(cells, F), f"triangles\n{cells}"
    p = meshio.read(os.path.join(folder, "packing.off"))
    V2, F2 = octahedron(2.0)
    assert same_bits(p.points, np.vstack([V, V2])), f"packing points\n{p.points}"
    assert np.array_equal(p.get_cells_type("triangle"), np.vstack([F, F2 + 6]))
    print("meshio read the mesh (6 points, 8 triangles) and the packing (12, 16) exactly")


def check_meshio_vtk(folder):
    import meshio

    def grid(dims, values):
        nx, ny, nz = dims
        # x fastest: the flat index of voxel (x, y, z) is x + nx*(y + ny*z).
        return np.array([values(x, y, z) for z in range(nz) for y in range(ny) for x in range(nx)])

    images = {
        "uint8": ((7, 5, 3), "solid", np.uint8, lambda x, y, z: (x + 7 * y + 35 * z) * 2 + 1,
                  (0.5, -1.0, 2.0), (0.25, 0.5, 1.0 / 3.0)),
        "float": ((4, 3, 2), "pressure", np.float32,
                  lambda x, y, z: np.float32(x * 0.5 - y / 3.0 + z * 1e-8),
                  (0, 0, 0), (0.04, 0.04, 0.04)),
        "int32": ((3, 3, 3), "label", np.int32, lambda x, y, z: x - 10 * y + 100 * z - 50,
                  (0, 0, 0), (1, 1, 1)),
        "double": ((2, 3, 4), "speed", np.float64, lambda x, y, z: x / 3.0 + y * 0.1 + z * 1e-300,
                   (0, 0, 0), (1, 1, 1)),
    }
    for stem, (dims, name, dtype, values, origin, spacing) in images.items():
        m = meshio.read(os.path.join(folder, stem + ".vtk"))
        data = m.point_data[name]
        # meshio keeps the file's big-endian byte order; the type itself must match.
        assert data.dtype.newbyteorder("=") == np.dtype(dtype), f"{stem}: dtype {data.dtype}"
        assert data.shape == (dims[0] * dims[1] * dims[2], 1), f"{stem}: shape {data.shape}"
        data = data.reshape(-1).astype(dtype)
        expected = grid(dims, values).astype(dtype)
        assert data.tobytes() == expected.tobytes(), f"{stem}: values\n{data}\n{expected}"
        nx, ny, _ = dims
        # A few voxels by (x, y, z), and the point meshio puts there.
        for x, y, z in [(0, 0, 0), (dims[0] - 1, 0, 0), (0, dims[1] - 1, 0),
                        (0, 0, dims[2] - 1), (dims[0] - 1, dims[1] - 1, dims[2] - 1), (1, 2, 1)]:
            i = x + nx * (y + ny * z)
            assert data[i] == dtype(values(x, y, z)), f"{stem}: voxel {(x, y, z)} = {data[i]}"
            p = [origin[k] + (x, y, z)[k] * spacing[k] for k in range(3)]
            assert np.allclose(m.points[i], p, rtol=0, atol=1e-12), f"{stem}: point {i} {m.points[i]}"
        assert len(m.points) == dims[0] * dims[1] * dims[2]
    print("meshio read 4 binary STRUCTURED_POINTS images: types, values x fastest, points")


def write_ase(folder):
    import ase
    import ase.io
    frames = []
    for k in range(2):
        atoms = ase.Atoms(symbols=["H", "O", "H"],
                          positions=[[0.125 * i + k, -1.5 * i, 2.25] for i in range(3)],
                          cell=[[6, 0, 0], [0, 7, 0], [0.5, 0, 8]], pbc=[True, False, True])
        atoms.new_array("radius", np.array([0.5, 0.75, 1.0]))
        atoms.new_array("shell", np.array([1, 2, 3 + k], dtype=np.int64))
        atoms.info["step"] = k
        atoms.info["label"] = "two words"
        frames.append(atoms)
    ase.io.write(os.path.join(folder, "ase_written.xyz"), frames, format="extxyz")
    print(open(os.path.join(folder, "ase_written.xyz")).read(), end="")


def write_meshio(folder):
    import meshio
    V, F = octahedron(0.0)
    meshio.write(os.path.join(folder, "meshio_written.off"),
                 meshio.Mesh(V, [("triangle", F)]), file_format="off")
    print(open(os.path.join(folder, "meshio_written.off")).read(), end="")


CHECKS = {"ase_xyz": check_ase_xyz, "meshio_off": check_meshio_off,
          "meshio_vtk": check_meshio_vtk, "write_ase": write_ase, "write_meshio": write_meshio}

if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] not in CHECKS:
        sys.exit(f"usage: {sys.argv[0]} {{{','.join(CHECKS)}}} FOLDER")
    CHECKS[sys.argv[1]](sys.argv[2])
