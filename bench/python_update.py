"""An in-situ loop from Python (docs/python.md, "In-situ loops"): a solver's mesh of about 1M
tetrahedra drawn step after step by cellproj.Volume. Per step, the wall time of update() plus
render() and the picture's prepare_seconds: a new field keeps the preparation (prepare_seconds 0),
moved points make it again. The first picture (the preparation made) is the baseline of the ratios.

usage: /usr/bin/python3 bench/python_update.py [--build build] [--n 56] [--size 512] [--steps 3]
(n^3 hexahedra cut into 6 tetrahedra: 56 gives 1,053,696 cells)
"""
import argparse
import os
import sys
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def box(n):
    """An n^3 box of hexahedra, each cut into 6 tetrahedra about its 0-6 diagonal, as numpy arrays."""
    g = np.linspace(-1.0, 1.0, n + 1)
    x, y, z = np.meshgrid(g, g, g, indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1)
    i, j, k = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    v = lambda a, b, c: (((i + a) * (n + 1) + (j + b)) * (n + 1) + (k + c)).ravel()
    corners = [v(0, 0, 0), v(1, 0, 0), v(1, 1, 0), v(0, 1, 0), v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1)]
    tets = [(0, 1, 2, 6), (0, 2, 3, 6), (0, 3, 7, 6), (0, 7, 4, 6), (0, 4, 5, 6), (0, 5, 1, 6)]
    conn = np.stack([np.stack([corners[a] for a in t], axis=1) for t in tets], axis=1).reshape(-1)
    cells = 6 * n ** 3
    return points, conn.astype(np.int64), np.arange(0, 4 * cells + 1, 4, dtype=np.int64), np.full(cells, 10, np.uint8)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--n", type=int, default=56)
    parser.add_argument("--size", type=int, default=512)
    parser.add_argument("--steps", type=int, default=3)
    a = parser.parse_args()
    sys.path.insert(0, os.path.join(a.build, "python"))
    import cellproj

    points, conn, offsets, types = box(a.n)
    field = lambda s: np.exp(-4 * ((points - [0.2 * s, 0, 0]) ** 2).sum(axis=1))
    volume = cellproj.Volume(cellproj.Mesh(points, conn, offsets, types, {"T": field(0)}), field="T",
                             size=(a.size, a.size), view="iso", cmap="inferno")
    print("%d cells, %d points, %dx%d, method %s" % (volume.mesh.n_cells, volume.mesh.n_points, a.size, a.size,
                                                    "pt-breakpoints"))
    print("%-18s %9s %10s %10s %8s" % ("step", "wall_s", "prepare_s", "render_s", "ratio"))
    t = time.perf_counter()
    first = volume.render()
    base = time.perf_counter() - t
    print("%-18s %9.3f %10.3f %10.3f %8.2f" % ("first picture", base, first.stats["prepare_seconds"],
                                                first.stats["render_seconds"], 1.0))
    def step(label, update):
        t = time.perf_counter()
        update()
        image = volume.render()
        wall = time.perf_counter() - t
        print("%-18s %9.3f %10.3f %10.3f %8.2f" % (label, wall, image.stats["prepare_seconds"],
                                                    image.stats["render_seconds"], wall / base))

    for s in range(1, a.steps + 1):
        values = field(s)  # made before the clock: the solver's step, not cellproj's
        step("update(field=) %d" % s, lambda: volume.update(field=values))
    for s in range(1, a.steps + 1):
        moved = points.copy()
        moved[:, 0] += 0.05 * s * moved[:, 2] ** 2
        step("update(points=) %d" % s, lambda: volume.update(points=moved))


if __name__ == "__main__":
    main()
