#!/usr/bin/python3
"""Frame time in a VTK render window: vtkCellprojVolumeMapper (cellproj.vtk) beside VTK's
vtkProjectedTetrahedraMapper in the same window and the same run, and the CLI's frame time on
the same scene (bench/vtk_window.sh runs it under Xvfb; docs/vtk.md quotes it).
usage: xvfb-run -a python3 bench/vtk_window.py SCENE.json CELLPROJ_EXE [--size N] [--frames F] [--threads T]
Each frame turns the camera 1 degree about the up axis (as `cellproj render --frames`); the median
of frames 2..F is quoted (frame 1 carries the preparation and VTK's set-up).
"""
import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import vtk

from cellproj.vtk import vtkCellprojVolumeMapper
from vtk_peer import scene_camera, volume_property  # (bench/: the scene as VTK objects)


def window_frames(scene, mapper, size, frames):
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(volume_property(scene["transfer_function"]))
    ren = vtk.vtkRenderer()
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(size, size)
    c = ren.GetActiveCamera()
    scene_camera(c, scene["camera"])
    times = []
    for f in range(frames):
        if f:
            c.Azimuth(1.0)
        ren.ResetCameraClippingRange()
        t = time.perf_counter()
        win.Render()
        times.append(time.perf_counter() - t)
    win.Finalize()
    return statistics.median(times[1:]), times[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("exe")
    ap.add_argument("--size", type=int, default=1024)
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    with open(a.scene) as f:
        scene = json.load(f)
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(os.path.dirname(os.path.abspath(a.scene)), scene["mesh"]))
    reader.Update()
    reader.GetOutput().GetPointData().SetActiveScalars(scene["field"])
    rows = []
    for method in ("pt-breakpoints", "pt-linear"):
        m = vtkCellprojVolumeMapper()
        m.SetInputConnection(reader.GetOutputPort())
        m.SetMethod(method)
        m.SetNumberOfThreads(a.threads)
        m.SetScalarModeToUsePointFieldData()
        m.SelectScalarArray(scene["field"])
        window, first = window_frames(scene, m, a.size, a.frames)
        with tempfile.TemporaryDirectory() as d:
            out = subprocess.run([a.exe, "render", a.scene, "--method", method, "--size", "%dx%d" % (a.size, a.size),
                                  "--frames", str(a.frames), "--threads", str(a.threads), "--stats", "-o",
                                  os.path.join(d, "f.png")], check=True, capture_output=True, text=True)
        cli = json.loads((out.stdout + out.stderr).strip().splitlines()[-1])["frame_seconds"]
        rows.append((method, window, first, cli))
    pt = vtk.vtkProjectedTetrahedraMapper()
    pt.SetInputConnection(reader.GetOutputPort())
    pt_window, _ = window_frames(scene, pt, a.size, a.frames)
    cells = reader.GetOutput().GetNumberOfCells()
    print("%d cells, %dx%d, %d threads, median of frames 2..%d" % (cells, a.size, a.size, a.threads, a.frames))
    print("%-16s %10s %10s %10s %14s %14s" % ("", "window s", "first s", "CLI s", "window / CLI", "window / VTK PT"))
    for method, window, first, cli in rows:
        print("%-16s %10.3f %10.3f %10.3f %14.2f %14.2f" % (method, window, first, cli, window / cli, window / pt_window))
    print("%-16s %10.3f" % ("VTK PT", pt_window))


if __name__ == "__main__":
    main()
