"""The Python module against the command line (bit for bit) and its errors on bad arrays.

Run by ctest (tests/CMakeLists.txt) with PYTHONPATH=build/python and CELLPROJ_EXE the CLI."""
import os
import subprocess
import threading

import numpy as np
import pytest

import cellproj

EXE = os.environ["CELLPROJ_EXE"]
SOURCE = os.environ["CELLPROJ_SOURCE_DIR"]
DEFAULT_SCENE = os.path.join(SOURCE, "scenes", "default.json")
DEFAULT_MESH = os.path.join(SOURCE, "scenes", "default.vtu")


def cli(tmp_path, *args):
    """The CLI's --npy image for `cellproj render ARGS`."""
    out = tmp_path / "cli.npy"
    subprocess.run([EXE, "render", *args, "--npy", str(out), "-o", str(tmp_path / "cli.png")], check=True,
                   capture_output=True)
    return np.load(out)


@pytest.fixture(scope="module")
def mixed(tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "mixed.vtu"
    subprocess.run([EXE, "generate", "mixed", "-n", "6", "-o", str(path)], check=True, capture_output=True)
    return str(path)


def test_render_scene_equals_the_cli_bit_for_bit(tmp_path):
    image = cellproj.render_scene(DEFAULT_SCENE, size=(160, 120))
    assert image.dtype == np.float32 and image.shape == (120, 160, 4)
    assert image[..., 3].max() > 0.5  # something is drawn
    assert np.array_equal(image, cli(tmp_path, DEFAULT_SCENE, "--size", "160x120"))


@pytest.mark.parametrize("method,options,cli_options", [
    ("slicing", {"slices": 64}, ["--slices", "64"]),
    ("pt-table", {"table_size": 64}, ["--table-size", "64"]),
    ("exact", {}, []),
])
def test_render_scene_with_options_equals_the_cli(tmp_path, method, options, cli_options):
    image = cellproj.render_scene(DEFAULT_SCENE, size=(96, 96), method=method, threads=2, **options)
    assert np.array_equal(image, cli(tmp_path, DEFAULT_SCENE, "--size", "96x96", "--method", method, *cli_options))


def test_a_scenes_render_block_is_the_clis_options(tmp_path):
    import json
    scene = json.load(open(DEFAULT_SCENE))
    scene["mesh"] = DEFAULT_MESH
    scene["render"] = {"method": "slicing", "slices": 48, "slice_axis": "view"}
    path = tmp_path / "render_block.json"
    path.write_text(json.dumps(scene))
    flags = ["--size", "64x48", "--method", "slicing", "--slices", "48", "--slice-axis", "view"]
    image = cellproj.render_scene(str(path), size=(64, 48))
    assert np.array_equal(image, cli(tmp_path, DEFAULT_SCENE, *flags))
    assert np.array_equal(image, cli(tmp_path, str(path), "--size", "64x48"))
    # A keyword wins over the scene's setting, as a flag does.
    assert np.array_equal(cellproj.render_scene(str(path), size=(64, 48), slices=20),
                          cli(tmp_path, str(path), "--size", "64x48", "--slices", "20"))


def test_camera_moves_are_the_clis(tmp_path, mixed):
    moves = {"azimuth": 40, "elevation": 25, "zoom": 1.6, "roll": -10}
    flags = ["--azimuth", "40", "--elevation", "25", "--zoom", "1.6", "--roll", "-10"]
    image = cellproj.render_scene(DEFAULT_SCENE, size=(64, 48), **moves)
    assert np.array_equal(image, cli(tmp_path, DEFAULT_SCENE, "--size", "64x48", *flags))
    mesh = cellproj.read(mixed)
    framed = cellproj.Camera.framing(mesh, "+y", aspect=64 / 48)
    by_keyword = cellproj.render(mesh, camera=framed, size=(64, 48), perspective=True, focus=(0.1, 0.2, 0.3))
    by_method = cellproj.render(mesh, camera=framed.moved(perspective=True, focus=(0.1, 0.2, 0.3)), size=(64, 48))
    assert np.array_equal(by_keyword, by_method)
    assert np.array_equal(by_keyword, cli(tmp_path, mixed, "--size", "64x48", "--view", "+y", "--perspective",
                                          "--focus", "0.1,0.2,0.3"))
    with pytest.raises(cellproj.InputError, match="zoom=: expected a positive factor"):
        cellproj.render(mesh, size=(8, 8), zoom=-1)


def test_write_png_transparent_and_16_bit(tmp_path):
    image = cellproj.render_scene(DEFAULT_SCENE, size=(24, 16))
    def ihdr(path):  # bit depth and colour type of a PNG's header chunk
        data = path.read_bytes()
        return data[24], data[25]
    cellproj.write_png(image, str(tmp_path / "a.png"))
    cellproj.write_png(image, str(tmp_path / "b.png"), background=None)
    cellproj.write_png(image, str(tmp_path / "c.png"), background=(1, 1, 1), bits=16)
    assert ihdr(tmp_path / "a.png") == (8, 2)   # RGB
    assert ihdr(tmp_path / "b.png") == (8, 6)   # RGBA: straight alpha
    assert ihdr(tmp_path / "c.png") == (16, 2)
    with pytest.raises(cellproj.InputError, match="bits must be 8 or 16"):
        cellproj.write_png(image, str(tmp_path / "d.png"), bits=12)


def test_render_of_a_mesh_equals_the_cli_without_a_scene(tmp_path, mixed):
    mesh = cellproj.read(mixed)
    camera = cellproj.Camera.framing(mesh, "+y", aspect=128 / 96)
    tf = cellproj.TransferFunction.default(mesh, colormap="viridis", depth=12)
    image = cellproj.render(mesh, tf, camera, size=(128, 96))
    assert np.array_equal(image, cli(tmp_path, mixed, "--size", "128x96", "--view", "+y", "--colormap", "viridis",
                                     "--depth", "12"))
    # Everything defaulted: the same as `cellproj render MESH`.
    assert np.array_equal(cellproj.render(mesh, size=(64, 64)), cli(tmp_path, mixed, "--size", "64x64"))


def test_numpy_arrays_render_as_the_file_they_came_from(mixed):
    meshio = pytest.importorskip("meshio")
    read = cellproj.read(mixed)
    tf = cellproj.TransferFunction.default(read)
    camera = cellproj.Camera.framing(read, "iso")
    reference = cellproj.render(read, tf, camera, size=(80, 80))
    from_meshio = cellproj.from_meshio(meshio.read(mixed))
    assert from_meshio.n_cells == read.n_cells and from_meshio.fields == read.fields
    assert np.array_equal(cellproj.render(from_meshio, tf, camera, size=(80, 80)), reference)
    vtk = pytest.importorskip("vtkmodules.vtkIOXML")
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(mixed)
    reader.Update()
    from_vtk = cellproj.from_vtk(reader.GetOutput())
    assert np.array_equal(cellproj.render(from_vtk, tf, camera, size=(80, 80)), reference)


SHARED = os.path.join(os.environ.get("CELLPROJ_SOURCE_DIR", "."), "..", "shared", "data")


@pytest.mark.parametrize("path", ["cgns_static_mixer/static_mixer.vtu", "cgns_heating_coil/heating_coil_fluid.vtu", "nasa_bluntfin/bluntfin_hex.vtu"])
def test_a_vectors_component_is_the_same_from_every_front_end(path):
    """read, from_meshio and from_vtk give one vector field with its components, and its x
    component renders the same from each (the old from_meshio took x under the vector's name)."""
    path = os.path.join(SHARED, path)
    if not os.path.exists(path):
        pytest.skip("no ../shared/data beside this clone")
    meshio = pytest.importorskip("meshio")
    vtk = pytest.importorskip("vtkmodules.vtkIOXML")
    read = cellproj.read(path)
    vector = [name for name, k in read.fields.items() if k == 3][0]
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    doors = {"read": read, "meshio": cellproj.from_meshio(meshio.read(path)),
             "vtk": cellproj.from_vtk(reader.GetOutput())}
    camera = cellproj.Camera.framing(read, "iso")
    x = read.field(vector + ":x")
    assert np.array_equal(x, read.field(vector)[:, 0]) and read.field(vector).shape == (read.n_points, 3)
    tf = cellproj.TransferFunction.default(read, field=vector + "_X")
    images = {}
    for door, mesh in doors.items():
        assert mesh.fields[vector] == 3, door
        assert np.array_equal(mesh.field(vector + "_X"), x), door
        assert np.array_equal(mesh.field(vector), read.field(vector)), door
        images[door] = cellproj.render(mesh, tf, camera, size=(64, 64), field=vector + ":x")
    assert np.array_equal(images["meshio"], images["read"]) and np.array_equal(images["vtk"], images["read"])
    with pytest.raises(cellproj.InputError, match="has 3 components; pick x, y, z"):
        cellproj.render(read, tf, camera, size=(16, 16), field=vector + ":w")


def test_a_log_scale_renders_as_the_cli_does(tmp_path, mixed):
    mesh = cellproj.read(mixed)
    assert np.array_equal(cellproj.render(mesh, size=(64, 48), log=True, log_floor=0.05),
                          cli(tmp_path, mixed, "--size", "64x48", "--log", "--log-floor", "0.05"))
    tf = cellproj.TransferFunction.default(mesh, log=True, log_floor=0.05, opacity="ramp")
    assert tf.extinction(np.log10(0.05)) == 0.0  # the ramp starts at the floor, on the log axis
    made = cellproj.TransferFunction(extinction=[(1, 0), (100, 2)], colormap="viridis", range=(1, 100), log=True)
    assert made.extinction(1.0) == 1.0
    with pytest.raises(cellproj.InputError, match="log_floor= is the floor of a log scale: give log= too"):
        cellproj.render(mesh, size=(8, 8), log_floor=0.05)
    with pytest.raises(cellproj.InputError, match="iso= does not go with log= yet"):
        cellproj.render(mesh, size=(8, 8), log=True, log_floor=0.05, method="exact", iso=["0.5"])


@pytest.mark.parametrize("mode", ["cells", "points"])
def test_cell_data_is_the_same_from_every_front_end(tmp_path, mixed, mode):
    """A cell field (and a point field of the same name, read back as NAME_cell for the cells) from
    read, from_meshio and from_vtk: drawn constant over each cell (or averaged to the points) the
    same way, to the same bits. (ASCII, which meshio reads.)"""
    meshio = pytest.importorskip("meshio")
    vtk = pytest.importorskip("vtkmodules.vtkIOXML")
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkFiltersCore import vtkCellCenters
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(mixed)
    reader.Update()
    grid = reader.GetOutput()
    centres = vtkCellCenters()
    centres.SetInputData(grid)
    centres.Update()
    x = np.array([centres.GetOutput().GetPoint(i) for i in range(grid.GetNumberOfCells())])
    for name, values in (("heat", np.sin(3 * x[:, 0]) + x[:, 2]), ("scalar", x[:, 1])):
        array = numpy_to_vtk(np.ascontiguousarray(values))
        array.SetName(name)
        grid.GetCellData().AddArray(array)
    path = str(tmp_path / "cells.vtu")
    writer = vtk.vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetDataModeToAscii()
    writer.SetFileName(path)
    writer.Write()
    read = cellproj.read(path, cell_data=mode)
    assert set(read.fields) == {"scalar", "scalar_cell", "heat"}
    assert read.n_points == (sum(grid.GetCell(c).GetNumberOfPoints() for c in range(grid.GetNumberOfCells()))
                             if mode == "cells" else grid.GetNumberOfPoints())
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    doors = {"meshio": cellproj.from_meshio(meshio.read(path), cell_data=mode),
             "vtk": cellproj.from_vtk(reader.GetOutput(), cell_data=mode)}
    camera = cellproj.Camera.framing(read, "iso")
    tf = cellproj.TransferFunction.default(read, field="heat")
    image = cellproj.render(read, tf, camera, size=(64, 64), field="heat")
    for door, mesh in doors.items():
        assert mesh.fields == read.fields, door
        # meshio groups cells by type: averaged to the points, the sums run in another order.
        same = np.array_equal if mode == "cells" or door == "vtk" else lambda a, b: np.allclose(a, b, 0, 1e-12)
        assert same(mesh.field("heat"), read.field("heat")), door
        rendered = cellproj.render(mesh, tf, camera, size=(64, 64), field="heat")
        assert np.array_equal(rendered, image) if same is np.array_equal else np.allclose(rendered, image, 0, 1e-6)


def test_a_figure_from_python_is_the_clis(tmp_path, mixed):
    """write_png's title and legend give the PNG the CLI's --title and --legend give, byte for byte."""
    mesh = cellproj.read(mixed)
    out = tmp_path / "cli.png"
    subprocess.run([EXE, "render", mixed, "--size", "96x80", "--title", "A twisted box", "--legend", "-o", str(out)],
                   check=True, capture_output=True)
    values = mesh.field("scalar")
    legend = cellproj.Legend(cellproj.TransferFunction.default(mesh), (values.min(), values.max()), "scalar")
    cellproj.write_png(cellproj.render(mesh, size=(96, 80)), str(tmp_path / "py.png"), title="A twisted box",
                       legend=legend)
    assert (tmp_path / "py.png").read_bytes() == out.read_bytes()
    subprocess.run([EXE, "render", mixed, "--size", "96x80", "--legend-orientation", "horizontal", "--legend-title",
                    "Heat", "--legend-unit", "K", "-o", str(out)], check=True, capture_output=True)
    across = cellproj.Legend(cellproj.TransferFunction.default(mesh), (values.min(), values.max()), "Heat",
                             horizontal=True, unit="K")
    cellproj.write_png(cellproj.render(mesh, size=(96, 80)), str(tmp_path / "py.png"), legend=across)
    assert (tmp_path / "py.png").read_bytes() == out.read_bytes()
    with pytest.raises(cellproj.InputError, match="range must be finite and increasing"):
        cellproj.write_png(cellproj.render(mesh, size=(8, 8)), str(tmp_path / "x.png"),
                           legend=cellproj.Legend(cellproj.TransferFunction.default(mesh), (1.0, 0.0)))


def test_vector_arrays_from_numpy():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    velocity = np.array([[3.0, 4.0, 0.0], [0, 0, 1], [1, 1, 1], [2, 0, 0]])
    mesh = cellproj.Mesh(points, np.arange(4), np.array([0, 4]), np.array([10], np.uint8), {"v": velocity})
    assert mesh.fields == {"v": 3}
    assert np.allclose(mesh.field("v:magnitude"), np.linalg.norm(velocity, axis=1))
    assert np.array_equal(mesh.field("v_Y"), velocity[:, 1])
    with pytest.raises(cellproj.InputError, match="1 to 9 components"):
        mesh.add_field("w", np.zeros((4, 12)))


def tet(points=None, connectivity=(0, 1, 2, 3), offsets=(0, 4), types=(10,), **kw):
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float) if points is None else points
    return cellproj.Mesh(points, np.asarray(connectivity), np.asarray(offsets), np.asarray(types, np.uint8),
                         kw.get("scalars", np.array([0.0, 1.0, 2.0, 3.0])))


