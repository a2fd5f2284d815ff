"""render()'s keywords as the module's door takes them, and how its arrays become pictures."""
import json as _json

from ._cellproj import InputError
from ._image import Image


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


def _picture(background, title, legend):
    """How a render's array becomes a cellproj.Image: its background, title and legend."""
    if background is not None and len(background) != 3:
        raise InputError("render: background= takes (r, g, b) in [0, 1], or None for a transparent picture")
    return lambda array, stats, bar: Image(array, stats=_json.loads(stats), background=background,
                                           title=title or "", legend=bar if legend else None)


def _call(tf=None, camera=None, size=(512, 512), field="", scalars=None, cmap="", colormap="", clim=None,
          opacity="", opacity_field="", depth=0.0, log_scale=False, log=False, log_floor=None, view="",
          method="pt-breakpoints", threads=0, clip=None, **settings):
    """render()'s keywords as the module's door takes them: PyVista's names folded into the CLI's."""
    if scalars is not None:
        if field and field != scalars:
            raise InputError("render: give scalars= or field=, not both")
        field = scalars
    if cmap and colormap and cmap != colormap:
        raise InputError("render: give cmap= or colormap=, not both")
    return dict(tf=tf, camera=camera, size=tuple(size), field=field, method=method, threads=threads,
                log=bool(log or log_scale), log_floor=log_floor, cmap=cmap or colormap, clim=clim, opacity=opacity,
                depth=depth, view=view, opacity_field=opacity_field, clip=_planes(clip), **settings)
