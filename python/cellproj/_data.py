"""Meshes from the objects Python users hold: files, meshio meshes, VTK data objects, PyVista-like datasets."""
import os as _os

import numpy as _np

from ._cellproj import InputError, Mesh, _load_vtk, _mesh_with_cell_data, _vtk_version, read

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


def from_vtk(data, field=None, cell_data="cells"):
    """A cellproj.Mesh from a VTK data object of this machine's VTK (python3-vtk9): a
    vtkUnstructuredGrid, a vtkStructuredGrid (a curvilinear grid: its hexahedra), a
    vtkMultiBlockDataSet or vtkPartitionedDataSetCollection (the output of VTK's Exodus and CGNS
    readers: its blocks assembled, an Exodus file's nodes merged on their global ids), assembled as
    cellproj.read assembles a file, so that both give the same mesh. Cell data is drawn constant
    over each cell, or averaged to the points with cell_data="points"; field= checks that the field
    is there."""
    name = data.GetClassName() if hasattr(data, "GetClassName") else type(data).__name__
    if not hasattr(data, "IsA") or not data.IsA("vtkDataObject"):
        raise InputError("from_vtk: %s is not a VTK data object" % name)
    from vtkmodules.vtkCommonCore import vtkVersion
    if vtkVersion.GetVTKVersion() != _vtk_version():
        raise InputError("from_vtk: this %s is VTK %s's, cellproj was built with VTK %s; write it to a file and "
                         "cellproj.read it" % (name, vtkVersion.GetVTKVersion(), _vtk_version()))
    address = int(data.__this__[1:].split("_p_")[0], 16)
    mesh = _load_vtk(address, name, cell_data)
    if field and field.split(":")[0] not in mesh.fields:
        raise InputError("from_vtk: %s has no field '%s' (fields: %s)" % (name, field, ", ".join(mesh.fields)))
    return mesh


def as_mesh(data, cell_data="cells"):
    """A cellproj.Mesh from whatever holds a mesh: a cellproj.Mesh, a file's path, a VTK data object,
    a meshio mesh, or a PyVista dataset (taken as the VTK object it is)."""
    if isinstance(data, Mesh):
        return data
    if isinstance(data, (str, _os.PathLike)):
        return read(_os.fspath(data), cell_data=cell_data)
    if hasattr(data, "IsA") and hasattr(data, "__this__"):  # VTK's Python objects, and PyVista's datasets
        return from_vtk(data, cell_data=cell_data)
    if hasattr(data, "points") and isinstance(getattr(data, "cells", None), list) and hasattr(data, "point_data"):
        return from_meshio(data, cell_data=cell_data)
    raise InputError("cellproj: cannot render a %s.%s: give a file's path, a cellproj.Mesh, a VTK data object "
                     "(vtkUnstructuredGrid, vtkStructuredGrid, vtkMultiBlockDataSet, ...), a PyVista dataset or a "
                     "meshio mesh" % (type(data).__module__, type(data).__name__))