def test_dtypes_taken_as_they_are_and_those_converted():
    assert tet().copies == []  # float64 points, int64 ids, uint8 types, float64 scalars: no copy
    wide = np.zeros((4, 5))
    wide[:, :3] = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]]
    assert tet(points=wide[:, :3]).copies == []  # rows at a stride: read in place
    assert tet(points=wide[:, :3].astype(np.float32)).copies == []
    narrow = cellproj.Mesh(np.eye(4, 3), np.arange(4, dtype=np.int32), np.array([0, 4], np.int32),
                           np.array([10], np.int16), np.arange(4, dtype=np.float32))
    copies = " | ".join(narrow.copies)
    assert "types: int16 copied as uint8" in copies and "float32 copied as float64" in copies
    assert "32-bit ids widened" in copies
    field = tet().field()
    assert field.tolist() == [0.0, 1.0, 2.0, 3.0] and not field.flags.writeable


@pytest.mark.parametrize("make,message", [
    (lambda: tet(connectivity=(0, 1, 2, 9)), "refers to point 9, out of range"),
    (lambda: tet(points=np.zeros((4, 2))), r"points: expected shape \(N, 3\), got \(4, 2\)"),
    (lambda: tet(connectivity=(0.0, 1.0, 2.0, 3.0)), "expected integer ids, got dtype float64"),
    (lambda: tet(offsets=(0, 4, 4)), "offsets: expected one more entry than types"),
    (lambda: tet(offsets=(0, 5)), "offsets end at 5 but the connectivity has 4"),
    (lambda: tet(types=(42,)), "unsupported cell types"),
    (lambda: tet(scalars=np.zeros(3)), "field 'scalars' has 3 values for 4 points"),
    (lambda: tet(points=np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, np.nan]])), "non-finite coordinate"),
    (lambda: cellproj.render(tet(), sort="bogus"), "sort=: unknown sort 'bogus'"),
    (lambda: cellproj.render(tet(), method="exact", sort="mpvo"), "sort= does not apply to method= exact, which reads method=, .*interpolation="),
    (lambda: cellproj.render(tet(), colour="red"), "'colour' is not a render setting \\(known: method=, .*table_size="),
    (lambda: cellproj.render(tet(), size=(0, 8)), "size: expected"),
    (lambda: cellproj.read("/nonexistent/mesh.vtu"), "mesh.vtu: no such file"),
    (lambda: cellproj.TransferFunction(extinction=[(0, -1)], color=[(0, 1, 1, 1)]), "must be finite and >= 0"),
    (lambda: cellproj.TransferFunction(extinction=[(0, 1)]), "give exactly one of color"),
    (lambda: cellproj.Camera(eye=(0, 0, 0), target=(0, 0, 0)), "eye and target are the same point"),
    (lambda: cellproj.render_scene("/nonexistent.json"), "no such scene file"),
])
def test_bad_input_raises_input_error_with_the_message(make, message):
    with pytest.raises(cellproj.InputError, match=message):
        make()
    assert issubclass(cellproj.InputError, ValueError)


