#!/usr/bin/env python3
"""The projection ladder measured against the exact renderer (docs/methods.md's tables).

usage: bench/projection.py [--build DIR] [--quick] [--out DIR]

For every scene (the default scene, a 1M-tetrahedron box, and the shared datasets' scenes when
../shared/data exists) and image size, renders `exact` (canonical-tets: the same piecewise-linear
field the projection methods see; and isoparametric where the mesh has other cells) and every
projection method, 3 frames each, and prints one Markdown row per (scene, size, method): median /
min / max seconds per frame (sort included, mesh preparation excluded), fragments, and RMSE and
largest error of the premultiplied float image against exact. Then the opacity-table sweep and
the thread speed-up. Pictures and difference images (x10) land in --out.
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
METHODS = ["pt-linear", "pt-table", "pt-analytic", "pt-breakpoints"]


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{p.stderr}")
    return p


def render(exe, scene, out, method, size, frames=3, extra=()):
    cmd = [exe, "render", scene, "--method", method, "--size", f"{size}x{size}", "--frames", str(frames),
           "-o", f"{out}.png", "--npy", f"{out}.npy", "--stats", *extra]
    stats = json.loads(run(cmd).stderr.strip().splitlines()[-1])
    return stats


def compare(exe, a, b, diff=None):
    cmd = [exe, "compare", a, b] + (["--diff", diff] if diff else [])
    return json.loads(run(cmd).stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true", help="512^2 only, no 1M mesh")
    ap.add_argument("--out", default="bench-out")
    a = ap.parse_args()
    exe = os.path.join(a.build, "bin", "cellproj")
    os.makedirs(a.out, exist_ok=True)
    scenes = [("default (swirl, 12k hex)", os.path.join(ROOT, "scenes", "default.json"), True)]
    if not a.quick:
        box = os.path.join(a.out, "box1m.vtu")
        if not os.path.exists(box):
            run([exe, "generate", "box-tets", "-n", "56", "-o", box])
        scene = os.path.join(a.out, "box1m.json")
        with open(scene, "w") as f:
            json.dump({"mesh": "box1m.vtu", "field": "scalar",
                       "transfer_function": {"color": [[0, 0.2, 0.3, 0.9], [0.6, 0.9, 0.8, 0.3], [1, 1, 0.3, 0.1]],
                                             "extinction": [[0, 0.2], [0.6, 1.0], [0.8, 4.0], [1, 8.0]]},
                       "camera": {"projection": "perspective", "eye": [3.5, 2.5, 4.5], "target": [0, 0, 0],
                                  "up": [0, 1, 0], "fov_y": 35}}, f)
        scenes.append(("box-tets 56^3 (1.05M tets)", scene, False))
    shared = os.path.join(ROOT, "..", "shared", "data")
    if os.path.isdir(shared):
        for name in ["post_tets", "bluntfin", "combustion_chamber", "disk_out_ref", "static_mixer"]:
            scenes.append((name, os.path.join(ROOT, "bench", "scenes", name + ".json"), name != "post_tets"))
    sizes = [512] if a.quick else [512, 1024]

    print("| scene | size | method | median s | min s | max s | fragments | RMSE | max error |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, scene, mixed in scenes:
        tag = os.path.splitext(os.path.basename(scene))[0]
        for size in sizes:
            base = os.path.join(a.out, f"{tag}_{size}")
            ref = render(exe, scene, base + "_exact", "exact", size, 1, ["--interpolation", "canonical-tets"])
            rows = [("exact (canonical-tets)", ref, None)]
            if mixed:
                iso = render(exe, scene, base + "_iso", "exact", size, 1)
                rows.append(("exact (isoparametric)", iso, compare(exe, base + "_iso.npy", base + "_exact.npy")))
            for m in METHODS:
                st = render(exe, scene, f"{base}_{m}", m, size)
                d = compare(exe, f"{base}_{m}.npy", base + "_exact.npy", f"{base}_{m}_diff.png")
                rows.append((m, st, d))
            for m, st, d in rows:
                frag = st.get("fragments", st.get("segments", ""))
                err = f"{d['rmse']:.2e} | {d['max_abs']:.2e}" if d else "reference | reference"
                print(f"| {label} | {size}² | {m} | {st['frame_seconds']:.3f} | {st['min_frame_seconds']:.3f} | "
                      f"{st['max_frame_seconds']:.3f} | {frag} | {err} |", flush=True)

    print("\nOpacity table size (pt-table, default scene, 512²): the table's own error, against an 8192² table,"
          " and the method's, against exact canonical-tets:\n")
    print("| table size | RMSE vs 8192² | max vs 8192² | RMSE vs exact | max vs exact |")
    print("|---|---|---|---|---|")
    default = os.path.join(ROOT, "scenes", "default.json")
    base = os.path.join(a.out, "default_512")
    for n in [8192, 8, 32, 128, 512, 2048]:
        render(exe, default, f"{base}_table{n}", "pt-table", 512, 1, ["--table-size", str(n)])
        t = compare(exe, f"{base}_table{n}.npy", f"{base}_table8192.npy")
        d = compare(exe, f"{base}_table{n}.npy", base + "_exact.npy")
        if n != 8192:
            print(f"| {n} | {t['rmse']:.2e} | {t['max_abs']:.2e} | {d['rmse']:.2e} | {d['max_abs']:.2e} |", flush=True)

    print("\nThreads (pt-analytic, median of 3 frames):\n")
    print("| scene | size | 1 thread s | 2 threads s | speed-up | same bits |")
    print("|---|---|---|---|---|---|")
    for label, scene, _ in scenes[:2]:
        size = sizes[-1]
        tag = os.path.splitext(os.path.basename(scene))[0]
        t = {}
        for n in (1, 2):
            t[n] = render(exe, scene, os.path.join(a.out, f"{tag}_t{n}"), "pt-analytic", size, 3, ["--threads", str(n)])
        same = compare(exe, os.path.join(a.out, f"{tag}_t1.npy"), os.path.join(a.out, f"{tag}_t2.npy"))["max_abs"] == 0
        print(f"| {label} | {size}² | {t[1]['frame_seconds']:.3f} | {t[2]['frame_seconds']:.3f} | "
              f"{t[1]['frame_seconds'] / t[2]['frame_seconds']:.2f}× | {'yes' if same else 'NO'} |", flush=True)


if __name__ == "__main__":
    main()
