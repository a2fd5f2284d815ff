"""The speed/accuracy benchmark (docs/accuracy.md and the measured parts of docs/methods.md). Run through bench/run, which installs what it
needs and calls this with Debian's python3 (numpy, matplotlib and VTK's Python module live there).

For every benchmark mesh and image size: `exact` (canonical-tets, the field the projection methods
render; and isoparametric where the mesh has other cells), every projection method with the `auto`
sort, `pt-breakpoints` with each other sort (so the error a sort causes shows in the picture),
slicing at 256 and 1024 planes (bench/slicing measures its convergence), and
VTK's three unstructured-grid mappers on the same scene; time per frame (median, min and max over
repeated frames), cells per second, RMSE and largest error of the premultiplied float image against
exact, and the sort's order violations counted by the ray-traced oracle (`sortbench --check`, four
views spread over a sphere at the same image size). Writes DIR/results.csv, DIR/plots/ (error
against time per mesh, log-log) and DIR/strips/ (pictures and difference images), and prints the
rows as a Markdown table; then the opacity table's error by size and the thread speed-up.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
METHODS = ["pt-linear", "pt-table", "pt-analytic", "pt-breakpoints"]
OTHER_SORTS = ["centroid", "mpvo", "mpvo-abuffer"]
SLICING = [(256, "sampled"), (1024, "sampled"), (1024, "preintegrated")]
PEERS = {"vtk-pt": "pt", "vtk-raycast": "raycast", "vtk-zsweep": "zsweep"}
PEER_CPU_LIMIT = 30_000  # cells: the CPU mappers take tens of seconds per frame beyond this
HEADER = ("| mesh | cells | method | sort (slicing: planes) | size | median s | min s | max s | cells/s | RMSE | max error | violations |\n"
          "|---|---|---|---|---|---|---|---|---|---|---|---|")
COLUMNS = ["mesh", "cells", "method", "sort", "width", "height", "median_seconds", "min_seconds", "max_seconds",
           "cells_per_second", "rmse", "max_abs", "violations"]


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{p.stderr[-2000:]}")
    return p


class Bench:
    def __init__(self, exe, out, frames):
        self.exe, self.out, self.frames = exe, out, frames
        self.rows = []

    def info(self, mesh):
        return json.loads(run([self.exe, "info", mesh, "--json"]).stdout)

    def render(self, scene, tag, method, size, frames, extra=()):
        npy = os.path.join(self.out, "images", f"{tag}.npy")
        cmd = [self.exe, "render", scene, "--method", method, "--size", f"{size}x{size}", "--frames", str(frames),
               "-o", npy[:-4] + ".png", "--npy", npy, "--stats", *extra]
        return json.loads(run(cmd).stderr.strip().splitlines()[-1]), npy

    def peer(self, scene, tag, mapper, size):
        prefix = os.path.join(self.out, "images", tag)
        cmd = ["xvfb-run", "-a", "-s", "-screen 0 2100x2100x24", sys.executable,
               os.path.join(ROOT, "bench", "vtk_peer.py"), scene, "--size", str(size), "--frames",
               str(self.frames + 1), "--mapper", mapper, "--out", prefix]
        return json.loads(run(cmd).stdout.strip().splitlines()[-1]), prefix + ".npy"

    def violations(self, mesh, size):
        p = run([self.exe, "sortbench", mesh, "--sorts", "auto,centroid,mpvo,mpvo-abuffer", "--views", "4",
                 "--size", f"{size}x{size}", "--check", "--json"])
        out = {}
        for line in p.stdout.splitlines():
            j = json.loads(line)
            out[j["sort"]] = j["violations"]
        return out

    def add(self, **row):
        self.rows.append(row)
        self.print_row(row)

    @staticmethod
    def print_row(r):
        err = ("reference | reference" if r["method"] == "exact" else "— | —") if r["rmse"] == "" else \
            f"{r['rmse']:.2e} | {r['max_abs']:.2e}"
        print(f"| {r['mesh']} | {r['cells']} | {r['method']} | {r['sort']} | {r['width']}² | {r['median_seconds']:.3f} | "
              f"{r['min_seconds']:.3f} | {r['max_seconds']:.3f} | {r['cells_per_second']:.3g} | {err} | {r['violations']} |",
              flush=True)


def error(a_npy, b_npy, rgb_only=False):
    a, b = np.load(a_npy), np.load(b_npy)
    if rgb_only:  # a peer's 8-bit RGB on black against our premultiplied RGB
        a, b = np.clip(a[..., :3], 0, 1), np.clip(b[..., :3], 0, 1)
    d = np.abs(a.astype(np.float64) - b.astype(np.float64))
    return float(np.sqrt((d * d).mean())), float(d.max())


def timing(st, cells):
    """A row's time columns from cellproj's --stats (frame_seconds: the median frame)."""
    return dict(median_seconds=st["frame_seconds"], min_seconds=st["min_frame_seconds"],
                max_seconds=st["max_frame_seconds"], cells_per_second=cells / st["frame_seconds"])


def synthetic(bench, kind, n, name):
    mesh = os.path.join(bench.out, "meshes", f"{name}.vtu")
    if not os.path.exists(mesh):
        run([bench.exe, "generate", kind, "-n", str(n), "-o", mesh])
    info = bench.info(mesh)
    field, (lo, hi) = next(iter(info["fields"].items()))
    b = info["bounds"]
    lo3, hi3 = np.array(b[0::2]), np.array(b[1::2])
    centre, diag = (lo3 + hi3) / 2, float(np.linalg.norm(hi3 - lo3))
    at = lambda t: lo + t * (hi - lo)
    k = 6.0 / diag  # an optical depth of a few across the mesh where the field is high
    eye = centre + 1.9 * diag * np.array([0.55, -0.7, 0.45]) / np.linalg.norm([0.55, -0.7, 0.45])
    scene = {"mesh": os.path.basename(mesh), "field": field,
             "transfer_function": {
                 "color": [[at(0), 0.15, 0.25, 0.8], [at(0.45), 0.3, 0.75, 0.8], [at(0.7), 0.95, 0.85, 0.35],
                           [at(1), 1.0, 0.3, 0.1]],
                 "extinction": [[at(0), 0.1 * k], [at(0.5), 0.4 * k], [at(0.75), 2.0 * k], [at(1), 1.0 * k]]},
             "camera": {"projection": "perspective", "eye": list(eye), "target": list(centre), "up": [0, 0, 1],
                        "fov_y": 35}}
    path = os.path.join(bench.out, "meshes", f"{name}.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return name, path, mesh, info


def measure(bench, name, scene, mesh, info, size, peers):
    cells = info["cells"]
    mixed = any(t != "tetra" and c > 0 for t, c in info["cells_by_type"].items())
    tag = f"{name}_{size}"
    ref_stats, ref = bench.render(scene, tag + "_exact", "exact", size, 1, ["--interpolation", "canonical-tets"])
    base = dict(mesh=name, cells=cells, width=size, height=size)
    t = ref_stats["frame_seconds"]
    bench.add(**base, method="exact", sort="", median_seconds=t, min_seconds=t, max_seconds=t,
              cells_per_second=cells / t, rmse="", max_abs="", violations="")
    if mixed:
        st, iso = bench.render(scene, tag + "_iso", "exact", size, 1)
        e = error(iso, ref)
        t = st["frame_seconds"]
        bench.add(**base, method="exact-isoparametric", sort="", median_seconds=t, min_seconds=t, max_seconds=t,
                  cells_per_second=cells / t, rmse=e[0], max_abs=e[1], violations="")
        # Whole cells (the default --tetrahedralize problem), against the isoparametric picture:
        # the ladder below splits every cell (--tetrahedralize all) to compare with its reference.
        st, npy = bench.render(scene, tag + "_whole", "pt-breakpoints", size, bench.frames)
        e = error(npy, iso)
        bench.add(**base, method="pt-breakpoints-whole-vs-iso", sort=st["sort"],
                  **timing(st, cells), rmse=e[0], max_abs=e[1], violations="")
    # sortbench sorts the cells as given; the projection sorts the canonical tetrahedra, so the
    # oracle's count describes the rendered order only on tetrahedral meshes.
    viol = {} if mixed else bench.violations(mesh, size)
    runs = [(m, "auto") for m in METHODS] + [("pt-breakpoints", s) for s in OTHER_SORTS]
    for method, sort in runs:
        st, npy = bench.render(scene, f"{tag}_{method}_{sort}", method, size, bench.frames,
                               ["--sort", sort, "--tetrahedralize", "all"])
        e = error(npy, ref)
        bench.add(**base, method=method, sort=st["sort"] if sort == "auto" else sort, **timing(st, cells),
                  rmse=e[0], max_abs=e[1], violations=viol.get(sort, ""))
    # Small cells splatted (bench/splat measures them against the anti-aliased reference; here the
    # row says how far splats move the picture from the point-sampled model, and what they cost).
    st, npy = bench.render(scene, f"{tag}_pt-breakpoints_splat", "pt-breakpoints", size, bench.frames,
                           ["--tetrahedralize", "all", "--small-cells", "splat"])
    e = error(npy, ref)
    bench.add(**base, method="pt-breakpoints-splat", sort=st["sort"], **timing(st, cells), rmse=e[0],
              max_abs=e[1], violations="")
    # Slicing (no sort; bench/slicing has its convergence): the sort column gives the plane count.
    for n, integral in SLICING:
        st, npy = bench.render(scene, f"{tag}_slicing_{integral}_{n}", "slicing", size, bench.frames,
                               ["--slices", str(n), "--slice-integral", integral, "--tetrahedralize", "all"])
        e = error(npy, ref)
        bench.add(**base, method=f"slicing-{integral}", sort=f"{n} slices", **timing(st, cells), rmse=e[0],
                  max_abs=e[1], violations="")
    # Iso-surfaces with the volume (methods.md): two semi-transparent surfaces at 45% and 70% of the
    # field's range, each --iso-mode against ordered (the exact order along each ray).
    with open(scene) as f:
        field = json.load(f).get("field")
    lo, hi = info["fields"][field] if field else next(iter(info["fields"].values()))
    iso = ["--iso", f"{lo + 0.45 * (hi - lo)}:0.3,0.5,1,0.35", "--iso", f"{lo + 0.7 * (hi - lo)}:1,0.5,0.2,0.5"]
    _, ordered = bench.render(scene, f"{tag}_iso_ordered", "exact", size, 1, iso)
    for mode in ("ordered", "blend2", "oit3", "oit4"):
        st, npy = bench.render(scene, f"{tag}_iso_{mode}", "exact", size, 1, iso + ["--iso-mode", mode])
        e = error(npy, ordered)
        t = st["frame_seconds"]
        bench.add(**base, method=f"exact-iso-{mode}", sort="vs ordered", median_seconds=t, min_seconds=t,
                  max_seconds=t, cells_per_second=cells / t, rmse=e[0], max_abs=e[1], violations="")
    if not peers or not mesh.endswith(".vtu"):
        return
    for method, mapper in PEERS.items():
        if mapper != "pt" and cells > PEER_CPU_LIMIT:
            continue
        st, npy = bench.peer(scene, f"{tag}_{method}", mapper, size)
        e = error(npy, ref, rgb_only=True)
        bench.add(**base, method=method, sort="", median_seconds=st["median_seconds"], min_seconds=st["min_seconds"],
                  max_seconds=st["max_seconds"], cells_per_second=cells / st["median_seconds"], rmse=e[0],
                  max_abs=e[1], violations="")


def ladder_rows(bench, name, scene, info, size, what):
    """Each projection method against exact (canonical tetrahedra) on `scene`, as rows METHOD-WHAT."""
    cells, tag = info["cells"], f"{name}_{size}_{what}"
    base = dict(mesh=name, cells=cells, width=size, height=size)
    _, ref = bench.render(scene, tag + "_exact", "exact", size, 1, ["--interpolation", "canonical-tets"])
    for method in METHODS:
        st, npy = bench.render(scene, f"{tag}_{method}", method, size, bench.frames, ["--tetrahedralize", "all"])
        e = error(npy, ref)
        bench.add(**base, method=f"{method}-{what}", sort=st["sort"], **timing(st, cells), rmse=e[0], max_abs=e[1],
                  violations="")


def log_scale_rows(bench, name, scene_path, info, size):
    """The field on a log scale (--log, docs/accuracy.md "Log scales"): the scene's field floored at
    1e-3 of its largest value, its transfer function over three decades; each projection method and
    slicing against exact on that log field."""
    with open(scene_path) as f:
        scene = json.load(f)
    field = scene["field"]
    hi = info["fields"][field][1]
    floor, k = 1e-3 * hi, 6.0 / float(np.linalg.norm(np.array(info["bounds"][1::2]) - np.array(info["bounds"][0::2])))
    scene.update({"log": True, "log_floor": floor, "transfer_function": {
        "color_preset": {"name": "viridis"},
        "extinction": [[floor, 0.05 * k], [10 * floor, 0.6 * k], [100 * floor, 2.0 * k], [hi, 0.8 * k]]}})
    log_scene = os.path.join(os.path.dirname(scene_path), f"{name}_log.json")
    with open(log_scene, "w") as f:
        json.dump(scene, f)
    ladder_rows(bench, name, log_scene, info, size, "log")


def two_field_rows(bench, name, scene_path, info, size):
    """Colour by one field, extinction by another (--opacity-field, docs/accuracy.md "Two fields"):
    the scene's field as its own opacity field, so the picture is the one-field model drawn the
    two-field way (each cell ray cast over its canonical tetrahedra); pt-breakpoints and pt-analytic
    against exact with two fields, as rows METHOD-2fields."""
    with open(scene_path) as f:
        scene = json.load(f)
    scene["opacity_field"] = scene["field"]
    two_scene = os.path.join(os.path.dirname(scene_path), f"{name}_2fields.json")
    with open(two_scene, "w") as f:
        json.dump(scene, f)
    cells, tag = info["cells"], f"{name}_{size}_2fields"
    base = dict(mesh=name, cells=cells, width=size, height=size)
    _, ref = bench.render(two_scene, tag + "_exact", "exact", size, 1, [])
    for method in ("pt-breakpoints", "pt-analytic"):
        st, npy = bench.render(two_scene, f"{tag}_{method}", method, size, bench.frames, [])
        e = error(npy, ref)
        bench.add(**base, method=f"{method}-2fields", sort=st["sort"], **timing(st, cells), rmse=e[0], max_abs=e[1],
                  violations="")


def cell_data_rows(bench, name, scene_path, mesh, info, size):
    """Cell data (--cell-data cells, the default: each cell's value constant over it, docs/accuracy.md
    "Cell data"): the mesh given a cell field, each cell the scene's transfer-function range sampled
    by a smooth function at its centre; each projection method against exact."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh)
    reader.Update()
    grid = reader.GetOutput()
    centres = vtk.vtkCellCenters()
    centres.SetInputData(grid)
    centres.Update()
    x = vtk_to_numpy(centres.GetOutput().GetPoints().GetData())
    lo3, hi3 = np.array(info["bounds"][0::2]), np.array(info["bounds"][1::2])
    u = (x - lo3) / np.maximum(hi3 - lo3, 1e-300)
    with open(scene_path) as f:
        scene = json.load(f)
    lo, hi = info["fields"][scene["field"]]
    values = lo + (hi - lo) * (0.5 + 0.5 * np.sin(5 * u[:, 0]) * np.cos(4 * u[:, 1] + 2 * u[:, 2]))
    array = numpy_to_vtk(np.ascontiguousarray(values))
    array.SetName("cells")
    grid.GetCellData().AddArray(array)
    cell_mesh = os.path.join(os.path.dirname(scene_path), f"{name}_cells.vtu")
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetFileName(cell_mesh)
    writer.SetInputData(grid)
    writer.Write()
    scene.update({"mesh": os.path.basename(cell_mesh), "field": "cells"})
    cell_scene = os.path.join(os.path.dirname(scene_path), f"{name}_cells.json")
    with open(cell_scene, "w") as f:
        json.dump(scene, f)
    ladder_rows(bench, name, cell_scene, info, size, "cells")