def test_exact_render_of_one_tetrahedron_has_its_analytic_optical_depth():
    # Constant extinction k and colour c: a pixel's alpha is 1 - exp(-k * chord), its colour c * alpha.
    m = tet(scalars=np.zeros(4))
    tf = cellproj.TransferFunction(extinction=[(0, 2.0)], color=[(0, 0.5, 0.25, 1.0)])
    camera = cellproj.Camera(eye=(0.1, 0.1, 5.0), target=(0.1, 0.1, 0.0), up=(0, 1, 0), projection="orthographic",
                             height=0.01)
    image = cellproj.render(m, tf, camera, size=(1, 1), method="exact")
    chord = 1.0 - 0.1 - 0.1  # along z through (0.1, 0.1): from z = 0 to the face x + y + z = 1
    alpha = 1.0 - np.exp(-2.0 * chord)
    assert image[0, 0, 3] == pytest.approx(alpha, rel=1e-5)
    assert image[0, 0, :3] == pytest.approx([0.5 * alpha, 0.25 * alpha, alpha], rel=1e-5)


def test_renders_from_two_python_threads_equal_one_thread(mixed):
    mesh = cellproj.read(mixed)
    alone = cellproj.render(mesh, size=(96, 96), threads=1)
    results = [None, None]

    def work(k):
        results[k] = cellproj.render(mesh, size=(96, 96), threads=2)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(r, alone) for r in results)


