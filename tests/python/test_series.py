"""Time series and in-situ loops from Python: cellproj.read of a .pvd, render(series, time=) and
play() against the CLI's --time and --animate (bit for bit), and Volume.update keeping the
preparation when only the field changes.

Run by ctest (tests/CMakeLists.txt) with PYTHONPATH=build/python and CELLPROJ_EXE the CLI."""
import os
import subprocess
import sys

import numpy as np
import pytest

import cellproj

EXE = os.environ["CELLPROJ_EXE"]
sys.path.insert(0, os.path.join(os.environ["CELLPROJ_SOURCE_DIR"], "bench"))
from python_update import box  # noqa: E402  (an n^3 box of tetrahedra as numpy arrays, as the benchmark's)
from test_cellproj import cli  # noqa: E402  (the CLI's --npy image)


@pytest.fixture(scope="module")
def pvd(tmp_path_factory):
    """Four key frames at times 0, 1, 2, 3 of a 4^3 box of tetrahedra, the field changing."""
    path = tmp_path_factory.mktemp("series") / "s.pvd"
    subprocess.run([EXE, "generate", "box-tets", "-n", "4", "--steps", "4", "-o", str(path)], check=True,
                   capture_output=True)
    return str(path)


@pytest.fixture(scope="module")
def moving(tmp_path_factory):
    """Two key frames whose points move (a box sheared over time), written with VTK's writer."""
    vtk = pytest.importorskip("vtkmodules.all")
    from vtkmodules.util import numpy_support
    folder = tmp_path_factory.mktemp("moving")
    base = cellproj.read(_box(folder))
    for k, shear in enumerate((0.0, 0.4)):
        grid = vtk.vtkUnstructuredGrid()
        points = base.points.copy()
        points[:, 0] += shear * points[:, 2]
        vp = vtk.vtkPoints()
        vp.SetData(numpy_support.numpy_to_vtk(points, deep=True))
        grid.SetPoints(vp)
        cells = vtk.vtkCellArray()
        cells.SetData(numpy_support.numpy_to_vtkIdTypeArray(np.asarray(base.offsets), deep=True),
                      numpy_support.numpy_to_vtkIdTypeArray(np.asarray(base.connectivity), deep=True))
        grid.SetCells(numpy_support.numpy_to_vtk(np.asarray(base.types), deep=True, array_type=vtk.VTK_UNSIGNED_CHAR), cells)
        field = numpy_support.numpy_to_vtk(np.array(base.field("scalar")) * (1 + k), deep=True)
        field.SetName("scalar")
        grid.GetPointData().AddArray(field)
        writer = vtk.vtkXMLUnstructuredGridWriter()
        writer.SetFileName(str(folder / ("m_%d.vtu" % k)))
        writer.SetInputData(grid)
        writer.Write()
    (folder / "m.pvd").write_text('<?xml version="1.0"?><VTKFile type="Collection"><Collection>'
                                  '<DataSet timestep="0" file="m_0.vtu"/><DataSet timestep="2" file="m_1.vtu"/>'
                                  '</Collection></VTKFile>')
    return str(folder / "m.pvd")


def _box(folder):
    path = folder / "box.vtu"
    subprocess.run([EXE, "generate", "box-tets", "-n", "4", "-o", str(path)], check=True, capture_output=True)
    return str(path)


def test_read_lists_a_series_and_its_key_frames_read_whole(pvd):
    series = cellproj.read(pvd)
    assert isinstance(series, cellproj.Series)
    assert series.times == [0.0, 1.0, 2.0, 3.0] and len(series) == 4
    meshes = list(series)
    assert len(meshes) == 4 and all(m.n_cells == 384 for m in meshes)
    assert np.array_equal(series[-1].field("scalar"), meshes[3].field("scalar"))
    # Between key frames the field is interpolated linearly: at 1.25 a quarter of the way from 1 to 2.
    at = series.at(1.25, field="scalar")
    expect = 0.75 * np.asarray(meshes[1].field("scalar")) + 0.25 * np.asarray(meshes[2].field("scalar"))
    assert np.allclose(at.field("scalar"), expect, rtol=0, atol=1e-15)
    with pytest.raises(IndexError):
        series[4]


def test_a_series_at_a_time_is_the_clis_picture_from_every_door(tmp_path, pvd):
    flags = ["--size", "64x48", "--time", "1.25", "--colormap", "viridis", "--view", "+y", "--azimuth", "20"]
    expect = cli(tmp_path, pvd, *flags)
    keywords = dict(size=(64, 48), time=1.25, cmap="viridis", view="+y", azimuth=20)
    assert np.array_equal(cellproj.render(pvd, **keywords), expect)
    assert np.array_equal(cellproj.render(cellproj.read(pvd), **keywords), expect)
    # Colours and framing are the first key frame's whatever the time, as the CLI's.
    assert not np.array_equal(cellproj.render(pvd, **dict(keywords, time=2.0)), expect)
    log = cellproj.render(pvd, size=(64, 48), time=2.5, log_scale=True, log_floor=0.01)
    assert np.array_equal(log, cli(tmp_path, pvd, "--size", "64x48", "--time", "2.5", "--log", "--log-floor", "0.01"))
    clipped = cellproj.render(pvd, size=(64, 48), time=1.25, clip=(0.1, 0, 0, 1, 0.3, 0))
    assert np.array_equal(clipped, cli(tmp_path, pvd, "--size", "64x48", "--time", "1.25", "--clip", "0.1,0,0,1,0.3,0"))
    image = cellproj.render(pvd, size=(64, 48), time=0.5)
    assert image.stats["time"] == 0.5 and image.stats["cells"] == 384


