"""A tetrahedral mesh with its points renumbered along a Z-order curve (connectivity and the point
field "scalar" with them) and its cells ordered by their lowest new point number: the experiment
behind bench/results/vtk_irregular.txt's point-numbering lines (the renderers renumber cells where
the numbering scatters them, not points: side by side, points in order gained nothing measurable).
usage: /usr/bin/python3 bench/morton_points.py IN.vtu OUT.vtu"""
import vtk, numpy as np, sys
from vtk.util.numpy_support import vtk_to_numpy, numpy_to_vtk, numpy_to_vtkIdTypeArray
r = vtk.vtkXMLUnstructuredGridReader(); r.SetFileName(sys.argv[1]); r.Update(); g = r.GetOutput()
pts = vtk_to_numpy(g.GetPoints().GetData()); conn = vtk_to_numpy(g.GetCells().GetConnectivityArray()).reshape(-1, 4)
sc = vtk_to_numpy(g.GetPointData().GetArray('scalar'))
lo = pts.min(0); q = ((pts - lo) / (pts.max(0) - lo).max() * (2**20 - 1)).astype(np.uint64)
key = np.zeros(len(pts), np.uint64)
for b in range(20):
    for d in range(3): key |= ((q[:, d] >> np.uint64(b)) & np.uint64(1)) << np.uint64(3 * b + d)
p = np.argsort(key, kind='stable'); inv = np.empty_like(p); inv[p] = np.arange(len(p))
pts = pts[p]; sc = sc[p]; conn = inv[conn]
# cells too, by their first vertex's new number (keeps them local to the points)
conn = conn[np.argsort(conn.min(1), kind='stable')]
out = vtk.vtkUnstructuredGrid(); P = vtk.vtkPoints(); P.SetData(numpy_to_vtk(np.ascontiguousarray(pts), deep=1)); out.SetPoints(P)
ca = vtk.vtkCellArray(); ca.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 4*len(conn)+1, 4, dtype=np.int64), deep=1), numpy_to_vtkIdTypeArray(np.ascontiguousarray(conn.ravel().astype(np.int64)), deep=1))
out.SetCells(vtk.VTK_TETRA, ca)
a = numpy_to_vtk(np.ascontiguousarray(sc), deep=1); a.SetName('scalar'); out.GetPointData().AddArray(a)
w = vtk.vtkXMLUnstructuredGridWriter(); w.SetFileName(sys.argv[2]); w.SetInputData(out); w.Write()
