"""Time series from Python (docs/python.md, "Time series"): reading one, and playing its frames."""
import os as _os

from ._cellproj import InputError, Series, _animation_times, _is_series_path, _Playback
from ._cellproj import read as _read_mesh
from ._image import _BLACK
from ._keywords import _call, _picture


def read(path, format="", q_file="", zone="", time_step=0, cell_data="cells"):
    """Reads and validates a mesh file (any format `cellproj info` reads) into a cellproj.Mesh; a
    time series (a ParaView .pvd, or numbered files given as a pattern such as 'out/mesh_%04d.vtu')
    into a cellproj.Series. cell_data='cells' draws cell data constant over each cell (each cell its
    own points), 'points' averages it to the points. An Exodus file is read at time_step=; its time
    steps as a series: read_series(path)."""
    path = _os.fspath(path)
    if _is_series_path(path):
        return read_series(path, cell_data=cell_data)
    return _read_mesh(path, format=format, q_file=q_file, zone=zone, time_step=time_step, cell_data=cell_data)


def read_series(path, cell_data="cells"):
    """A time series by its key frames, listed without reading a mesh: a ParaView .pvd, numbered
    files ('out/mesh_%04d.vtu', each its number as time) or an Exodus file's time steps. A
    cellproj.Series: .times, len(), series[i] (key frame i read whole), iteration over the key
    frames' meshes, series.at(t, field=) (interpolated); render(series, time=t) and play(series, times)."""
    return Series(_os.fspath(path), cell_data)


def play(data, times=None, *, prefetch=True, background=_BLACK, title="", legend=False, cell_data="cells",
         **keywords):
    """Renders a time series' frames in order, yielding a cellproj.Image each, as `cellproj render
    --animate` does: frame f renders while a background thread reads the next key frame when needed
    and interpolates the next frame (prefetch=False: in turn; the same pictures). `data`: a
    cellproj.Series or its path; times= the frames' times (a list, or 'T0:T1:FRAMES' as --animate;
    None: the key frames'). Colours and framing are the first key frame's whatever the time; every
    other keyword is render()'s. Each image's .stats has its "time".

        with cellproj.Movie("run.mp4") as movie:
            for image in cellproj.play("run.pvd", "0:2:48", cmap="viridis", legend=True):
                movie.add(image)"""
    series = _series_of(data, True, cell_data)
    if series is None:
        raise InputError("play: expected a time series (a .pvd, a pattern, an Exodus file or a cellproj.Series), "
                         "got %s" % type(data).__name__)
    if times is None:
        times = series.times
    elif isinstance(times, str):
        times = _animation_times(times)
    else:
        times = [float(t) for t in times]
    return _frames(series, times, prefetch, _picture(background, title, legend), keywords)


def _series_of(data, any_path, cell_data):
    """`data` as a cellproj.Series when it is one or names one (a .pvd or a pattern; with `any_path`,
    any file, an Exodus file's time steps among them), else None."""
    if isinstance(data, Series):
        return data
    if isinstance(data, (str, _os.PathLike)):
        path = _os.fspath(data)
        if any_path or _is_series_path(path):
            return read_series(path, cell_data=cell_data)
    return None


def _frames(series, times, prefetch, picture, keywords):
    for array, stats, bar in _Playback(series, times, prefetch, **_call(**keywords)):
        yield picture(array, stats, bar)