def test_moving_points_are_interpolated_as_the_cli_does(tmp_path, moving):
    image = cellproj.render(moving, size=(64, 48), time=0.5)
    assert np.array_equal(image, cli(tmp_path, moving, "--size", "64x48", "--time", "0.5"))
    series = cellproj.read(moving)
    first, last = series[0], series[1]
    mid = series.at(0.5)
    assert np.allclose(mid.points, 0.75 * first.points + 0.25 * last.points, rtol=0, atol=1e-15)


def test_play_gives_each_frame_of_the_cli_animation_in_order(tmp_path, pvd):
    times = [0.0, 0.6, 1.25, 3.0]
    played = list(cellproj.play(pvd, times, size=(48, 40), cmap="plasma", legend=True))
    in_turn = list(cellproj.play(cellproj.read(pvd), times, prefetch=False, size=(48, 40), cmap="plasma"))
    assert [p.stats["time"] for p in played] == times
    for t, a, b in zip(times, played, in_turn):
        assert np.array_equal(a, b), t  # the background thread changes no bit
        assert np.array_equal(a, cli(tmp_path, pvd, "--size", "48x40", "--time", str(t), "--colormap", "plasma"))
    assert played[0].legend is not None and in_turn[0].legend is None
    # --animate's own spelling of the times, frames written as a movie from Python.
    assert [p.stats["time"] for p in cellproj.play(pvd, "0:3:4", size=(16, 16))] == [0.0, 1.0, 2.0, 3.0]
    with cellproj.Movie(str(tmp_path / "run.gif"), fps=4) as movie:
        for image in cellproj.play(pvd, "0:3:7", size=(32, 32)):
            movie.add(image)
    assert movie.frames == 7 and (tmp_path / "run.gif").stat().st_size > 0


def test_a_series_refuses_what_it_cannot_draw(tmp_path, pvd):
    with pytest.raises(cellproj.InputError, match="outside the series' times"):
        cellproj.render(pvd, time=9.0)
    with pytest.raises(cellproj.InputError, match="outside the series' times"):
        list(cellproj.play(pvd, [0.0, 4.0]))
    with pytest.raises(cellproj.InputError, match="time= picks a frame of a time series"):
        cellproj.render(cellproj.read(_box(tmp_path)), time=1.0)
    with pytest.raises(cellproj.InputError, match="play: expected a time series"):
        cellproj.play(cellproj.read(_box(tmp_path)))
    with pytest.raises(cellproj.UnsupportedError, match="opacity_field="):
        cellproj.render(pvd, time=1.0, opacity_field="scalar")
    with pytest.raises(cellproj.InputError, match="animate"):
        cellproj.play(pvd, "0:3")
    with pytest.raises(cellproj.InputError):
        cellproj.read(str(tmp_path / "missing_%04d.vtu"))


def test_volume_update_of_the_field_keeps_the_preparation_at_a_million_cells():
    points, conn, offsets, types = box(56)  # 1,053,696 tetrahedra
    temperature = np.exp(-4 * (points ** 2).sum(axis=1))
    volume = cellproj.Volume(cellproj.Mesh(points, conn, offsets, types, {"T": temperature}), size=(96, 96),
                             cmap="inferno", view="iso")
    assert volume.mesh.n_cells == 1053696
    first = volume.render()
    assert first.stats["prepare_seconds"] > 0
    step = temperature * 0.5  # the solver's next step, taken in place
    volume.update(field=step)
    second = volume.render()
    assert second.stats["prepare_seconds"] == 0.0
    assert volume.mesh.copies == [c for c in volume.mesh.copies if "points recentred" in c]  # no field copied
    # The look stays the first picture's: the same as a render of the new values with its transfer function.
    tf = cellproj.TransferFunction.default(cellproj.Mesh(points, conn, offsets, types, {"T": temperature}),
                                           colormap="inferno")
    camera = cellproj.Camera.framing(volume.mesh, "iso")
    again = cellproj.render(cellproj.Mesh(points, conn, offsets, types, {"T": step}), tf, camera, size=(96, 96))
    assert np.array_equal(second, again)
    assert not np.array_equal(second, first)


def test_volume_update_of_the_points_is_the_moved_meshs_picture_and_bad_arrays_are_refused():
    points, conn, offsets, types = box(6)
    field = points[:, 0] + 0.5 * points[:, 2]
    volume = cellproj.Volume(cellproj.Mesh(points, conn, offsets, types, field), size=(64, 64), view="+y",
                             elevation=20)
    volume.render()
    moved = points.copy()
    moved[:, 0] += 0.3 * moved[:, 2] ** 2
    volume.update(points=moved)
    image = volume.render()
    assert image.stats["prepare_seconds"] > 0
    look = cellproj.Volume(cellproj.Mesh(points, conn, offsets, types, field), size=(64, 64), view="+y", elevation=20)
    look.render()
    expect = cellproj.render(cellproj.Mesh(moved, conn, offsets, types, field), look._fixed[0], look._fixed[1],
                             size=(64, 64), elevation=20)
    assert np.array_equal(image, expect)
    bad = moved.copy()
    bad[3, 1] = np.nan
    with pytest.raises(cellproj.InputError, match="point 3"):
        volume.update(points=bad)
    with pytest.raises(cellproj.InputError, match="expected shape"):
        volume.update(points=moved[:-1])
    with pytest.raises(cellproj.InputError, match="values for"):
        volume.update(field=field[:-1])
    assert np.array_equal(volume.render(), image)  # refused updates left the volume as it was
