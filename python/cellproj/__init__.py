"""cellproj: direct volume rendering of unstructured and curvilinear grids (docs/python.md).

    import cellproj
    mesh = cellproj.read("mesh.vtu")
    image = cellproj.render(mesh, size=(640, 480))   # float32 (480, 640, 4), premultiplied
    cellproj.write_png(image, "out.png")
"""
import numpy as _np

from ._cellproj import (Camera, InputError, Mesh, ResourceError, TransferFunction, colormaps, read, render,
                        render_scene, write_png)

__all__ = ["Camera", "InputError", "Mesh", "ResourceError", "TransferFunction", "colormaps", "read", "render",
           "render_scene", "write_png", "from_meshio", "from_vtk"]

# meshio's cell block names -> VTK cell type codes (the cells cellproj renders).
_MESHIO_TYPES = {"tetra": 10, "hexahedron": 12, "wedge": 13, "pyramid": 14, "voxel": 11}


def from_meshio(mesh, field=None):
    """A cellproj.Mesh from a meshio.Mesh: its volume cell blocks and its point data (all fields,
    or only `field`), vectors and tensors with their components as cellproj.read gives them
    (field="V:x" renders one). Cell blocks of other kinds (triangles, lines) are left out."""
    blocks = [b for b in mesh.cells if b.type in _MESHIO_TYPES]
    if not blocks:
        raise InputError("meshio mesh: no tetra, hexahedron, wedge or pyramid cells (has: %s)"
                         % ", ".join(b.type for b in mesh.cells))
    connectivity = _np.concatenate([b.data.reshape(-1) for b in blocks]).astype(_np.int64, copy=False)
    sizes = _np.concatenate([_np.full(len(b.data), b.data.shape[1], dtype=_np.int64) for b in blocks])
    offsets = _np.concatenate([[0], _np.cumsum(sizes)]).astype(_np.int64)
    types = _np.concatenate([_np.full(len(b.data), _MESHIO_TYPES[b.type], dtype=_np.uint8) for b in blocks])
    names = [field] if field else list(mesh.point_data)
    scalars = {n: _np.asarray(mesh.point_data[n]).reshape(len(mesh.points), -1) for n in names}
    scalars = {n: (v[:, 0] if v.shape[1] == 1 else v) for n, v in scalars.items()}
    return Mesh(_np.asarray(mesh.points, dtype=_np.float64), connectivity, offsets, types, scalars or None,
                name="meshio mesh")


def from_vtk(grid, field=None):
    """A cellproj.Mesh from a vtkUnstructuredGrid (VTK 9's arrays, through vtk.util.numpy_support):
    its points, cells and point data (all fields, or only `field`), vectors and tensors with their
    components as cellproj.read gives them (field="V:x" renders one)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    cells = grid.GetCells()
    connectivity = vtk_to_numpy(cells.GetConnectivityArray())
    offsets = vtk_to_numpy(cells.GetOffsetsArray())
    types = vtk_to_numpy(grid.GetCellTypesArray())
    points = vtk_to_numpy(grid.GetPoints().GetData())
    data = grid.GetPointData()
    names = [field] if field else [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())
                                   if data.GetArray(i) is not None]
    scalars = {n: vtk_to_numpy(data.GetArray(n)) for n in names}
    return Mesh(points, connectivity, offsets, types, scalars or None, name="vtkUnstructuredGrid")
