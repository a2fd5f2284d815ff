"""cellproj: direct volume rendering of unstructured and curvilinear grids (docs/python.md).

    import cellproj
    image = cellproj.render("mesh.vtu", cmap="viridis", view="+x", legend=True)
    image.save("out.png")        # or show it: a Jupyter cell displays `image`
"""
from ._cellproj import (Camera, InputError, Legend, Mesh, ResourceError, Series, TransferFunction, UnsupportedError,
                        _keywords_doc, _render, colormaps, read_exr, render_scene, write_png)
from ._data import as_mesh, from_meshio, from_pyvista, from_vtk
from ._image import _BLACK, Image, Movie
from ._keywords import _call, _picture
from ._series import _frames, _series_of, play, read, read_series
from ._volume import Volume

__all__ = ["Camera", "Image", "InputError", "Legend", "Mesh", "Movie", "ResourceError", "Series", "TransferFunction",
           "UnsupportedError", "Volume", "as_mesh", "colormaps", "from_meshio", "from_pyvista", "from_vtk", "play",
           "read", "read_exr", "read_series", "render", "render_scene", "write_png"]


def render(data, tf=None, camera=None, *, size=(512, 512), field="", scalars=None, cmap="", colormap="", clim=None,
           opacity="", opacity_field="", depth=0.0, log_scale=False, log=False, log_floor=None, view="",
           method="pt-breakpoints", threads=0, background=_BLACK, legend=False, title="", cell_data="cells",
           clip=None, time=None, **settings):
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
    time= a time series' frame (data a cellproj.Series, a .pvd, a pattern, or an Exodus file): its
    field (and moving points) interpolated between the key frames around it, as the CLI's --time; colours
    and framing are the first key frame's. play() renders many frames.
    cell_data='points' averages cell data to the points. Every render setting of the CLI is a
    keyword of the same name (below)."""
    keywords = dict(tf=tf, camera=camera, size=size, field=field, scalars=scalars, cmap=cmap, colormap=colormap,
                    clim=clim, opacity=opacity, opacity_field=opacity_field, depth=depth, log_scale=log_scale,
                    log=log, log_floor=log_floor, view=view, method=method, threads=threads, clip=clip, **settings)
    picture = _picture(background, title, legend)
    series = _series_of(data, time is not None, cell_data)
    if series is not None:
        return next(_frames(series, [series.times[0] if time is None else float(time)], False, picture, keywords))
    if time is not None:
        raise InputError("render: time= picks a frame of a time series (a .pvd, a pattern, an Exodus file or a "
                         "cellproj.Series), not of %s" % type(data).__name__)
    array, stats, bar, _, _ = _render(as_mesh(data, cell_data), **_call(**keywords))
    return picture(array, stats, bar)


render.__doc__ += _keywords_doc()


