"""cellproj.render(data, ...) as a PyVista user calls it (issue 59): any mesh object, PyVista's
keywords, an Image that saves and shows itself, movies."""
import json
import os
import shutil
import subprocess

import numpy as np
import pytest

import cellproj

EXE = os.environ.get("CELLPROJ_EXE", "cellproj")
SHARED = os.path.join(os.environ.get("CELLPROJ_SOURCE_DIR", "."), "..", "shared", "data")
DEFAULT = os.path.join(os.environ.get("CELLPROJ_SOURCE_DIR", "."), "scenes", "default.vtu")


def shared(path):
    path = os.path.join(SHARED, path)
    if not os.path.exists(path):
        pytest.skip("no ../shared/data beside this clone")
    return path


def cli_npy(tmp_path, *args):
    out = tmp_path / "cli.npy"
    subprocess.run([EXE, "render", *args, "--npy", str(out)], check=True, capture_output=True)
    return np.load(out)


def test_pyvista_keywords_give_the_clis_picture(tmp_path):
    """cmap, clim, opacity, view and a camera move are the CLI's --colormap, --range, --opacity,
    --view and --azimuth: the same picture, bit for bit."""
    image = cellproj.render(DEFAULT, cmap="viridis", clim=(0.2, 0.9), opacity="sigmoid", view="+z", azimuth=30,
                            size=(96, 80))
    cli = cli_npy(tmp_path, DEFAULT, "--colormap", "viridis", "--range", "0.2,0.9", "--opacity", "sigmoid", "--view",
                  "+z", "--azimuth", "30", "--size", "96x80")
    assert isinstance(image, cellproj.Image) and image.shape == (80, 96, 4)
    assert np.array_equal(image, cli)
    log = cellproj.render(DEFAULT, scalars="temperature", log_scale=True, log_floor=0.01, size=(64, 48))
    assert np.array_equal(log, cli_npy(tmp_path, DEFAULT, "--log", "--log-floor", "0.01", "--size", "64x48"))


def test_an_opacity_field_of_its_own_as_the_cli_draws_it(tmp_path):
    """opacity_field= is the CLI's --opacity-field, on a log scale too; exact is its reference."""
    path = shared("exodus_disk_out_ref/disk_out_ref.ex2")
    image = cellproj.render(path, scalars="Temp", opacity_field="V_X", opacity="ramp", size=(64, 48))
    assert image.stats["opacity_field"] == "V:x"
    cli = cli_npy(tmp_path, path, "--field", "Temp", "--opacity-field", "V_X", "--opacity", "ramp", "--size", "64x48")
    assert np.array_equal(image, cli)
    exact = cellproj.render(path, scalars="Temp", opacity_field="V_X", opacity="ramp", size=(64, 48), method="exact")
    assert np.abs(image - exact).max() < 1e-6
    log = cellproj.render(path, scalars="Pres", log_scale=True, opacity_field="Temp", size=(64, 48))
    assert np.array_equal(log, cli_npy(tmp_path, path, "--field", "Pres", "--log", "--opacity-field", "Temp",
                                       "--size", "64x48"))
    assert issubclass(cellproj.UnsupportedError, cellproj.InputError)
    assert issubclass(cellproj.UnsupportedError, NotImplementedError)
    with pytest.raises(cellproj.UnsupportedError, match="opacity_field= .* is drawn by method= exact, pt-breakpoints "
                                                        "or pt-analytic, not by slicing"):
        cellproj.render(path, scalars="Temp", opacity_field="V", method="slicing", size=(32, 32))
    with pytest.raises(cellproj.InputError, match="no point field named 'nope'"):
        cellproj.render(path, scalars="Temp", opacity_field="nope", size=(32, 32))


@pytest.mark.parametrize("path, reader, field", [
    ("vtkdata_post_tets/post_tets.vtu", "vtkXMLUnstructuredGridReader", "Pressure"),
    ("nasa_bluntfin/bluntfin.vts", "vtkXMLStructuredGridReader", "Density"),
    ("exodus_disk_out_ref/disk_out_ref.ex2", "vtkExodusIIReader", "V:x")])
def test_one_picture_from_a_path_a_mesh_and_a_vtk_object(path, reader, field):
    """An unstructured, a structured (curvilinear) and a multi-block file: the path, cellproj.read's
    Mesh and VTK's own reader's object (a vtkStructuredGrid, a vtkMultiBlockDataSet) render alike."""
    path = shared(path)
    io = pytest.importorskip("vtkmodules.vtkIOXML" if reader.startswith("vtkXML") else "vtkmodules.vtkIOExodus")
    r = getattr(io, reader)()
    r.SetFileName(path)
    if reader == "vtkExodusIIReader":
        r.UpdateInformation()
        r.SetAllArrayStatus(r.NODAL, 1)
        r.GenerateGlobalNodeIdArrayOn()
    r.Update()
    data = r.GetOutput()
    from_path = cellproj.render(path, field=field, size=(72, 64))
    assert from_path.stats["cells"] > 0 and from_path.stats["field"] == field
    assert np.array_equal(cellproj.render(cellproj.read(path), field=field, size=(72, 64)), from_path)
    from_vtk = cellproj.render(data, field=field, size=(72, 64))
    assert from_vtk.stats["cells"] == from_path.stats["cells"], data.GetClassName()
    assert np.array_equal(from_vtk, from_path), data.GetClassName()


