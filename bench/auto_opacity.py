"""How much of each default picture is neither an opaque slab nor an invisible haze (docs/cli.md,
"--opacity auto"): for every dataset of ../shared/data and every generated mesh, the default
picture of `cellproj render MESH` (its field as listed below, every other option default) at
256², and the fraction of the mesh's footprint whose alpha lies in (0.05, 0.95). The footprint is
where a faint flat extinction leaves any alpha. Each opacity given on the command line is a
column (default: ramp, the old default, against auto, the new one).

usage: /usr/bin/python3 bench/auto_opacity.py [--build build] [--opacity ramp auto ...] [--out DIR]
                                              [--sheet PNG]
--sheet writes the pictures of ../shared/data side by side, one column per opacity (through the
Python module of the build).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared", "data")
# One file per dataset (the others are the same mesh in another format) and the field a user of
# it would look at first.
DATASETS = [
    ("nasa_bluntfin/bluntfin_hex.vtu", "Density"),
    ("nasa_combustion_chamber/comb_hex.vtu", "Density"),
    ("cgns_heating_coil/heating_coil_fluid.vtu", "Temperature"),
    ("cgns_heating_coil/heating_coil_solid.vtu", "Temperature"),
    ("cgns_static_mixer/static_mixer.vtu", "Temperature"),
    ("exodus_disk_out_ref/disk_out_ref.ex2", "Temp"),
    ("vtkdata_can/can.vtu", "EQPS"),
    ("vtkdata_hexa/hexa.vtu", "scalars"),
    ("vtkdata_notch_stress/notch_stress.vtu", "Nodal Stress:von_mises"),
    ("vtkdata_post_tets/post_tets.vtu", "Pressure"),
    ("vtkdata_tetramesh/tetramesh.vtu", "scalars"),
    ("vtkdata_angular_sector/angular_sector.vtu", "PointId"),
    ("vtk_small_cell_samples/Tetrahedron.vtu", "Polynomial"),
    ("vtk_small_cell_samples/Wedge.vtu", "Polynomial"),
    ("vtk_small_cell_samples/elements.vtu", "pointScalars"),
    ("vtk_small_cell_samples/uGridEx.vtk", "scalars"),
]
GENERATED = [("box", 16), ("box-tets", 12), ("swirl", 12), ("swirl-tets", 8), ("mixed", 8), ("graded", 8),
             ("graded-tets", 6)]


def picture(exe, mesh, field, out, *args):
    """The premultiplied RGBA of `cellproj render MESH --size 256x256 ARGS`."""
    npy = os.path.join(out, "a.npy")
    cmd = [exe, "render", mesh, "--size", "256x256", "--npy", npy, "-o", os.path.join(out, "a.png"), *args]
    if field:
        cmd += ["--field", field]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"failed: {' '.join(cmd)}\n{p.stderr}")
    return np.load(npy)


def write_sheet(path, build, tiles, columns):
    """tiles: rows of premultiplied RGBA pictures, `columns` to a row, halved and set side by side."""
    sys.path.insert(0, os.path.join(build, "python"))
    import cellproj
    rows = [np.concatenate([t[::2, ::2] for t in tiles[r:r + columns]], axis=1) for r in range(0, len(tiles), columns)]
    cellproj.write_png(np.ascontiguousarray(np.concatenate(rows, axis=0), dtype=np.float32), path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--opacity", nargs="+", default=["ramp", "auto"])
    ap.add_argument("--out", help="keep each picture here as NAME_OPACITY.png")
    ap.add_argument("--sheet", help="the pictures of ../shared/data side by side, a column per opacity, as a PNG")
    a = ap.parse_args()
    exe = os.path.join(a.build, "bin", "cellproj")
    out = tempfile.mkdtemp()
    cases = [(os.path.join(SHARED, f), field, f) for f, field in DATASETS if os.path.exists(os.path.join(SHARED, f))]
    for kind, n in GENERATED:
        mesh = os.path.join(out, f"{kind}.vtu")
        subprocess.run([exe, "generate", kind, "-n", str(n), "-o", mesh], check=True, capture_output=True)
        cases.append((mesh, "", f"generated {kind} -n {n}"))
    print("| mesh | field | " + " | ".join(a.opacity) + " |")
    print("|---|---|" + "---|" * len(a.opacity))
    worst = {o: 1.0 for o in a.opacity}
    tiles = []
    for mesh, field, name in cases:
        footprint = picture(exe, mesh, field, out, "--opacity", "flat", "--depth", "0.01")[..., 3] > 0
        row = []
        for o in a.opacity:
            image = picture(exe, mesh, field, out, "--opacity", o)
            al = image[..., 3]
            if not name.startswith("generated"):
                tiles.append(image)
            if a.out:
                os.makedirs(a.out, exist_ok=True)
                tag = name.replace("/", "_").replace(" ", "_")
                subprocess.run(["cp", os.path.join(out, "a.png"), os.path.join(a.out, f"{tag}_{o}.png")], check=True)
            share = float(np.mean((al[footprint] > 0.05) & (al[footprint] < 0.95)))
            worst[o] = min(worst[o], share)
            row.append(f"{share:.2f}")
        print(f"| {name} | {field or '(its only one)'} | " + " | ".join(row) + " |")
    print("| worst | | " + " | ".join(f"{worst[o]:.2f}" for o in a.opacity) + " |")
    if a.sheet:
        write_sheet(a.sheet, a.build, tiles, 4 * len(a.opacity))


if __name__ == "__main__":
    main()