def measure_speed(bench, name, scene, mesh, info, size, peers):
    """--speed-only: each projection method and VTK's projected tetrahedra, timed in the same run
    (no reference, so no error; the full run measures that)."""
    base = dict(mesh=name, cells=info["cells"], width=size, height=size)
    for method in METHODS:
        st, _ = bench.render(scene, f"{name}_{size}_{method}_speed", method, size, bench.frames,
                             ["--tetrahedralize", "all"])
        bench.add(**base, method=method, sort=st["sort"], **timing(st, info["cells"]), rmse="", max_abs="",
                  violations="")
    if peers and mesh.endswith(".vtu"):
        st, _ = bench.peer(scene, f"{name}_{size}_vtk-pt_speed", "pt", size)
        bench.add(**base, method="vtk-pt", sort="", median_seconds=st["median_seconds"],
                  min_seconds=st["min_seconds"], max_seconds=st["max_seconds"],
                  cells_per_second=info["cells"] / st["median_seconds"], rmse="", max_abs="", violations="")


def report(path):
    """The tables of an earlier run, from its results.csv."""
    bench = Bench("", os.path.dirname(path), 0)
    with open(path) as f:
        for r in csv.DictReader(f):
            for k in ("cells", "width", "height"):
                r[k] = int(r[k])
            for k in ("median_seconds", "min_seconds", "max_seconds", "cells_per_second", "rmse", "max_abs"):
                r[k] = float(r[k]) if r[k] != "" else ""
            bench.rows.append(r)
    print(HEADER)
    for r in list(bench.rows):
        bench.print_row(r)
    summary(bench)
    peer_ratios(bench)


