"""PyVista's datasets taken by their attributes (PyVista is not packaged in Debian here): stand-ins
with PyVista's attribute names and layouts, their arrays from real files read by VTK, render the
file's picture bit for bit (issue 59)."""
import os

import numpy as np
import pytest

import cellproj

vtk = pytest.importorskip("vtkmodules.all")
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402

SHARED = os.path.join(os.environ.get("CELLPROJ_SOURCE_DIR", "."), "..", "shared", "data")


def shared(path):
    path = os.path.join(SHARED, path)
    if not os.path.exists(path):
        pytest.skip("no ../shared/data beside this clone")
    return path


def arrays(attributes):
    return {attributes.GetArrayName(k): vtk_to_numpy(attributes.GetArray(k)) for k in range(attributes.GetNumberOfArrays())}


class DataSet:
    """What PyVista's datasets share: points, point_data, cell_data (dict-like)."""

    def __init__(self, grid):
        self.points = vtk_to_numpy(grid.GetPoints().GetData())
        self.point_data, self.cell_data = arrays(grid.GetPointData()), arrays(grid.GetCellData())


class UnstructuredGrid(DataSet):
    """pyvista.UnstructuredGrid: celltypes, and the new layout (offset, cell_connectivity) or the legacy
    cells [n, ids..., n, ...]."""

    def __init__(self, grid, legacy):
        super().__init__(grid)
        self.celltypes = vtk_to_numpy(grid.GetCellTypesArray())
        cells = grid.GetCells()
        if legacy:
            exported = vtk.vtkIdTypeArray()
            cells.ExportLegacyFormat(exported)
            self.cells = vtk_to_numpy(exported)
        else:
            self.offset = vtk_to_numpy(cells.GetOffsetsArray())
            self.cell_connectivity = vtk_to_numpy(cells.GetConnectivityArray())


class StructuredGrid(DataSet):
    """pyvista.StructuredGrid: points x fastest, dimensions."""

    def __init__(self, grid):
        super().__init__(grid)
        self.dimensions = grid.GetDimensions()


class MultiBlock:
    """pyvista.MultiBlock: blocks by key, n_blocks."""

    def __init__(self, blocks):
        self._blocks = blocks

    def keys(self):
        return list(self._blocks)

    def __getitem__(self, key):
        return self._blocks[key]

    @property
    def n_blocks(self):
        return len(self._blocks)


def stand_in(data, legacy=False):
    if data.IsA("vtkMultiBlockDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        blocks = {}
        while not it.IsDoneWithTraversal():
            blocks["block %d" % len(blocks)] = stand_in(it.GetCurrentDataObject(), legacy)
            it.GoToNextItem()
        return MultiBlock(blocks)
    return StructuredGrid(data) if data.IsA("vtkStructuredGrid") else UnstructuredGrid(data, legacy)


def read_vtk(path, reader):
    r = getattr(vtk, reader)()
    r.SetFileName(path)
    if reader == "vtkExodusIIReader":
        r.UpdateInformation()
        r.SetAllArrayStatus(vtk.vtkExodusIIReader.NODAL, 1)
    r.Update()
    return r.GetOutput()


@pytest.mark.parametrize("path, reader, field", [
    ("vtkdata_post_tets/post_tets.vtu", "vtkXMLUnstructuredGridReader", "Pressure"),
    ("nasa_bluntfin/bluntfin.vts", "vtkXMLStructuredGridReader", "Density"),
    ("exodus_disk_out_ref/disk_out_ref.ex2", "vtkExodusIIReader", "V:x")])
@pytest.mark.parametrize("legacy", [False, True])
def test_a_pyvista_stand_in_renders_the_files_picture(path, reader, field, legacy):
    path = shared(path)
    data = stand_in(read_vtk(path, reader), legacy)
    mesh = cellproj.as_mesh(data)
    assert isinstance(mesh, cellproj.Mesh)
    ours = cellproj.render(data, scalars=field, cmap="viridis", view="+x", size=(64, 48))
    assert np.array_equal(ours, cellproj.render(path, scalars=field, cmap="viridis", view="+x", size=(64, 48)))
    assert ours[..., 3].max() > 0.05


def test_a_bad_pyvista_stand_in_is_an_input_error_naming_it():
    grid = UnstructuredGrid(read_vtk(shared("vtkdata_post_tets/post_tets.vtu"), "vtkXMLUnstructuredGridReader"),
                            legacy=True)
    grid.cells = grid.cells.copy()
    grid.cells[0] = 5  # a tetrahedron said to have five points
    with pytest.raises(cellproj.InputError, match=r"UnstructuredGrid: cells: .*"):
        cellproj.render(grid, size=(16, 16))
    flat = StructuredGrid(read_vtk(shared("nasa_bluntfin/bluntfin.vts"), "vtkXMLStructuredGridReader"))
    flat.dimensions = (2, 2, 2)
    with pytest.raises(cellproj.InputError, match=r"StructuredGrid: dimensions \[2, 2, 2\] do not hold its"):
        cellproj.render(flat, size=(16, 16))
    flat.points = flat.points[:, :2]
    with pytest.raises(cellproj.InputError, match=r"points: expected an \(n, 3\) array"):
        cellproj.render(flat, size=(16, 16))
