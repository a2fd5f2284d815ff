"""In-situ loops from Python (docs/python.md, "In-situ loops")."""
from ._cellproj import InputError, _render
from ._data import as_mesh
from ._image import _BLACK
from ._keywords import _call, _picture


class Volume:
    """A mesh drawn step after step of a solver's loop (in situ), its colours and framing fixed by its
    first picture as a played series' are by its first key frame, so that the steps compare:

        volume = cellproj.Volume(mesh, field="T", cmap="viridis", view="iso", legend=True)
        for step in range(steps):
            solver.advance()
            volume.update(field=solver.T)   # the solver's array, taken in place: the preparation is kept
            volume.render().save("T_%04d.png" % step)

    `data` and the keywords are render()'s. update(points=) moves the points: the same cells, validated
    again, the preparation made on the next render (what is kept and what is not: docs/python.md).
    render(**changes) draws with some keywords changed; a change of the look or the view (cmap=,
    clim=, opacity=, field=, view=, size=, ...) fixes the new look, camera moves apply to the fixed
    view. .stats["prepare_seconds"] of a picture is 0 when the preparation was kept."""

    _LOOK = {"tf", "camera", "cmap", "colormap", "clim", "opacity", "opacity_field", "depth", "log", "log_scale",
             "log_floor", "view", "field", "scalars", "size"}

    def __init__(self, data, *, cell_data="cells", **keywords):
        """`data` as render() takes it (cell_data= as read's); `keywords` render()'s, for every picture."""
        self.mesh = as_mesh(data, cell_data)
        self._keywords = keywords
        self._fixed = None  # the transfer function and camera (before the moves) of the look

    def update(self, field=None, points=None):
        """The next step: field= the rendered field's new values ((N,) or (N, k) as stored), points=
        the moved points (N, 3). Arrays of float64, contiguous, are read in place, not copied: keep
        them alive and unchanged until the next update."""
        spec = self._keywords.get("field") or self._keywords.get("scalars") or ""
        self.mesh.update(field=field, points=points, name=spec)

    def render(self, **changes):
        """A cellproj.Image of the mesh as it is now; `changes` as render()'s keywords."""
        keywords = dict(self._keywords, **changes)
        picture = _picture(keywords.pop("background", _BLACK), keywords.pop("title", ""),
                           keywords.pop("legend", False))
        if "time" in keywords or "cell_data" in keywords:
            raise InputError("Volume.render: time= and cell_data= are not for a Volume")
        call = _call(**keywords)
        fixed = self._fixed is not None and not (self._LOOK & set(changes))
        if fixed:
            call.update(tf=self._fixed[0], camera=self._fixed[1], cmap="", clim=None, opacity="", depth=0.0, view="")
        array, stats, bar, tf, camera = _render(self.mesh, **call)
        if not fixed:
            self._fixed = (tf, camera)
        return picture(array, stats, bar)

    def __repr__(self):
        return "<cellproj.Volume of %r>" % (self.mesh,)