def compare(old_path, new_path):
    """Whether two runs' errors agree: each row's RMSE, largest error and violation count (the first
    row of each mesh, method, sort and size), with the count of values compared and those that differ."""
    def rows(path):
        out = {}
        for r in csv.DictReader(open(path)):
            out.setdefault((r["mesh"], r["method"], r["sort"], r["width"]), r)
        return out
    old, new = rows(old_path), rows(new_path)
    same = differ = 0
    largest = 0.0  # the largest relative difference of a value that differs
    for key, r in new.items():
        if key not in old:
            print("only in the new run:", key)
            continue
        for c in ("rmse", "max_abs", "violations"):
            if old[key][c] == r[c]:
                same += 1
                continue
            differ += 1
            try:
                a, b = float(old[key][c]), float(r[c])
                largest = max(largest, abs(a - b) / max(abs(a), abs(b)))
            except ValueError:
                largest = float("inf")
            print(f"{key} {c}: {old[key][c]} -> {r[c]}")
    print(f"{same} values the same, {differ} different (largest relative difference {largest:.1e}), "
          f"over {len(new)} rows ({len(old)} before)")


def model_check(bench):
    """The optical model handed to VTK, checked where the answer is known: a slab of constant
    extinction 1 and thickness 2 seen straight down, 1 - e^-2 = 0.8647 at its centre."""
    mesh = os.path.join(bench.out, "meshes", "slab.vtu")
    run([bench.exe, "generate", "box-tets", "-n", "4", "-o", mesh])
    scene = os.path.join(bench.out, "meshes", "slab.json")
    with open(scene, "w") as f:
        json.dump({"mesh": "slab.vtu", "field": "scalar",
                   "transfer_function": {"color": [[0, 1, 1, 1], [1, 1, 1, 1]], "extinction": [[0, 1.0], [1, 1.0]]},
                   "camera": {"projection": "orthographic", "eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0],
                              "height": 3}}, f)
    print("\nThe optical model given to VTK, on a constant slab (centre pixel, exact 1 - e^-2 = 0.8647):\n")
    print("| renderer | centre value |")
    print("|---|---|")
    _, npy = bench.render(scene, "slab_exact", "exact", 64, 1)
    print(f"| cellproj exact | {np.load(npy)[32, 32, 0]:.4f} |")
    for method, mapper in PEERS.items():
        _, npy = bench.peer(scene, f"slab_{method}", mapper, 64)
        print(f"| {method} | {np.load(npy)[32, 32, 0]:.4f} |", flush=True)


