"""pvbatch script: ParaView 5.11 loads the cellproj plugin, shows a mesh with 'cellproj Volume' and
saves a screenshot; it must be the CLI's picture of the same scene (tests/paraview/run.sh).
usage: pvbatch pvbatch_plugin.py PLUGIN SCENE.json CELLPROJ_EXE OUT_DIR [SIZE]
It also saves ParaView's own projected tetrahedra ("Volume", "Projected tetra") of the scene as
OUT_DIR/paraview_projected_tetra.png, for docs/vtk.md's pictures.
The transfer function is given to ParaView in RGB with the scene's control points and its
opacity function with o = kappa u per unit distance u, and the view has no colour palette
background, orientation axes or anti-aliasing: ParaView then adds only its 8-bit window.
"""
import json
import os
import subprocess
import sys

import numpy as np
import paraview.simple
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, GetOpacityTransferFunction,
                             LoadPlugin, Render, SaveScreenshot, Show, XMLUnstructuredGridReader)
from paraview.vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

plugin, scene_path, exe, out = sys.argv[1:5]
SIZE = int(sys.argv[5]) if len(sys.argv) > 5 else 200
LoadPlugin(plugin, ns=globals())
paraview.simple._DisableFirstRenderCameraReset()  # the scene's camera, not one framing the data
with open(scene_path) as f:
    scene = json.load(f)
mesh = os.path.normpath(os.path.join(os.path.dirname(scene_path), scene["mesh"]))
field, tf, cam = scene["field"], scene["transfer_function"], scene["camera"]

reader = XMLUnstructuredGridReader(FileName=[mesh])
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [SIZE, SIZE]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.0, 0.0, 0.0]
display = Show(reader, view)
assert "cellproj Volume" in display.Representation.Available, display.Representation.Available
display.SetRepresentationType("cellproj Volume")
ColorBy(display, ("POINTS", field))
lut = GetColorTransferFunction(field)
lut.AutomaticRescaleRangeMode = "Never"
lut.ColorSpace = "RGB"
lut.RGBPoints = [v for point in tf["color"] for v in point]
unit = 1.0 / max(k for _, k in tf["extinction"])
opacity = GetOpacityTransferFunction(field)
opacity.Points = [v for s, k in tf["extinction"] for v in (s, k * unit, 0.5, 0.0)]
display.ScalarOpacityUnitDistance = unit
for mode in ("cellproj exact", "cellproj fast"):
    display.CellprojMode = mode
    method = {"cellproj exact": "pt-breakpoints", "cellproj fast": "pt-linear"}[mode]
    view.CameraPosition = cam["eye"]
    view.CameraFocalPoint = cam["target"]
    view.CameraViewUp = cam["up"]
    view.CameraViewAngle = cam["fov_y"]
    view.CameraParallelProjection = 0
    Render(view)
    shot = os.path.join(out, "paraview_%s.png" % method)
    SaveScreenshot(shot, view, ImageResolution=[SIZE, SIZE], TransparentBackground=0)
    png = vtkPNGReader()
    png.SetFileName(shot)
    png.Update()
    img = png.GetOutput()
    w, h, _ = img.GetDimensions()
    got = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[::-1, :, :3] / 255.0
    npy = os.path.join(out, "cli_%s.npy" % method)
    subprocess.run([exe, "render", scene_path, "--method", method, "--size", "%dx%d" % (SIZE, SIZE), "--background",
                    "0,0,0", "--npy", npy, "-o", os.path.join(out, "cli_%s.png" % method)], check=True,
                   capture_output=True)
    want = np.load(npy)[..., :3]
    rmse = float(np.sqrt(((got - want) ** 2).mean()))
    print("%s: RMSE %.2e against the CLI's --method %s (bound 2e-3), largest %.3f" %
          (mode, rmse, method, float(np.abs(got - want).max())))
    assert got.max() > 0.2, "an empty picture"
    assert rmse <= 2e-3, rmse
display.SetRepresentationType("Volume")
display.SelectMapper = "Projected tetra"
Render(view)
SaveScreenshot(os.path.join(out, "paraview_projected_tetra.png"), view, ImageResolution=[SIZE, SIZE],
               TransparentBackground=0)
print("plugin test passed")