def test_write_png_matches_the_cli_png(tmp_path):
    image = cli(tmp_path, DEFAULT_SCENE, "--size", "64x48")
    cellproj.write_png(image, str(tmp_path / "py.png"), background=(0.04, 0.04, 0.06))
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


def test_render_scene_of_a_time_series_at_a_time_equals_the_cli(tmp_path):
    series = tmp_path / "series" / "s.pvd"
    subprocess.run([EXE, "generate", "box-tets", "-n", "4", "--steps", "4", "-o", str(series)], check=True,
                   capture_output=True)
    scene = tmp_path / "scene.json"
    scene.write_text('{"mesh": "series/s.pvd", "transfer_function": {"color": [[0, 0.2, 0.4, 1], [1, 1, 0.8, 0.2]],'
                     ' "extinction": [[0, 1], [1, 6]]}}')
    image = cellproj.render_scene(str(scene), size=(64, 48), time=1.25)
    assert np.array_equal(image, cli(tmp_path, str(scene), "--size", "64x48", "--time", "1.25"))
    assert not np.array_equal(image, cellproj.render_scene(str(scene), size=(64, 48), time=1.0))
    with pytest.raises(cellproj.InputError, match="outside the series' times"):
        cellproj.render_scene(str(scene), size=(64, 48), time=9.0)
    # Clipped, as the CLI's playback clips it (the field mapped onto the clipped cells): the same playback.
    clipped = tmp_path / "clipped.json"
    clipped.write_text(scene.read_text()[:-1] + ', "clip": [{"point": [0.1, 0, 0], "normal": [1, 0.3, 0]}]}')
    image = cellproj.render_scene(str(clipped), size=(64, 48), time=1.25)
    assert np.array_equal(image, cli(tmp_path, str(clipped), "--size", "64x48", "--time", "1.25"))
    assert not np.allclose(image, cellproj.render_scene(str(scene), size=(64, 48), time=1.25), atol=1e-3)


