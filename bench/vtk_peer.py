#!/usr/bin/python3
"""A VTK unstructured-grid volume mapper on one of our scenes, for bench/run (run.py).

usage: xvfb-run -a /usr/bin/python3 bench/vtk_peer.py SCENE.json --size N --frames F --out PREFIX
                [--mapper pt|raycast|zsweep]

pt: vtkProjectedTetrahedraMapper (OpenGL); raycast: vtkUnstructuredGridVolumeRayCastMapper and
zsweep: vtkUnstructuredGridVolumeZSweepMapper (both on the CPU, the window only shows the image).

Renders the scene's mesh (tetrahedralized by vtkDataSetTriangleFilter if it has other cells) with
the same camera and the same optical model as cellproj, F frames turning 1 degree about the up axis
(as `cellproj render --frames`), and prints one JSON line: median/min/max seconds of frames 2..F
(frame 1 carries VTK's set-up) and the picture as PREFIX.npy (float RGB composited on black, row 0
at the top).

The optical model: VTK's unstructured-grid mappers read the scalar opacity value o(s) as an
attenuation o/u per unit length, u the ScalarOpacityUnitDistance (a segment of length l gets
1 - exp(-o l / u); vtkglProjectedTetrahedraFS.glsl, and checked here on a constant slab). So our
extinction kappa(s) becomes o(s) = kappa(s) u with u = 1 / max(kappa), which keeps o in [0, 1]:
the same control points, since the map is linear. Colour: the same control points.
"""
import argparse
import json
import os
import statistics
import sys
import time

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def volume_property(tf):
    """A scene's transfer function as VTK's: the same colour points, extinction kappa as opacity
    kappa u per unit distance u = 1 / max(kappa) (the module docstring's mapping)."""
    kmax = max(k for _, k in tf["extinction"])
    unit = 1.0 / kmax if kmax > 0 else 1.0
    opacity = vtk.vtkPiecewiseFunction()
    for s, k in tf["extinction"]:
        opacity.AddPoint(s, k * unit)
    color = vtk.vtkColorTransferFunction()
    for s, r, g, b in tf["color"]:
        color.AddRGBPoint(s, r, g, b)
    prop = vtk.vtkVolumeProperty()
    prop.SetColor(color)
    prop.SetScalarOpacity(opacity)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.ShadeOff()
    prop.SetInterpolationTypeToLinear()
    return prop


def scene_camera(camera, cam):
    """Sets the vtkCamera `camera` to a scene's camera (docs/scene.md's defaults)."""
    camera.SetPosition(*cam["eye"])
    camera.SetFocalPoint(*cam.get("target", [0, 0, 0]))
    camera.SetViewUp(*cam.get("up", [0, 1, 0]))
    if cam.get("projection", "orthographic") == "perspective":
        camera.ParallelProjectionOff()
        camera.SetViewAngle(cam.get("fov_y", 30.0))
    else:
        camera.ParallelProjectionOn()
        camera.SetParallelScale(cam.get("height", 2.0) / 2)


def window_rgb(win):
    """The window's back buffer as float64 RGB in [0, 1], row 0 at the top."""
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    img = grab.GetOutput()
    w, h, _ = img.GetDimensions()
    return vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, 3)[::-1].astype(np.float64) / 255


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("scene")
    ap.add_argument("--size", type=int, default=512)
    ap.add_argument("--frames", type=int, default=5)
    ap.add_argument("--out", required=True)
    ap.add_argument("--mapper", choices=["pt", "raycast", "zsweep"], default="pt")
    a = ap.parse_args()
    with open(a.scene) as f:
        scene = json.load(f)
    base = os.path.dirname(os.path.abspath(a.scene))
    mesh = os.path.join(base, scene["mesh"])
    if not mesh.endswith(".vtu"):
        sys.exit(f"{mesh}: this peer script reads .vtu only")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(mesh)
    reader.Update()
    grid = reader.GetOutput()
    field = scene["field"]
    grid.GetPointData().SetActiveScalars(field)
    source = reader
    if any(grid.GetCellType(c) != vtk.VTK_TETRA for c in range(grid.GetNumberOfCells())):
        source = vtk.vtkDataSetTriangleFilter()
        source.SetInputConnection(reader.GetOutputPort())

    prop = volume_property(scene["transfer_function"])

    mapper = {"pt": vtk.vtkProjectedTetrahedraMapper, "raycast": vtk.vtkUnstructuredGridVolumeRayCastMapper,
              "zsweep": vtk.vtkUnstructuredGridVolumeZSweepMapper}[a.mapper]()
    mapper.SetInputConnection(source.GetOutputPort())
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    ren = vtk.vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.SetMultiSamples(0)
    win.AddRenderer(ren)
    win.SetSize(a.size, a.size)

    scene_camera(ren.GetActiveCamera(), scene["camera"])
    c = ren.GetActiveCamera()
    ren.ResetCameraClippingRange()

    times = []
    for f in range(a.frames):
        if f > 0:
            c.Azimuth(1.0)
            ren.ResetCameraClippingRange()
        t = time.perf_counter()
        win.Render()
        times.append(time.perf_counter() - t)
        if f == 0:
            rgb = window_rgb(win).astype(np.float32)
            np.save(a.out + ".npy", rgb)
    later = times[1:] or times
    print(json.dumps({"mapper": mapper.GetClassName(), "cells": grid.GetNumberOfCells(),
                      "first_frame_seconds": times[0], "median_seconds": statistics.median(later),
                      "min_seconds": min(later), "max_seconds": max(later),
                      "opengl_renderer": next((l.split(":", 1)[1].strip() for l in win.ReportCapabilities().splitlines()
                                               if l.startswith("OpenGL renderer string")), "?")}))


if __name__ == "__main__":
    main()
