"""cellproj: direct volume rendering of unstructured and curvilinear grids (docs/python.md).

    import cellproj
    image = cellproj.render("mesh.vtu", cmap="viridis", view="+x", legend=True)
    image.save("out.png")        # or show it: a Jupyter cell displays `image`
"""
from ._cellproj import (Camera, InputError, Legend, Mesh, ResourceError, TransferFunction, UnsupportedError,
                        _keywords_doc, _render, colormaps, read, read_exr, render_scene, write_png)
from ._data import as_mesh, from_meshio, from_pyvista, from_vtk
from ._image import _BLACK, Image, Movie

__all__ = ["Camera", "Image", "InputError", "Legend", "Mesh", "Movie", "ResourceError", "TransferFunction",
           "UnsupportedError", "as_mesh", "colormaps", "from_meshio", "from_pyvista", "from_vtk", "read", "read_exr",
           "render", "render_scene", "write_png"]

import json as _json


def _planes(clip):
    """clip= as lists of 6 numbers: one plane (x, y, z, nx, ny, nz) or ((x, y, z), (nx, ny, nz)), or a list of them."""
    if clip is None:
        return []

    def number(v):
        return not hasattr(v, "__len__")

    def one(plane):
        return (len(plane) == 6 and all(number(v) for v in plane)) or (
            len(plane) == 2 and all(not number(p) and len(p) == 3 and all(number(v) for v in p) for p in plane))

    def flat(plane):
        if number(plane) or not one(plane):
            raise InputError("render: clip= takes planes (x, y, z, nx, ny, nz) or ((x, y, z), (nx, ny, nz)), got %r"
                             % (plane,))
        return [float(v) for v in plane] if len(plane) == 6 else [float(v) for p in plane for v in p]

    return [flat(clip)] if not number(clip) and one(clip) else [flat(p) for p in clip]


def render(data, tf=None, camera=None, *, size=(512, 512), field="", scalars=None, cmap="", colormap="", clim=None,
           opacity="", opacity_field="", depth=0.0, log_scale=False, log=False, log_floor=None, view="",
           method="pt-breakpoints", threads=0, background=_BLACK, legend=False, title="", cell_data="cells",
           clip=None, **settings):
    """Renders `data` (a file's path, a cellproj.Mesh, a VTK data object, a PyVista dataset or a meshio
    mesh) to a cellproj.Image: a float32 (H, W, 4) premultiplied array that saves itself
    (image.save("out.png"), .exr) and shows itself in Jupyter, with .stats.

    The look, as PyVista's add_volume names it: scalars= (or field=) the field, of a vector 'V:x',
    'V_X', 'V:magnitude'; cmap= a colour map (cellproj.colormaps()); clim=(lo, hi) its range;
    opacity= 'auto' (default), 'ramp', 'reverse', 'flat', 'sigmoid', 'geometric' or 'S=DEPTH,...';
    depth= the largest optical depth across the mesh; log_scale=True (log_floor=F); opacity_field= another
    field the extinction comes from (ParaView's separate opacity array: opacity= then shapes it over
    that field's values, never on a log scale); or tf= a
    cellproj.TransferFunction instead. The camera: view='+x' ... 'iso', or camera= a cellproj.Camera,
    then the moves azimuth=, elevation=, roll=, zoom=, dolly=, focus=, perspective=, parallel=. The
    picture: size=(width, height), background=(r, g, b) or None (transparent), legend=True, title=.
    clip= a plane (x, y, z, nx, ny, nz), ((x, y, z), (nx, ny, nz)), or a list of them: the mesh clipped
    before it is drawn, keeping the side each normal points away from (the CLI's --clip); colours and
    framing stay the whole mesh's.
    cell_data='points' averages cell data to the points. Every render setting of the CLI is a
    keyword of the same name (below)."""
    if scalars is not None:
        if field and field != scalars:
            raise InputError("render: give scalars= or field=, not both")
        field = scalars
    if cmap and colormap and cmap != colormap:
        raise InputError("render: give cmap= or colormap=, not both")
    if background is not None and len(background) != 3:
        raise InputError("render: background= takes (r, g, b) in [0, 1], or None for a transparent picture")
    array, stats, bar = _render(as_mesh(data, cell_data), tf, camera, size=size, field=field, method=method,
                                threads=threads, log=bool(log or log_scale), log_floor=log_floor,
                                cmap=cmap or colormap, clim=clim, opacity=opacity, depth=depth, view=view,
                                opacity_field=opacity_field, clip=_planes(clip), **settings)
    if title is None:
        title = ""
    return Image(array, stats=_json.loads(stats), background=background, title=title, legend=bar if legend else None)


render.__doc__ += _keywords_doc()
