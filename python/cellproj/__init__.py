"""cellproj: direct volume rendering of unstructured and curvilinear grids (docs/python.md).

    import cellproj
    mesh = cellproj.read("mesh.vtu")
    image = cellproj.render(mesh, size=(640, 480))   # float32 (480, 640, 4), premultiplied
    cellproj.write_png(image, "out.png")
"""
import numpy as _np

from ._cellproj import (Camera, InputError, Legend, Mesh, ResourceError, TransferFunction, _mesh_with_cell_data,
                        colormaps, read, render, render_scene, write_png)

__all__ = ["Camera", "InputError", "Legend", "Mesh", "ResourceError", "TransferFunction", "colormaps", "read", "render",
           "render_scene", "write_png", "from_meshio", "from_vtk"]

# Arrays VTK's readers add that are not data (cellproj.read skips them too).
_VTK_INTERNAL = {"GlobalNodeId", "PedigreeNodeId", "GlobalElementId", "PedigreeElementId", "ObjectId"}

# meshio's cell block names -> VTK cell type codes (the cells cellproj renders).
_MESHIO_TYPES = {"tetra": 10, "hexahedron": 12, "wedge": 13, "pyramid": 14, "voxel": 11}


def from_meshio(mesh, field=None, cell_data="cells"):
    """A cellproj.Mesh from a meshio.Mesh: its volume cell blocks, its point data and its cell data
    (all fields, or only `field`), vectors and tensors with their components as cellproj.read gives
    them (field="V:x" renders one). Cell data is drawn constant over each cell, or averaged to the
    points with cell_data="points", as cellproj.read(path, cell_data=...). Cell blocks of other
    kinds (triangles, lines) are left out."""
    kept = [k for k, b in enumerate(mesh.cells) if b.type in _MESHIO_TYPES]
    blocks = [mesh.cells[k] for k in kept]
    if not blocks:
        raise InputError("meshio mesh: no tetra, hexahedron, wedge or pyramid cells (has: %s)"
                         % ", ".join(b.type for b in mesh.cells))
    connectivity = _np.concatenate([b.data.reshape(-1) for b in blocks]).astype(_np.int64, copy=False)
    sizes = _np.concatenate([_np.full(len(b.data), b.data.shape[1], dtype=_np.int64) for b in blocks])
    offsets = _np.concatenate([[0], _np.cumsum(sizes)]).astype(_np.int64)
    types = _np.concatenate([_np.full(len(b.data), _MESHIO_TYPES[b.type], dtype=_np.uint8) for b in blocks])
    names = [field] if field and field in mesh.point_data else [] if field else list(mesh.point_data)
    scalars = {n: _components(_np.asarray(mesh.point_data[n]), len(mesh.points)) for n in names}
    cell_names = [field] if field and field in mesh.cell_data else [] if field else list(mesh.cell_data)
    cells = {n: _components(_np.concatenate([_np.asarray(mesh.cell_data[n][k]) for k in kept]), len(types))
             for n in cell_names}
    points = _np.asarray(mesh.points, dtype=_np.float64)
    if cells:
        return _mesh_with_cell_data(points, connectivity, offsets, types, _clash(scalars, cells), cells, cell_data,
                                    "meshio mesh")
    return Mesh(points, connectivity, offsets, types, scalars or None, name="meshio mesh")


def _components(values, n):
    """(n,) for one value per element, else (n, k)."""
    v = values.reshape(n, -1)
    return v[:, 0] if v.shape[1] == 1 else v


def _clash(point_fields, cell_fields):
    """The point fields, and each cell field named as a point field renamed NAME_cell, as cellproj.read names it."""
    for n in [n for n in cell_fields if n in point_fields]:
        cell_fields[n + "_cell"] = cell_fields.pop(n)
    return point_fields


def from_vtk(grid, field=None, cell_data="cells"):
    """A cellproj.Mesh from a vtkUnstructuredGrid (VTK 9's arrays, through vtk.util.numpy_support):
    its points, cells, point data and cell data (all fields, or only `field`), vectors and tensors
    with their components as cellproj.read gives them (field="V:x" renders one). Cell data is drawn
    constant over each cell, or averaged to the points with cell_data="points"."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    cells = grid.GetCells()
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    types = vtk_to_numpy(grid.GetCellTypesArray())
    points = vtk_to_numpy(grid.GetPoints().GetData())

    def arrays(data):
        names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays()) if data.GetArray(i) is not None]
        names = [n for n in names if not n.startswith("vtk") and n not in _VTK_INTERNAL]
        return {n: vtk_to_numpy(data.GetArray(n)) for n in ([field] if field in names else [] if field else names)}

    scalars, cell_fields = arrays(grid.GetPointData()), arrays(grid.GetCellData())
    if cell_fields:
        return _mesh_with_cell_data(points, connectivity, offsets, types, _clash(scalars, cell_fields), cell_fields,
                                    cell_data, "vtkUnstructuredGrid")
    return Mesh(points, connectivity, offsets, types, scalars or None, name="vtkUnstructuredGrid")