def test_iso_surfaces_from_a_list_equal_the_cli_with_repeated_options(tmp_path):
    image = cellproj.render_scene(DEFAULT_SCENE, size=(64, 48), method="exact",
                                  iso=["0.3:0.3,0.5,1,0.35", "0.6:1,0.5,0.2,0.5"], iso_mode="oit4")
    assert np.array_equal(image, cli(tmp_path, DEFAULT_SCENE, "--size", "64x48", "--method", "exact", "--iso",
                                     "0.3:0.3,0.5,1,0.35", "--iso", "0.6:1,0.5,0.2,0.5", "--iso-mode", "oit4"))


def test_a_scenes_iso_list_is_what_exact_draws_from_python_and_the_cli(tmp_path):
    base = ('{"mesh": "%s", "transfer_function": {"color": [[0, 0.2, 0.4, 1], [1.1, 1, 0.8, 0.2]],'
            ' "extinction": [[0, 0.5], [1.1, 8]]}' % os.path.abspath(DEFAULT_MESH))
    scene, plain = tmp_path / "iso.json", tmp_path / "plain.json"
    scene.write_text(base + ', "iso": [{"value": 0.3, "color": [0.3, 0.5, 1], "opacity": 0.35}, {"value": 0.6}],'
                     ' "iso_mode": "oit4", "volume": false}')
    plain.write_text(base + "}")
    image = cellproj.render_scene(str(scene), size=(48, 40), method="exact")
    assert image[..., 3].max() > 0.3
    assert np.array_equal(image, cli(tmp_path, str(scene), "--size", "48x40", "--method", "exact"))
    same = cellproj.render_scene(str(plain), size=(48, 40), method="exact", iso=["0.3:0.3,0.5,1,0.35", "0.6"],
                                 iso_mode="oit4", volume="off")
    assert np.array_equal(image, same)
    with pytest.warns(UserWarning, match="iso-surfaces are drawn by method= exact"):
        cellproj.render_scene(str(scene), size=(16, 16))


