"""A render as a picture: a numpy array that saves itself and shows itself in Jupyter, and movies."""
import os as _os
import tempfile as _tempfile

import numpy as _np

from ._cellproj import _MovieWriter, write_png

_BLACK = (0.0, 0.0, 0.0)


class Image(_np.ndarray):
    """A render: a float32 (H, W, 4) array of premultiplied RGBA (row 0 at the top) that carries what
    makes it a picture, as render(...) was asked: background (None: transparent), title and legend
    (a cellproj.Legend, or None). save(path) writes it as the CLI's -o would; a Jupyter cell shows
    it; .stats is the CLI's --stats as a dict."""

    def __new__(cls, array, stats=None, background=_BLACK, title="", legend=None):
        image = _np.asarray(array, dtype=_np.float32).view(cls)
        image.stats, image.background, image.title, image.legend = dict(stats or {}), background, title, legend
        return image

    def __array_finalize__(self, source):
        self.stats = getattr(source, "stats", {})
        self.background = getattr(source, "background", _BLACK)
        self.title = getattr(source, "title", "")
        self.legend = getattr(source, "legend", None)

    def save(self, path, bits=8):
        """Writes the picture by its name: a PNG (bits=8 or 16; transparent with background=None) or an
        OpenEXR .exr (float RGBA, premultiplied), with its title and legend."""
        write_png(_np.asarray(self), _os.fspath(path), background=self.background, bits=bits, title=self.title,
                  legend=self.legend)

    def _repr_png_(self):
        if self.ndim != 3 or self.shape[2] != 4:
            return None  # a slice of a picture is shown as an array
        with _tempfile.TemporaryDirectory() as folder:
            path = _os.path.join(folder, "image.png")
            self.save(path)
            with open(path, "rb") as f:
                return f.read()


class Movie:
    """A movie written frame by frame (MP4 as H.264, or GIF, by the name), as the CLI's -o turn.mp4:

        with cellproj.Movie("turn.mp4", fps=24) as movie:
            for angle in range(0, 360, 10):
                movie.add(cellproj.render(mesh, azimuth=angle, legend=True))

    Each frame is encoded as it is added (none is held), over its own background, with its title and
    legend; every frame must have the first one's size. A movie left by an exception is removed."""

    def __init__(self, path, fps=24.0):
        """A movie at `path` (.mp4 or .gif), `fps` frames per second."""
        self._writer = _MovieWriter(_os.fspath(path), fps)

    def add(self, image):
        """Encodes `image` (a cellproj.Image, or an (H, W, 4) array over black) as the next frame."""
        background = getattr(image, "background", _BLACK)
        if background is None:
            raise ValueError("Movie.add: a movie has no alpha; render with a background= colour")
        self._writer.add(_np.asarray(image), list(background), getattr(image, "title", ""),
                         getattr(image, "legend", None))

    @property
    def frames(self):
        """How many frames were added."""
        return self._writer.frames

    def close(self):
        """Finishes the movie: the encoder flushed and the file's index written."""
        self._writer.finish()

    def __enter__(self):
        return self

    def __exit__(self, kind, value, trace):
        if kind is None:
            self.close()
        else:
            self._writer = None  # not finished: its file is removed
        return False
