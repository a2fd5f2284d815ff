"""A mesh of one cell type with its cells in a random order (a fixed seed), points and point
fields unchanged: the numbering a careless writer leaves (bench/cell_numbering.sh).
usage: /usr/bin/python3 bench/shuffle_cells.py IN.vtu OUT.vtu [SEED]"""
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy

src, dst = sys.argv[1], sys.argv[2]
seed = int(sys.argv[3]) if len(sys.argv) > 3 else 1
reader = vtk.vtkXMLUnstructuredGridReader()
reader.SetFileName(src)
reader.Update()
grid = reader.GetOutput()
types = vtk_to_numpy(grid.GetCellTypesArray())
if len(set(types.tolist())) != 1:
    sys.exit(f"{src}: cells of {len(set(types.tolist()))} types; this shuffles a mesh of one type")
cells = grid.GetCells()
offsets = vtk_to_numpy(cells.GetOffsetsArray())
size = int(offsets[1] - offsets[0])
conn = vtk_to_numpy(cells.GetConnectivityArray()).reshape(-1, size)
conn = conn[np.random.default_rng(seed).permutation(len(conn))]
shuffled = vtk.vtkCellArray()
shuffled.SetData(numpy_to_vtkIdTypeArray(np.arange(0, conn.size + 1, size, dtype=np.int64), deep=1),
                 numpy_to_vtkIdTypeArray(np.ascontiguousarray(conn.ravel().astype(np.int64)), deep=1))
out = vtk.vtkUnstructuredGrid()
out.SetPoints(grid.GetPoints())
out.SetCells(int(types[0]), shuffled)
out.GetPointData().ShallowCopy(grid.GetPointData())
writer = vtk.vtkXMLUnstructuredGridWriter()
writer.SetFileName(dst)
writer.SetInputData(out)
writer.Write()