def test_clip_gives_the_clis_picture(tmp_path):
    """clip= is the CLI's --clip: one plane as 6 numbers or (point, normal), or a list of them."""
    lo, hi = cellproj.read(DEFAULT).bounds
    c = [0.5 * (a + b) for a, b in zip(lo, hi)]
    one = cellproj.render(DEFAULT, clip=(*c, 1, 0.3, 0), size=(64, 48))
    text = ",".join("%.17g" % v for v in (*c, 1, 0.3, 0))
    assert np.array_equal(one, cli_npy(tmp_path, DEFAULT, "--clip", text, "--size", "64x48"))
    assert not np.array_equal(one, cellproj.render(DEFAULT, size=(64, 48)))
    two = cellproj.render(DEFAULT, clip=[(c, (1, 0.3, 0)), (*c, 0, 0, 1)], size=(64, 48))
    z = ",".join("%.17g" % v for v in (*c, 0, 0, 1))
    assert np.array_equal(two, cli_npy(tmp_path, DEFAULT, "--clip", text, "--clip", z, "--size", "64x48"))
    with pytest.raises(cellproj.InputError, match=r"clip= takes planes"):
        cellproj.render(DEFAULT, clip=(1, 2, 3))
    with pytest.raises(cellproj.InputError, match=r"clip=.*normal"):
        cellproj.render(DEFAULT, clip=(0, 0, 0, 0, 0, 0))


def test_render_scene_of_what_is_not_a_scene_says_what_it_is(tmp_path):
    """A mesh or a text given to render_scene: what it is, never the JSON parser's raw message."""
    with pytest.raises(cellproj.InputError, match="default.vtu: is a mesh file, not a scene .*: render the mesh itself"):
        cellproj.render_scene(DEFAULT)
    notes = tmp_path / "notes.json"
    notes.write_text("mesh: run.vtu\n")
    with pytest.raises(cellproj.InputError, match=r"notes.json: not valid JSON \(a scene file, docs/scene.md\): "
                                                  r"parse error at line 1, column 1"):
        cellproj.render_scene(str(notes))


def test_anything_else_is_an_input_error_naming_its_type():
    with pytest.raises(cellproj.InputError, match="cannot render a builtins.dict"):
        cellproj.render({"points": []})
    with pytest.raises(ValueError, match="not a VTK data object"):
        from vtkmodules.vtkCommonCore import vtkPoints
        cellproj.from_vtk(vtkPoints())
    with pytest.raises(cellproj.InputError, match="tf= or the look keywords"):
        mesh = cellproj.read(DEFAULT)
        cellproj.render(mesh, cellproj.TransferFunction.default(mesh), cmap="viridis")


def test_an_image_saves_and_shows_itself_as_the_cli_writes_it(tmp_path):
    """image.save is the CLI's -o with --background, --title and --legend (the same bytes);
    _repr_png_ is that PNG; .stats is --stats; .exr keeps the floats."""
    image = cellproj.render(DEFAULT, size=(96, 80), background=(1, 1, 1), title="Swirl", legend=True)
    image.save(tmp_path / "py.png")
    subprocess.run([EXE, "render", DEFAULT, "--size", "96x80", "--background", "white", "--title", "Swirl", "--legend",
                    "-o", str(tmp_path / "cli.png")], check=True, capture_output=True)
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    assert image._repr_png_() == (tmp_path / "cli.png").read_bytes()
    assert image.stats["method"] == "pt-breakpoints" and image.stats["fragments"] > 0
    clear = cellproj.render(DEFAULT, size=(32, 24), background=None)
    clear.save(tmp_path / "clear.exr")
    assert np.allclose(cellproj.read_exr(str(tmp_path / "clear.exr")), clear, rtol=0, atol=1e-6)
    assert image[:, :, 3].__class__ is cellproj.Image and image[:, :, 3]._repr_png_() is None


@pytest.mark.skipif(shutil.which("ffprobe") is None, reason="ffprobe (Debian's ffmpeg) is missing")
def test_a_movie_from_python(tmp_path):
    mesh = cellproj.read(DEFAULT)
    path = tmp_path / "turn.gif"
    with cellproj.Movie(path, fps=10) as movie:
        for angle in range(0, 360, 60):
            movie.add(cellproj.render(mesh, size=(64, 48), azimuth=angle, legend=True))
    assert movie.frames == 6
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=nb_read_frames", "-of", "csv=p=0", str(path)], check=True, capture_output=True,
                         text=True).stdout
    assert out.strip() == "6"
    with pytest.raises(cellproj.InputError, match="must have one size"):
        with cellproj.Movie(tmp_path / "bad.mp4") as movie:
            movie.add(cellproj.render(mesh, size=(64, 48)))
            movie.add(cellproj.render(mesh, size=(32, 48)))
    assert not (tmp_path / "bad.mp4").exists()
    with pytest.raises(ValueError, match="no alpha"):
        cellproj.Movie(tmp_path / "clear.mp4").add(cellproj.render(mesh, size=(8, 8), background=None))
