"""An irregular mesh of the 1M box's size for issue 21's comparison: N random points in [-1, 1]^3
(numpy, a fixed seed), the field 0.5 + 0.4 sin(2x + y) cos(1.5z), tetrahedralized by scipy's
Delaunay (Qhull) and written as DIR/cloud.vtu, with DIR/cloud.json holding bench/scenes/box_1m.json's
camera and transfer function. Then: SCENE=DIR/cloud.json bash bench/vtk_1m.sh build
(bench/results/vtk_irregular.txt).
usage: /usr/bin/python3 bench/delaunay_cloud.py DIR [N=160000] [SEED=3]"""
import json
import os
import sys

import numpy as np
import vtk
from scipy.spatial import Delaunay
from vtk.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray

out_dir = sys.argv[1]
n = int(sys.argv[2]) if len(sys.argv) > 2 else 160000
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 3
p = np.random.default_rng(seed).random((n, 3)) * 2 - 1
s = 0.5 + 0.4 * np.sin(2 * p[:, 0] + p[:, 1]) * np.cos(1.5 * p[:, 2])
tets = Delaunay(p).simplices.astype(np.int64)
grid = vtk.vtkUnstructuredGrid()
points = vtk.vtkPoints()
points.SetData(numpy_to_vtk(np.ascontiguousarray(p), deep=1))
grid.SetPoints(points)
cells = vtk.vtkCellArray()
cells.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 4 * len(tets) + 1, 4, dtype=np.int64), deep=1),
              numpy_to_vtkIdTypeArray(np.ascontiguousarray(tets.ravel()), deep=1))
grid.SetCells(vtk.VTK_TETRA, cells)
field = numpy_to_vtk(np.ascontiguousarray(s), deep=1)
field.SetName("scalar")
grid.GetPointData().AddArray(field)
os.makedirs(out_dir, exist_ok=True)
writer = vtk.vtkXMLUnstructuredGridWriter()
writer.SetFileName(os.path.join(out_dir, "cloud.vtu"))
writer.SetInputData(grid)
writer.Write()
scene = json.load(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "box_1m.json")))
scene["mesh"] = "cloud.vtu"
json.dump(scene, open(os.path.join(out_dir, "cloud.json"), "w"))
print(f"{os.path.join(out_dir, 'cloud.vtu')}: {len(tets)} tetrahedra")
