"""Plane slicing on the speed/accuracy table (docs/accuracy.md, "Slicing"). Run through bench/slicing,
which builds cellproj and installs numpy and matplotlib for Debian's python3.

1. Convergence: on a tetrahedral box, a hexahedral non-convex ring, its tetrahedra and the mixed
   mesh (512², the bench scenes of bench/run), the RMSE against `exact` (canonical-tets, the field
   slicing renders with --tetrahedralize all) of sampled and preintegrated slicing at N = 16 ... 2048
   slices, beside pt-table and pt-analytic; the measured order (log-log slope over the last
   doublings); the first N at which slicing's error drops below pt-table's and pt-analytic's, and
   its time there. Plot: DIR/plots/slicing_convergence.png.
2. Speed where the errors match: on the 1M-tetrahedron box, the N at which preintegrated slicing
   reaches pt-table's error (found at 512², where exact takes ~2 min; 1024² would take ~8), then
   both timed at 1024² in the same run: the ratio.
3. The 8-bit path: a slab of 240 faint slices (opacity 2e-4 each), its mean opacity in the float,
   8-bit and dithered 8-bit targets against 1 - exp(-kappa thickness).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import Bench, error, run, synthetic  # noqa: E402

COUNTS = [16, 32, 64, 128, 256, 512, 1024, 2048]
INTEGRALS = ["sampled", "preintegrated"]


def slicing(bench, scene, tag, n, integral, size, frames=1):
    return bench.render(scene, f"{tag}_slicing_{integral}_{n}", "slicing", size, frames,
                        ["--slices", str(n), "--slice-integral", integral, "--tetrahedralize", "all"])


def convergence(bench, meshes, size):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(meshes), figsize=(4.2 * len(meshes), 3.8))
    print(f"\nSlicing against exact (canonical-tets), {size}², 2 threads\n")
    print("| mesh | cells | method | slices | s | RMSE | max error |")
    print("|---|---|---|---|---|---|---|")
    summary = []
    for ax, (name, scene, mesh, info) in zip(axes, meshes):
        tag = f"{name}_{size}"
        _, ref = bench.render(scene, tag + "_exact", "exact", size, 1, ["--interpolation", "canonical-tets"])
        ladder = {}
        for m in ["pt-table", "pt-analytic"]:
            st, npy = bench.render(scene, f"{tag}_{m}", m, size, 3, ["--tetrahedralize", "all"])
            ladder[m] = (st["frame_seconds"], *error(npy, ref))
            print(f"| {name} | {info['cells']} | {m} | | {ladder[m][0]:.3f} | {ladder[m][1]:.2e} | {ladder[m][2]:.2e} |")
            ax.axhline(ladder[m][1], ls="--", lw=0.8, color="gray")
            ax.annotate(m, (COUNTS[0], ladder[m][1]), fontsize=7, xytext=(0, 2), textcoords="offset points")
        for integral in INTEGRALS:
            errs, times = [], []
            for n in COUNTS:
                st, npy = slicing(bench, scene, tag, n, integral, size, 3 if n <= 512 else 1)
                e = error(npy, ref)
                errs.append(e[0]), times.append(st["frame_seconds"])
                print(f"| {name} | {info['cells']} | slicing {integral} | {n} | {st['frame_seconds']:.3f} | "
                      f"{e[0]:.2e} | {e[1]:.2e} |", flush=True)
            ax.loglog(COUNTS, errs, "o-", label=integral, ms=3)
            order = -math.log(errs[-1] / errs[-4]) / math.log(COUNTS[-1] / COUNTS[-4])
            cross = {}
            for m, (t, rmse, _) in ladder.items():
                k = next((k for k, e in enumerate(errs) if e < rmse), None)
                cross[m] = "beyond 2048" if k is None else f"{COUNTS[k]} ({times[k]:.3f} s, {times[k] / t:.1f}× {m}'s)"
            summary.append((name, integral, order, cross))
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("slices")
        ax.set_ylabel("RMSE against exact")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(os.path.join(bench.out, "plots"), exist_ok=True)
    fig.savefig(os.path.join(bench.out, "plots", "slicing_convergence.png"), dpi=110)
    print("\n| mesh | integral | order (last 3 doublings) | below pt-table at | below pt-analytic at |")
    print("|---|---|---|---|---|")
    for name, integral, order, cross in summary:
        print(f"| {name} | {integral} | {order:.2f} | {cross['pt-table']} | {cross['pt-analytic']} |")


def speed_1m(bench):
    name, scene, mesh, info = synthetic(bench, "box-tets", 56, "tets-1m")
    tag = f"{name}_512"
    _, ref = bench.render(scene, tag + "_exact", "exact", 512, 1)
    _, npy = bench.render(scene, tag + "_pt-table", "pt-table", 512, 1)
    target = error(npy, ref)[0]
    match = None
    for n in [128, 256, 512, 1024, 2048]:
        _, npy = slicing(bench, scene, tag, n, "preintegrated", 512)
        e = error(npy, ref)[0]
        print(f"tets-1m 512²: slicing preintegrated {n} slices RMSE {e:.2e} (pt-table {target:.2e})", flush=True)
        if e <= target:
            match = n
            break
    match = match or 2048
    pt, _ = bench.render(scene, f"{name}_1024_pt-table", "pt-table", 1024, 3)
    sl, _ = slicing(bench, scene, f"{name}_1024", match, "preintegrated", 1024, 3)
    print(f"\n1M tetrahedra at 1024², 2 threads: pt-table {pt['frame_seconds']:.3f} s; slicing preintegrated at "
          f"{match} slices (its error matches pt-table's at 512²) {sl['frame_seconds']:.3f} s: "
          f"slicing / pt-table = {sl['frame_seconds'] / pt['frame_seconds']:.2f}")
    print(f"slicing phases: {sl['phase_seconds']}")


def faint(bench):
    mesh = os.path.join(bench.out, "meshes", "slab.vtu")
    run([bench.exe, "generate", "box-tets", "-n", "4", "-o", mesh])
    scene = os.path.join(bench.out, "meshes", "faint.json")
    with open(scene, "w") as f:
        f.write('{"mesh": "slab.vtu", "field": "scalar", "transfer_function": {"color": [[0, 1, 1, 1]], '
                '"extinction": [[0, 0.025]]}, "camera": {"projection": "orthographic", "eye": [0, 0, 5], '
                '"target": [0, 0, 0], "up": [0, 1, 0], "height": 1.5}}')
    want = -math.expm1(-0.025 * 2.0)
    print(f"\nFaint slices: 240 slices of opacity {-math.expm1(-0.025 * 2 / 240):.1e} each, mean opacity "
          f"(exact {want:.4f})\n")
    print("| back end | mean opacity | lost |")
    print("|---|---|---|")
    for backend in ["software", "opengl", "opengl-8bit", "opengl-8bit-dither"]:
        _, npy = bench.render(scene, f"faint_{backend}", "slicing", 64, 1,
                              ["--slices", "240", "--slice-integral", "sampled", "--backend", backend])
        a = float(np.load(npy)[..., 3].mean())
        print(f"| {backend} | {a:.4f} | {100 * (1 - a / want):.0f}% |", flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="bench-out")
    ap.add_argument("--build", default=os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build"))
    ap.add_argument("--no-1m", action="store_true", help="skip the 1M-tetrahedron timing (a third of the run)")
    a = ap.parse_args()
    for sub in ("meshes", "images"):
        os.makedirs(os.path.join(a.out, sub), exist_ok=True)
    bench = Bench(os.path.join(a.build, "bin", "cellproj"), a.out, 3)
    meshes = [synthetic(bench, "box-tets", 12, "tets-10k"), synthetic(bench, "swirl", 16, "curvilinear"),
              synthetic(bench, "swirl-tets", 8, "swirl-tets"), synthetic(bench, "mixed", 8, "mixed")]
    faint(bench)
    convergence(bench, meshes, 512)
    if not a.no_1m:
        speed_1m(bench)


if __name__ == "__main__":
    main()
