"""Splatting small cells on the speed/accuracy table (docs/accuracy.md, "Splatting"). Run through
bench/splat, which builds cellproj and installs numpy for Debian's python3.

1. Error against the anti-aliased reference: `exact` rendered at 8x the size and box-filtered down
   (`cellproj compare --downsample 8` computes the same), at 256² and 512², for pt-linear,
   pt-breakpoints and slicing with --small-cells draw and splat, on
   - graded: the generated mesh whose cells thin geometrically to 1e-4 (1/50 of a pixel at 512²)
     towards a hot filament, optically thick there (an optical depth of about 4 across it);
   - graded-thin: the same with extinction / 25 (the filament optically thin);
   - uniform: 131k tetrahedra of about a pixel (a box seen from afar), where small cells do not
     carry anything the neighbours do not;
   - bluntfin (../shared/data, when present): NASA's curvilinear grid, clustered at the wall.
   Also: the small cells (by the rule) and, without splats, those that add no fragment at all
   (cells_covering_no_pixel for projection, cells_between_planes for slicing).
2. The threshold: RMSE of pt-breakpoints and slicing against the same references for several
   --splat-threshold values.
3. Temporal stability: a 36-frame turntable (10 degrees per frame about the scene's up axis) at
   256²; in the region where the small cells land (pixels where splat and skip differ in any
   frame), the mean frame-to-frame change of the total light over its mean, for draw, splat,
   exact at 1x and exact at 4x box-filtered (the scene's own change).
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run import ROOT, Bench, run  # noqa: E402

METHODS = ["pt-linear", "pt-breakpoints", "slicing"]
THRESHOLDS = {"pt-breakpoints": [1, 2, 4, 8, 16], "slicing": [0.25, 1, 4, 16]}
SUPER = 8


def scene_with_mesh(bench, name, template, mesh):
    """The bench scene `template` with its mesh in the output folder."""
    with open(os.path.join(ROOT, "bench", "scenes", template)) as f:
        s = json.load(f)
    s["mesh"] = mesh
    path = os.path.join(bench.out, "meshes", name + ".json")
    with open(path, "w") as f:
        json.dump(s, f)
    return path


def scenes(bench, quick):
    meshes = os.path.join(bench.out, "meshes")
    graded, uniform = os.path.join(meshes, "graded.vtu"), os.path.join(meshes, "uniform.vtu")
    if not os.path.exists(graded):
        run([bench.exe, "generate", "graded", "-n", "16", "-o", graded])
    if not os.path.exists(uniform):
        run([bench.exe, "generate", "box-tets", "-n", "28", "-o", uniform])
    out = [("graded", scene_with_mesh(bench, "graded", "graded.json", graded), (1, 1)),
           ("graded-thin", scene_with_mesh(bench, "graded_thin", "graded_thin.json", graded), (1, 1)),
           ("uniform", scene_with_mesh(bench, "uniform", "uniform_far.json", uniform), (1, 1))]
    bluntfin = os.path.join(ROOT, "bench", "scenes", "bluntfin.json")
    if os.path.isdir(os.path.join(ROOT, "..", "shared", "data")) and not quick:
        out.append(("bluntfin", bluntfin, (4, 3)))
    return out


def size_of(aspect, width):
    return width, width * aspect[1] // aspect[0]


def render(bench, scene, tag, method, size, extra=()):
    w, h = size
    npy = os.path.join(bench.out, "images", f"{tag}.npy")
    if not os.path.exists(npy) or not tag.endswith("_ref"):
        cmd = [bench.exe, "render", scene, "--method", method, "--size", f"{w}x{h}", "-o", npy[:-4] + ".png",
               "--npy", npy, "--stats", *extra]
        st = json.loads(run(cmd).stderr.strip().splitlines()[-1])
    else:
        st = {}
    return st, npy


def reference(bench, scene, tag, size, k):
    """exact at k times the size, box-filtered down (cellproj compare --downsample k)."""
    w, h = size
    _, npy = render(bench, scene, tag + f"_x{k}_ref", "exact", (k * w, k * h))
    a = np.load(npy).astype(np.float64)
    return a.reshape(h, k, w, k, 4).mean(axis=(1, 3))


def rmse(npy, ref):
    d = np.load(npy).astype(np.float64) - ref
    return float(np.sqrt((d * d).mean())), float(np.abs(d).max())


def errors(bench, name, scene, aspect, width):
    size = size_of(aspect, width)
    tag = f"{name}_{width}"
    ref = reference(bench, scene, tag, size, SUPER)
    _, point = render(bench, scene, tag + "_exact1x", "exact", size)
    e = rmse(point, ref)
    print(f"| {name} | {width}² | exact (1 sample per pixel) | | | {e[0]:.2e} | |", flush=True)
    for m in METHODS:
        row = {}
        for mode in ["draw", "splat"]:
            st, npy = render(bench, scene, f"{tag}_{m}_{mode}", m, size, ["--small-cells", mode])
            row[mode] = (rmse(npy, ref), st)
        d, s = row["draw"], row["splat"]
        missed = d[1].get("cells_between_planes" if m == "slicing" else "cells_covering_no_pixel")
        print(f"| {name} | {width}² | {m} | {s[1]['small_cells']} | {missed} | {d[0][0]:.2e} | {s[0][0]:.2e} | "
              f"{s[0][0] / d[0][0]:.2f} | {d[1]['frame_seconds']:.3f} | {s[1]['frame_seconds']:.3f} |", flush=True)
    return ref


def thresholds(bench, name, scene, aspect, width, ref):
    size = size_of(aspect, width)
    for m, values in THRESHOLDS.items():
        cells = []
        for t in values:
            st, npy = render(bench, scene, f"{name}_{width}_{m}_t{t}", m, size,
                             ["--small-cells", "splat", "--splat-threshold", str(t)])
            cells.append(f"{t}: {rmse(npy, ref)[0]:.2e} ({st['small_cells']})")
        print(f"| {name} | {width}² | {m} | " + " | ".join(cells) + " |", flush=True)


def turntable(scene, out, frames):
    with open(scene) as f:
        s = json.load(f)
    eye, target = np.array(s["camera"]["eye"], float), np.array(s["camera"]["target"], float)
    up = np.array(s["camera"].get("up", [0, 0, 1]), float)
    up /= np.linalg.norm(up)
    base = os.path.dirname(os.path.abspath(scene))
    s["mesh"] = os.path.normpath(os.path.join(base, s["mesh"]))
    paths = []
    for k in range(frames):
        a = 2 * math.pi * k / frames
        d = eye - target
        par = up * np.dot(d, up)
        perp = d - par
        rot = perp * math.cos(a) + np.cross(up, perp) * math.sin(a) + par
        s["camera"]["eye"] = list(target + rot)
        p = os.path.join(out, f"turn_{k:02d}.json")
        with open(p, "w") as f:
            json.dump(s, f)
        paths.append(p)
    return paths


def flicker(bench, name, scene, aspect, width, frames, with_reference):
    size = size_of(aspect, width)
    folder = os.path.join(bench.out, "turntable", name)
    os.makedirs(folder, exist_ok=True)
    views = turntable(scene, folder, frames)
    images = {}
    modes = [("pt-breakpoints", "draw"), ("pt-breakpoints", "splat"), ("pt-breakpoints", "skip"),
             ("slicing", "draw"), ("slicing", "splat"), ("exact", None)]
    for m, mode in modes:
        key = m if mode is None else f"{m} {mode}"
        extra = [] if mode is None else ["--small-cells", mode]
        images[key] = [np.load(render(bench, v, f"turn_{name}_{m}_{mode}_{k}", m, size, extra)[1]).astype(np.float64)
                       for k, v in enumerate(views)]
    if with_reference:
        images["exact 4x box-filtered"] = []
        for k, v in enumerate(views):
            w, h = size
            _, npy = render(bench, v, f"turn_{name}_aa_{k}_ref", "exact", (4 * w, 4 * h))
            images["exact 4x box-filtered"].append(np.load(npy).astype(np.float64).reshape(h, 4, w, 4, 4).mean(axis=(1, 3)))
    region = np.zeros(images["exact"][0].shape[:2], bool)
    for a, b in zip(images["pt-breakpoints splat"], images["pt-breakpoints skip"]):
        region |= np.abs(a - b).max(axis=2) > 1e-3
    for key, frames_ in images.items():
        if key.endswith("skip"):
            continue
        light = np.array([f[region].sum() for f in frames_])
        change = np.abs(np.diff(np.append(light, light[0]))).mean() / light.mean()
        print(f"| {name} | {width}² | {key} | {int(region.sum())} | {change:.2e} | {light.std() / light.mean():.2e} |",
              flush=True)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="bench-out/splat")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--quick", action="store_true", help="256² only, no bluntfin, no 4x turntable reference")
    a = ap.parse_args()
    for sub in ("meshes", "images"):
        os.makedirs(os.path.join(a.out, sub), exist_ok=True)
    bench = Bench(os.path.join(a.build, "bin", "cellproj"), a.out, 1)
    widths = [256] if a.quick else [256, 512]
    todo = scenes(bench, a.quick)
    print("\nError against exact at 8x box-filtered (2 threads)\n")
    print("| mesh | size | method | small cells | missed without splats | RMSE draw | RMSE splat | splat / draw "
          "| s draw | s splat |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    refs = {}
    for name, scene, aspect in todo:
        for w in widths:
            refs[(name, w)] = errors(bench, name, scene, aspect, w)
    print("\nRMSE by --splat-threshold (small cells in brackets)\n")
    for name, scene, aspect in todo:
        for w in widths:
            thresholds(bench, name, scene, aspect, w, refs[(name, w)])
    print("\nFlicker over a 36-frame turntable: mean |L(k+1) - L(k)| / mean L of the light in the small "
          "cells' region; and std(L) / mean L\n")
    print("| mesh | size | method | region pixels | frame-to-frame change | spread |")
    print("|---|---|---|---|---|---|")
    for name, scene, aspect in todo:
        if name in ("graded", "graded-thin", "bluntfin"):
            flicker(bench, name, scene, aspect, 256, 36, not a.quick and name == "graded")


if __name__ == "__main__":
    main()