def first_rows(bench, mesh, width):
    """Each method's first row on a mesh at a size: for the projection methods, their `auto` sort."""
    first = {}
    for x in bench.rows:
        if x["mesh"] == mesh and x["width"] == width:
            first.setdefault(x["method"], x)
    return first


def summary(bench):
    """docs/accuracy.md's summary: per mesh and size, each projection method's median time and RMSE
    with the `auto` sort (the first row of each method), exact's time and VTK's projected tetrahedra."""
    ours = METHODS
    print("\n| mesh | cells | size | " + " | ".join(f"{m} s / RMSE" for m in ours) + " | exact s | vtk-pt s / RMSE |")
    print("|---|---|---|" + "---|" * (len(ours) + 2))
    seen = []
    for r in bench.rows:
        if (r["mesh"], r["width"]) not in seen:
            seen.append((r["mesh"], r["width"]))
    for mesh, width in seen:
        first = first_rows(bench, mesh, width)
        cell = lambda m: (f"{first[m]['median_seconds']:.3f} / {first[m]['rmse']:.1e}"
                          if m in first and first[m]["rmse"] != "" else "—")
        exact = f"{first['exact']['median_seconds']:.3f}" if "exact" in first else "—"
        cells = next(iter(first.values()))["cells"]
        print(f"| {mesh} | {cells} | {width}² | " + " | ".join(cell(m) for m in ours) + f" | {exact} | {cell('vtk-pt')} |")