def test_a_scene_of_two_volumes_and_a_clipped_scene_equal_the_cli(tmp_path):
    subprocess.run([EXE, "generate", "box-tets", "-n", "4", "-o", str(tmp_path / "a.vtu")], check=True,
                   capture_output=True)
    subprocess.run([EXE, "generate", "swirl", "-n", "4", "-o", str(tmp_path / "b.vtu")], check=True,
                   capture_output=True)
    tf = '{"color": [[0, 0.2, 0.4, 1], [1.1, 1, 0.8, 0.2]], "extinction": [[0, 0.5], [1.1, 4]]}'
    two = tmp_path / "two.json"
    two.write_text('{"volumes": [{"mesh": "a.vtu", "transfer_function": %s},'
                   ' {"mesh": "b.vtu", "transfer_function": %s, "iso": [{"value": 0.5, "color": [1, 0, 0],'
                   ' "opacity": 0.4}]}], "iso_mode": "oit3", "clip": [{"point": [0, 0, 0.2], "normal": [0, 0, 1]}]}'
                   % (tf, tf))
    image = cellproj.render_scene(str(two), size=(40, 32))
    assert image[..., 3].max() > 0.3
    assert np.array_equal(image, cli(tmp_path, str(two), "--size", "40x32"))
    with pytest.raises(cellproj.InputError, match="several volumes"):
        cellproj.render_scene(str(two), size=(8, 8), field="scalar")
    # One mesh with a clipping plane: clipped as the CLI clips it, not drawn whole.
    one = tmp_path / "one.json"
    one.write_text('{"mesh": "a.vtu", "transfer_function": %s, "clip": [{"point": [0, 0, 0.2], "normal": [1, 0, 1]}]}'
                   % tf)
    clipped = cellproj.render_scene(str(one), size=(40, 32))
    assert np.array_equal(clipped, cli(tmp_path, str(one), "--size", "40x32"))
    whole = tmp_path / "whole.json"
    whole.write_text('{"mesh": "a.vtu", "transfer_function": %s}' % tf)
    assert not np.array_equal(clipped, cellproj.render_scene(str(whole), size=(40, 32)))


