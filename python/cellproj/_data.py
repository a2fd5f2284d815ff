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


# VTK's linear cell types and their point counts, for PyVista's legacy `cells` layout [n, ids..., n, ...].
_CELL_SIZES = {1: 1, 3: 2, 5: 3, 8: 4, 9: 4, 10: 4, 11: 8, 12: 8, 13: 6, 14: 5}


def _legacy_offsets(cells, types, name):
    """The offsets (n_cells + 1) and connectivity of PyVista's legacy `cells` array, checked against
    `celltypes`: InputError naming the first cell whose count disagrees."""
    cells = _np.asarray(cells, dtype=_np.int64).reshape(-1)
    n = len(types)
    sizes = _np.array([_CELL_SIZES.get(int(t), -1) for t in _np.unique(types)])
    if (sizes > 0).all():  # every type of a fixed size: the layout follows from the types
        lookup = _np.zeros(256, dtype=_np.int64)
        for t, k in _CELL_SIZES.items():
            lookup[t] = k
        counts = lookup[_np.asarray(types, dtype=_np.int64)]
    else:  # polygons, polyhedra: walk the counts
        counts, at = _np.empty(n, dtype=_np.int64), 0
        for c in range(n):
            if at >= len(cells):
                raise InputError("%s: cells: ends at cell %d of %d" % (name, c, n))
            counts[c], at = cells[at], at + 1 + cells[at]
    heads = _np.concatenate([[0], _np.cumsum(counts + 1)[:-1]]).astype(_np.int64)
    need = int(heads[-1] + counts[-1] + 1) if n else 0
    if need != len(cells):
        raise InputError("%s: cells: %d entries, where the legacy layout [n, ids...] of celltypes' %d cells "
                         "needs %d" % (name, len(cells), n, need))
    wrong = _np.nonzero(cells[heads] != counts)[0]
    if wrong.size:
        c = int(wrong[0])
        raise InputError("%s: cells: cell %d has %d points in the legacy layout, its celltype %d has %d"
                         % (name, c, cells[heads[c]], types[c], counts[c]))
    keep = _np.ones(len(cells), dtype=bool)
    keep[heads] = False
    return _np.concatenate([[0], _np.cumsum(counts)]), cells[keep]


def _vtk_of(data, name):
    """A VTK data object made of a PyVista-like dataset's arrays (its attributes, no PyVista needed):
    an UnstructuredGrid or ExplicitStructuredGrid (points, celltypes, and cell_connectivity with
    offset, or the legacy cells), a StructuredGrid (points, dimensions), a MultiBlock (blocks by
    key), with their point_data and cell_data."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import (vtkCellArray, vtkCompositeDataSet, vtkMultiBlockDataSet,
                                               vtkStructuredGrid, vtkUnstructuredGrid)
    if hasattr(data, "keys") and not hasattr(data, "points"):  # a MultiBlock: its blocks in order
        blocks = vtkMultiBlockDataSet()
        for k, key in enumerate(data.keys()):
            block = data[key]
            if block is None:
                continue
            blocks.SetBlock(k, _vtk_of(block, "%s block '%s'" % (name, key)))
            blocks.GetMetaData(k).Set(vtkCompositeDataSet.NAME(), str(key))
        return blocks
    points = _np.asarray(data.points, dtype=_np.float64)
    if points.ndim != 2 or points.shape[1] != 3:
        raise InputError("%s: points: expected an (n, 3) array, got shape %s" % (name, points.shape))
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(_np.ascontiguousarray(points), deep=1))
    if hasattr(data, "celltypes"):
        types = _np.asarray(data.celltypes, dtype=_np.uint8)
        if hasattr(data, "cell_connectivity") and hasattr(data, "offset"):
            offsets = _np.asarray(data.offset, dtype=_np.int64)
            connectivity = _np.asarray(data.cell_connectivity, dtype=_np.int64)
            if len(offsets) != len(types) + 1:
                raise InputError("%s: offset has %d entries for %d cells (expected n_cells + 1)"
                                 % (name, len(offsets), len(types)))
        else:
            offsets, connectivity = _legacy_offsets(data.cells, types, name)
        cell_array = vtkCellArray()
        cell_array.SetData(numpy_to_vtkIdTypeArray(_np.ascontiguousarray(offsets), deep=1),
                           numpy_to_vtkIdTypeArray(_np.ascontiguousarray(connectivity), deep=1))
        out = vtkUnstructuredGrid()
        out.SetPoints(vtk_points)
        out.SetCells(numpy_to_vtk(_np.ascontiguousarray(types), deep=1), cell_array)
    elif hasattr(data, "dimensions"):
        dims = [int(d) for d in data.dimensions]
        if len(dims) != 3 or _np.prod(dims) != len(points):
            raise InputError("%s: dimensions %s do not hold its %d points" % (name, dims, len(points)))
        out = vtkStructuredGrid()
        out.SetDimensions(*dims)
        out.SetPoints(vtk_points)
    else:
        raise InputError("%s: has points but neither celltypes (an unstructured grid) nor dimensions (a "
                         "structured grid)" % name)
    for attributes, target in ((getattr(data, "point_data", {}), out.GetPointData()),
                               (getattr(data, "cell_data", {}), out.GetCellData())):
        for key in attributes.keys():
            array = numpy_to_vtk(_np.ascontiguousarray(_np.asarray(attributes[key])), deep=1)
            array.SetName(str(key))
            target.AddArray(array)
    return out


def from_pyvista(data, field=None, cell_data="cells"):
    """A cellproj.Mesh from a PyVista dataset, taken by its attributes (PyVista need not be
    installed): UnstructuredGrid and ExplicitStructuredGrid (the legacy `cells` [n, ids...] or the
    new cell_connectivity and offset), StructuredGrid (points and dimensions: a curvilinear grid's
    hexahedra), MultiBlock (its blocks, assembled as VTK's readers' output is), with point_data and
    cell_data as cellproj.read gives a file's. The arrays become VTK objects of this machine's
    VTK, read as from_vtk reads them: the same mesh as the file."""
    return from_vtk(_vtk_of(data, "%s.%s" % (type(data).__module__, type(data).__name__)), field, cell_data)


def as_mesh(data, cell_data="cells"):
    """A cellproj.Mesh from whatever holds a mesh: a cellproj.Mesh, a file's path, a VTK data object,
    a PyVista dataset (the VTK object it is, or any object with PyVista's attributes), or a meshio
    mesh."""
    if isinstance(data, Mesh):
        return data
    if isinstance(data, (str, _os.PathLike)):
        return read(_os.fspath(data), cell_data=cell_data)
    if hasattr(data, "IsA") and hasattr(data, "__this__"):  # VTK's Python objects, and PyVista's datasets
        return from_vtk(data, cell_data=cell_data)
    if hasattr(data, "points") and isinstance(getattr(data, "cells", None), list) and hasattr(data, "point_data"):
        return from_meshio(data, cell_data=cell_data)
    if hasattr(data, "points") and (hasattr(data, "celltypes") or hasattr(data, "dimensions")) or (
            hasattr(data, "keys") and hasattr(data, "n_blocks")):
        return from_pyvista(data, cell_data=cell_data)
    raise InputError("cellproj: cannot render a %s.%s: give a file's path, a cellproj.Mesh, a VTK data object "
                     "(vtkUnstructuredGrid, vtkStructuredGrid, vtkMultiBlockDataSet, ...), a PyVista dataset or a "
                     "meshio mesh" % (type(data).__module__, type(data).__name__))