def peer_ratios(bench):
    """Each VTK mapper's time over ours (above 1: ours is faster), per mesh and size."""
    ours = METHODS
    print("\n| mesh | size | peer | peer s | peer RMSE | " + " | ".join(f"peer / {m}" for m in ours) + " |")
    print("|---|---|---|---|---|" + "---|" * len(ours))
    for r in bench.rows:
        if not r["method"].startswith("vtk-"):
            continue
        mine = first_rows(bench, r["mesh"], r["width"])
        ratios = " | ".join(f"{r['median_seconds'] / mine[m]['median_seconds']:.2f}" if m in mine else "" for m in ours)
        rmse = f"{r['rmse']:.1e}" if r["rmse"] != "" else "—"
        print(f"| {r['mesh']} | {r['width']}² | {r['method']} | {r['median_seconds']:.3f} | {rmse} | {ratios} |")


def sweeps(bench, default_scene, big):
    """The opacity table's own error by size, and the thread speed-up with bit-identity."""
    base = "default_512"
    bench.render(default_scene, f"{base}_table8192", "pt-table", 512, 1, ["--table-size", "8192"])
    ref8192 = os.path.join(bench.out, "images", f"{base}_table8192.npy")
    print("\nOpacity table size (pt-table, default scene, 512²): its own error against an 8192² table\n")
    print("| table size | RMSE | max error |")
    print("|---|---|---|")
    for n in [8, 32, 128, 256, 512, 2048]:
        _, npy = bench.render(default_scene, f"{base}_table{n}", "pt-table", 512, 1, ["--table-size", str(n)])
        e = error(npy, ref8192)
        print(f"| {n} | {e[0]:.1e} | {e[1]:.1e} |", flush=True)
    print("\nThreads (pt-breakpoints, 1024², median of 3 frames):\n")
    print("| mesh | 1 thread s | 2 threads s | speed-up | same bits |")
    print("|---|---|---|---|---|")
    for name, scene in big:
        t = {}
        for n in (1, 2):
            t[n] = bench.render(scene, f"{name}_threads{n}", "pt-breakpoints", 1024, 3, ["--threads", str(n)])
        same = error(t[1][1], t[2][1])[1] == 0
        print(f"| {name} | {t[1][0]['frame_seconds']:.3f} | {t[2][0]['frame_seconds']:.3f} | "
              f"{t[1][0]['frame_seconds'] / t[2][0]['frame_seconds']:.2f}× | {'yes' if same else 'NO'} |", flush=True)


