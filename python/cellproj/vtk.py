"""cellproj's volume mapper for VTK pipelines (docs/vtk.md), wrapped by VTK's own Python wrapping.

``vtkCellprojVolumeMapper`` is a ``vtkUnstructuredGridVolumeMapper``: it goes wherever VTK's
unstructured-grid mappers go, reads the ``vtkVolumeProperty`` (colour, scalar opacity per
``ScalarOpacityUnitDistance``), the scalars chosen by scalar mode and array name, the active camera
and the viewport, and draws among the opaque geometry already in the window::

    from cellproj.vtk import vtkCellprojVolumeMapper
    mapper = vtkCellprojVolumeMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetMethod("pt-breakpoints")          # or "pt-linear" (fast), "exact"
    volume.SetMapper(mapper)

``use_cellproj(volume)`` swaps it into a ``vtkVolume`` that already has a mapper (PyVista's
``add_volume`` returns one), keeping its input and scalar choice.
"""
try:
    from .vtkCellprojVolumeMapper import vtkCellprojVolumeMapper
except ImportError as e:  # pip installs the numpy module only; the VTK module comes with the CMake build
    raise ImportError("cellproj.vtk is the CMake build's VTK module (CELLPROJ_VTK, docs/vtk.md), not in this "
                      "install: " + str(e)) from e

__all__ = ["vtkCellprojVolumeMapper", "use_cellproj"]


def use_cellproj(volume, method="pt-breakpoints", threads=0):
    """Replaces the mapper of ``volume`` (a ``vtkVolume``, e.g. PyVista's ``add_volume`` result) by a
    ``vtkCellprojVolumeMapper`` drawing the same input and scalars with ``method``; returns it."""
    old = volume.GetMapper()
    mapper = vtkCellprojVolumeMapper()
    if old is not None:
        if old.GetNumberOfInputConnections(0) > 0:
            mapper.SetInputConnection(old.GetInputConnection(0, 0))
        mapper.SetScalarMode(old.GetScalarMode())
        mapper.SetArrayAccessMode(old.GetArrayAccessMode())
        if old.GetArrayName():
            mapper.SelectScalarArray(old.GetArrayName())
        elif old.GetArrayId() >= 0:
            mapper.SelectScalarArray(old.GetArrayId())
    mapper.SetMethod(method)
    mapper.SetNumberOfThreads(threads)
    volume.SetMapper(mapper)
    return mapper