def test_thread_counts_are_checked_as_the_clis_before_tbb_sees_them():
    mesh = cellproj.read(DEFAULT_MESH)
    for bad in (10 ** 9, 10 ** 8, -1, 1025, 10 ** 30, 2.5, True, "4"):
        with pytest.raises(cellproj.InputError, match="threads=: expected"):
            cellproj.render(mesh, size=(8, 8), threads=bad)
    with pytest.raises(cellproj.InputError, match="threads=: expected"):
        cellproj.render_scene(DEFAULT_SCENE, size=(8, 8), threads=10 ** 9)
    one = cellproj.render(mesh, size=(24, 16), threads=np.int64(1))
    assert np.array_equal(one, cellproj.render(mesh, size=(24, 16), threads=1024))  # the same bits on any count


def test_complex_arrays_and_a_bad_framing_aspect_are_refused():
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    conn, offsets, types = np.arange(4), np.array([0, 4]), np.array([10], dtype=np.uint8)
    with pytest.raises(cellproj.InputError, match="points: complex values"):
        cellproj.Mesh(points.astype(complex), conn, offsets, types, np.zeros(4))
    with pytest.raises(cellproj.InputError, match="complex values"):
        cellproj.Mesh(points, conn, offsets, types, np.zeros(4, dtype=complex))
    mesh = cellproj.Mesh(points, conn, offsets, types, np.zeros(4))
    for aspect in (float("nan"), 0.0, -1.0, float("inf")):
        with pytest.raises(cellproj.InputError, match="aspect: expected"):
            cellproj.Camera.framing(mesh, "iso", aspect)