def plots(bench):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(os.path.join(bench.out, "plots"), exist_ok=True)
    for mesh in sorted({r["mesh"] for r in bench.rows}):
        fig, ax = plt.subplots(figsize=(6.4, 4.4))
        for r in bench.rows:
            if r["mesh"] != mesh or r["rmse"] == "" or (r["method"] == "pt-breakpoints" and r["sort"] in OTHER_SORTS):
                continue
            label = f"{r['method']} {r['width']}²"
            ax.scatter(r["median_seconds"], max(r["rmse"], 1e-9), marker="s" if r["method"].startswith("vtk") else "o")
            ax.annotate(label, (r["median_seconds"], max(r["rmse"], 1e-9)), fontsize=7, xytext=(3, 3),
                        textcoords="offset points")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("seconds per frame (2 cores)")
        ax.set_ylabel("RMSE against exact")
        ax.set_title(f"{mesh}: error against time")
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(bench.out, "plots", f"{mesh}.png"), dpi=110)
        plt.close(fig)


def strips(bench, size):
    """Per mesh: exact and each method's picture on black, with |difference| x 20 below."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    os.makedirs(os.path.join(bench.out, "strips"), exist_ok=True)
    img = lambda tag: os.path.join(bench.out, "images", tag + ".npy")
    for mesh in sorted({r["mesh"] for r in bench.rows}):
        tag = f"{mesh}_{size}"
        if not os.path.exists(img(tag + "_exact")):
            continue
        ref = np.clip(np.load(img(tag + "_exact"))[..., :3], 0, 1)
        cols = [("exact", ref, None)]
        for m in METHODS:
            a = np.clip(np.load(img(f"{tag}_{m}_auto"))[..., :3], 0, 1)
            cols.append((m, a, np.clip(20 * np.abs(a - ref), 0, 1)))
        if os.path.exists(img(f"{tag}_vtk-pt")):
            a = np.load(img(f"{tag}_vtk-pt"))
            cols.append(("vtk-pt", a, np.clip(20 * np.abs(a - ref), 0, 1)))
        fig, axes = plt.subplots(2, len(cols), figsize=(2.2 * len(cols), 4.6))
        for k, (name, a, d) in enumerate(cols):
            axes[0][k].imshow(a)
            axes[0][k].set_title(name, fontsize=8)
            axes[1][k].imshow(d if d is not None else np.zeros_like(a))
            for ax in (axes[0][k], axes[1][k]):
                ax.axis("off")
        axes[1][0].set_title("|difference| x 20", fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(bench.out, "strips", f"{mesh}.png"), dpi=100)
        plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="512² only, meshes up to ~100k cells, 2 frames: ~10 min")
    ap.add_argument("--out", default="bench-out")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--no-peers", action="store_true", help="skip VTK's mappers")
    ap.add_argument("--report", metavar="CSV", help="print the tables of an earlier run's results.csv and stop")
    ap.add_argument("--compare", nargs=2, metavar=("OLD_CSV", "NEW_CSV"),
                    help="whether two runs' errors (RMSE, largest error, violations) are the same, row by row")
    ap.add_argument("--speed-only", action="store_true",
                    help="each projection method against VTK's projected tetrahedra, time only, every mesh (~15 min)")
    ap.add_argument("--sweeps-only", action="store_true", help="only the table-size and thread sweeps (~3 min)")
    ap.add_argument("--fields-only", action="store_true",
                    help="only the log-scale, cell-data and two-field rows (tets-100k and mixed, 512², ~2 min)")
    a = ap.parse_args()
    if a.report:
        report(a.report)
        return
    if a.compare:
        compare(*a.compare)
        return
    for sub in ("meshes", "images"):
        os.makedirs(os.path.join(a.out, sub), exist_ok=True)
    # --speed-only times 6 frames (VTK 7, its first dropped): this machine's speed drifts from one
    # run to the next, and more frames steady both sides' medians.
    bench = Bench(os.path.join(a.build, "bin", "cellproj"), a.out, 6 if a.speed_only else 2 if a.quick else 3)
    default_scene = os.path.join(ROOT, "scenes", "default.json")
    if a.sweeps_only:
        sweeps(bench, default_scene, [("default", default_scene), synthetic(bench, "box-tets", 26, "tets-100k")[:2]])
        return
    if a.fields_only:
        print(HEADER)
        for name, scene, mesh, info in [synthetic(bench, "box-tets", 26, "tets-100k"), synthetic(bench, "mixed", 8, "mixed")]:
            log_scale_rows(bench, name, scene, info, 512)
            cell_data_rows(bench, name, scene, mesh, info, 512)
            two_field_rows(bench, name, scene, info, 512)
        return
    meshes = [synthetic(bench, "box-tets", 12, "tets-10k"), synthetic(bench, "box-tets", 26, "tets-100k"),
              synthetic(bench, "mixed", 8, "mixed"), synthetic(bench, "swirl", 16, "curvilinear")]
    if not a.quick:
        meshes.append(synthetic(bench, "box-tets", 56, "tets-1m"))
    shared = os.path.join(ROOT, "..", "shared", "data")
    if os.path.isdir(shared):
        names = ["post_tets", "static_mixer", "bluntfin"] + ([] if a.quick else ["combustion_chamber", "disk_out_ref"])
        for n in names:
            scene = os.path.join(ROOT, "bench", "scenes", n + ".json")
            with open(scene) as f:
                mesh = os.path.normpath(os.path.join(os.path.dirname(scene), json.load(f)["mesh"]))
            meshes.append((n, scene, mesh, bench.info(mesh)))
    sizes = [512] if a.quick else [512, 1024]
    if a.speed_only:
        for name, scene, mesh, info in meshes:
            for size in sizes:
                measure_speed(bench, name, scene, mesh, info, size, not a.no_peers)
        peer_ratios(bench)
        return
    print(HEADER)
    for name, scene, mesh, info in meshes:
        for size in sizes:
            measure(bench, name, scene, mesh, info, size, not a.no_peers)
    for name, scene, mesh, info in meshes:
        if name in ("tets-100k", "mixed"):
            log_scale_rows(bench, name, scene, info, sizes[0])
            cell_data_rows(bench, name, scene, mesh, info, sizes[0])
            two_field_rows(bench, name, scene, info, sizes[0])
    with open(os.path.join(a.out, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(bench.rows)
    summary(bench)
    peer_ratios(bench)
    if not a.no_peers:
        model_check(bench)
    big = [("default", default_scene)] + [m[:2] for m in meshes if m[0] in ("tets-100k", "tets-1m")]
    sweeps(bench, default_scene, big)
    plots(bench)
    strips(bench, 512)
    print(f"\nwrote {a.out}/results.csv, {a.out}/plots/, {a.out}/strips/")


if __name__ == "__main__":
    main()
