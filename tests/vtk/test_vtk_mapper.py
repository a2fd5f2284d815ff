"""vtkCellprojVolumeMapper in a real VTK render window (offscreen, under Xvfb): the CLI's picture for
the same transfer function and camera to 8-bit rounding, opaque geometry hiding what lies behind it,
its preparation kept across frames, and bad input reported without a crash (docs/vtk.md).

Run by ctest's vtk_mapper (tests/vtk/run.sh); needs ../shared/data (skipped without it).
"""
import json
import os
import subprocess
import sys
import tempfile

import numpy as np
import pytest
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

from cellproj.vtk import use_cellproj, vtkCellprojVolumeMapper

SOURCE = os.environ.get("CELLPROJ_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(SOURCE, "bench"))
from vtk_peer import scene_camera, volume_property, window_rgb  # noqa: E402  (a scene as VTK objects)

EXE = os.environ.get("CELLPROJ_EXE", "cellproj")
SCENES = os.path.join(SOURCE, "bench", "scenes")
SIZE = 200
RMSE_8BIT = 2e-3  # the bound: 8-bit rounding of the window's RGB


def scene(name):
    path = os.path.join(SCENES, name + ".json")
    with open(path) as f:
        s = json.load(f)
    s["mesh"] = os.path.normpath(os.path.join(SCENES, s["mesh"]))
    if not os.path.exists(s["mesh"]):
        pytest.skip("no " + s["mesh"] + " (../shared/data)")
    s["path"] = path
    return s


def read(mesh):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(mesh)
    r.Update()
    return r


_WINDOW = []


def shared_window():
    """One offscreen window for every test: a window per test (an X window and a GL context each)
    made VTK's window creation abort under Xvfb after a dozen."""
    if not _WINDOW:
        w = vtk.vtkRenderWindow()
        w.SetOffScreenRendering(1)
        w.SetMultiSamples(0)
        _WINDOW.append(w)
    return _WINDOW[0]


class Window:
    """A window with the scene's camera and a black background, the mapper's volume in it."""

    def __init__(self, s, mapper, size=SIZE):
        self.volume = vtk.vtkVolume()
        self.volume.SetMapper(mapper)
        self.volume.SetProperty(volume_property(s["transfer_function"]))
        self.renderer = vtk.vtkRenderer()
        self.renderer.SetBackground(0, 0, 0)
        self.renderer.AddVolume(self.volume)
        self.window, self.size = shared_window(), size
        scene_camera(self.renderer.GetActiveCamera(), s["camera"])

    def __del__(self):
        if self.window.HasRenderer(self.renderer):
            self.window.RemoveRenderer(self.renderer)

    def add(self, prop):
        self.renderer.AddActor(prop)

    def picture(self):
        """The window's RGB after a render, float, row 0 at the top."""
        renderers = self.window.GetRenderers()
        for r in [renderers.GetItemAsObject(k) for k in range(renderers.GetNumberOfItems())]:
            if r is not self.renderer:
                self.window.RemoveRenderer(r)
        if not self.window.HasRenderer(self.renderer):
            self.window.AddRenderer(self.renderer)
        self.window.SetSize(self.size, self.size)
        self.renderer.ResetCameraClippingRange()
        self.window.Render()
        return window_rgb(self.window)


def cli(s, *options, size=SIZE):
    """The CLI's picture of the scene over black (its premultiplied .npy composited)."""
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "cli.npy")
        subprocess.run([EXE, "render", s["path"], "--size", "%dx%d" % (size, size), "--background", "0,0,0",
                        "--npy", out, "-o", os.path.join(d, "cli.png"), *options], check=True, capture_output=True)
        return np.load(out)[..., :3].astype(np.float64)


def rmse(a, b, what=None):
    """Root-mean-square difference; printed when `what` names it (docs/vtk.md quotes them:
    `pytest -s tests/vtk` under Xvfb shows them)."""
    e = float(np.sqrt(((a - b) ** 2).mean()))
    if what:
        print("%s: RMSE %.1e" % (what, e))
    return e


def mapper_of(s, method="pt-breakpoints", cells=False):
    m = vtkCellprojVolumeMapper()
    reader = read(s["mesh"])  # alive until connected: an output port does not hold its algorithm
    m.SetInputConnection(reader.GetOutputPort())
    m.SetMethod(method)
    if cells:
        m.SetScalarModeToUseCellFieldData()
    else:
        m.SetScalarModeToUsePointFieldData()
    m.SelectScalarArray(s["field"])
    return m


@pytest.mark.parametrize("name,method", [("post_tets", "pt-breakpoints"), ("post_tets", "exact"),
                                         ("static_mixer", "pt-linear")])
def test_the_window_shows_the_clis_picture(name, method):
    s = scene(name)
    m = mapper_of(s, method)
    got = Window(s, m).picture()
    assert m.GetLastError() == ""
    want = cli(s, "--method", method)
    assert rmse(got, want, "%s %s, window against the CLI" % (name, method)) <= RMSE_8BIT
    assert got.max() > 0.2  # a picture, not an empty window


def test_cell_scalars_are_drawn_constant_over_each_cell_as_the_cli_does():
    s = scene("angular_sector")  # "CellId": cell data
    got = Window(s, mapper_of(s, cells=True)).picture()
    assert rmse(got, cli(s), "angular_sector cell data, window against the CLI") <= RMSE_8BIT


def flat(source, rgb):
    """An opaque prop of `source` in one flat colour (no lighting)."""
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*rgb)
    actor.GetProperty().SetAmbient(1.0)
    actor.GetProperty().SetDiffuse(0.0)
    actor.GetProperty().SetSpecular(0.0)
    return actor


def test_an_opaque_plane_hides_the_volume_behind_it_as_the_clis_clipping_plane():
    # A black square facing the eye through the target, over the whole view: the window shows the
    # volume in front of it, which is the CLI's picture clipped by that plane.
    s = scene("post_tets")
    cam = s["camera"]
    eye, target = np.array(cam["eye"], float), np.array(cam["target"], float)
    forward = (target - eye) / np.linalg.norm(target - eye)
    w = Window(s, mapper_of(s))
    plane = vtk.vtkPlaneSource()
    plane.SetCenter(*target)
    plane.SetNormal(*forward)
    side = np.cross(forward, cam["up"])
    side /= np.linalg.norm(side)
    up = np.cross(side, forward)
    plane.SetOrigin(*(target - 50 * side - 50 * up))
    plane.SetPoint1(*(target + 50 * side - 50 * up))
    plane.SetPoint2(*(target - 50 * side + 50 * up))
    w.add(flat(plane, (0, 0, 0)))
    got = w.picture()
    clip = ",".join("%.17g" % v for v in (*target, *forward))
    want = cli(s, "--clip", clip)
    assert rmse(got, want, "post_tets, opaque plane against the CLI's --clip") <= RMSE_8BIT
    assert rmse(got, cli(s)) > 10 * RMSE_8BIT  # the plane did cut


def test_an_opaque_sphere_inside_the_volume_is_hidden_where_the_volume_is_in_front():
    s = scene("post_tets")
    sphere = vtk.vtkSphereSource()
    sphere.SetCenter(2.0, 0.0, 0.5)
    sphere.SetRadius(1.5)
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    plain = Window(s, mapper_of(s)).picture()
    with_sphere = Window(s, mapper_of(s))
    with_sphere.add(flat(sphere, (1, 1, 0)))
    got = with_sphere.picture()
    alone = Window(s, mapper_of(s))
    alone.renderer.RemoveVolume(alone.volume)
    alone.add(flat(sphere, (1, 1, 0)))
    sphere_only = alone.picture()
    on_sphere = sphere_only.sum(axis=2) > 0.5
    volume = plain.sum(axis=2) > 0.5 / 255
    # Off the sphere: the volume as without it.
    assert np.abs(got - plain)[~on_sphere].max() <= 2.5 / 255
    # On the sphere where no volume lies: the sphere as alone.
    assert np.abs(got - sphere_only)[on_sphere & ~volume].max() <= 2.5 / 255
    # On the sphere where the volume lies: the volume in front of it shows (not the bare sphere),
    # and the volume behind it does not (the whole volume's light added over the sphere is more).
    both = on_sphere & volume
    assert both.sum() > 100
    assert np.abs(got - sphere_only)[both].mean() > 0.02
    assert (np.clip(plain + sphere_only, 0, 1) - got)[both].mean() > 0.02


def test_the_preparation_is_kept_while_the_mesh_is_unchanged():
    s = scene("post_tets")
    m = mapper_of(s)
    w = Window(s, m)
    w.picture()
    cam = w.renderer.GetActiveCamera()
    for _ in range(3):
        cam.Azimuth(10)
        w.picture()
    assert m.GetNumberOfPreparations() == 1
    prop = w.volume.GetProperty()
    prop.GetRGBTransferFunction(0).AddRGBPoint(1.2, 0.0, 1.0, 0.0)  # a new colour: no new preparation
    w.picture()
    assert m.GetNumberOfPreparations() == 1
    before = w.picture()
    points = vtk_to_numpy(m.GetInput().GetPoints().GetData())
    points[:, 2] += 0.5  # the points moved (in place): the volume is made again from them
    m.GetInput().GetPoints().Modified()
    moved = w.picture()
    assert m.GetLastError() == "" and rmse(moved, before) > 0.01


def grid_of(points, cells, scalars=None):
    g = vtk.vtkUnstructuredGrid()
    p = vtk.vtkPoints()
    for x in points:
        p.InsertNextPoint(*x)
    g.SetPoints(p)
    for kind, ids in cells:
        g.InsertNextCell(kind, len(ids), ids)
    if scalars is not None:
        a = numpy_to_vtk(np.asarray(scalars, dtype=np.float64), deep=1)
        a.SetName("s")
        g.GetPointData().AddArray(a)
    return g


TET = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]


def render_grid(grid, method="pt-breakpoints", array="s"):
    m = vtkCellprojVolumeMapper()
    m.SetInputData(grid)
    m.SetMethod(method)
    m.SetScalarModeToUsePointFieldData()
    m.SelectScalarArray(array)
    s = {"transfer_function": {"color": [[0, 1, 1, 1], [1, 1, 0, 0]], "extinction": [[0, 1], [1, 2]]},
         "camera": {"projection": "perspective", "eye": [3, 2, 4], "target": [0.3, 0.3, 0.3], "up": [0, 1, 0],
                    "fov_y": 30}}
    w = Window(s, m, size=32)
    observer = vtk.vtkFileOutputWindow()  # VTK's error messages kept out of the test's output
    observer.SetFileName(os.devnull)
    vtk.vtkOutputWindow.SetInstance(observer)
    picture = w.picture()
    return m.GetLastError(), picture


@pytest.mark.parametrize("grid,method,array,words", [
    (lambda: grid_of(TET, [(vtk.VTK_TETRA, [0, 1, 2, 3])], [0, 1, 0.5, 0.2]), "nonsense", "s", "method"),
    (lambda: grid_of(TET, [(vtk.VTK_TETRA, [0, 1, 2, 3])], [0, 1, 0.5, 0.2]), "pt-breakpoints", "T", "no point"),
    (lambda: grid_of(TET, [(vtk.VTK_TETRA, [0, 1, 2, 3])], [0, float("nan"), 0.5, 0.2]), "pt-breakpoints", "s",
     "finite"),
    (lambda: grid_of(TET, [(vtk.VTK_TRIANGLE, [0, 1, 2])], [0, 1, 0.5, 0.2]), "pt-breakpoints", "s", "cell 0"),
    (lambda: grid_of(TET, [(vtk.VTK_TETRA, [0, 1, 2, 7])], [0, 1, 0.5, 0.2]), "pt-breakpoints", "s", "cell 0"),
])
def test_bad_input_is_reported_and_nothing_is_drawn(grid, method, array, words):
    error, picture = render_grid(grid(), method, array)
    assert words in error, error
    assert picture.max() == 0.0


def test_use_cellproj_swaps_the_mapper_of_a_volume_keeping_its_input_and_scalars():
    # PyVista's add_volume returns a vtkVolume whose mapper draws the chosen scalars; the recipe of
    # docs/vtk.md swaps in cellproj's. Here the volume is made as PyVista makes it, with VTK's objects.
    s = scene("post_tets")
    old = vtk.vtkUnstructuredGridVolumeRayCastMapper()
    reader = read(s["mesh"])
    old.SetInputConnection(reader.GetOutputPort())
    old.SetScalarModeToUsePointFieldData()
    old.SelectScalarArray(s["field"])
    w = Window(s, old)
    m = use_cellproj(w.volume, method="pt-breakpoints", threads=1)
    assert w.volume.GetMapper() is m and m.GetArrayName() == s["field"] and m.GetNumberOfThreads() == 1
    assert rmse(w.picture(), cli(s)) <= RMSE_8BIT


def test_a_method_that_cannot_cut_at_opaque_geometry_says_how_to_draw_over_it():
    s = scene("post_tets")
    m = mapper_of(s, "slicing")
    w = Window(s, m)
    sphere = vtk.vtkSphereSource()
    sphere.SetCenter(2.0, 0.0, 0.5)
    w.add(flat(sphere, (1, 1, 0)))
    w.picture()
    assert "IntermixOpaqueGeometryOff" in m.GetLastError(), m.GetLastError()
    m.IntermixOpaqueGeometryOff()
    assert w.picture().max() > 0.2 and m.GetLastError() == ""


def test_two_dependent_components_are_coloured_by_the_first_and_opaque_by_the_second_as_the_cli():
    # VTK's rule for two components with IndependentComponents off (ParaView's separate opacity
    # array): colour from the first, opacity from the second; the CLI's --field A --opacity-field B.
    s = scene("post_tets")
    grid = read(s["mesh"]).GetOutput()
    p = vtk_to_numpy(grid.GetPointData().GetArray("Pressure")).astype(np.float64)
    z = vtk_to_numpy(grid.GetPoints().GetData())[:, 2].astype(np.float64)
    for name, values in (("A", p), ("B", z)):
        a = numpy_to_vtk(values, deep=1)
        a.SetName(name)
        grid.GetPointData().AddArray(a)
    both = numpy_to_vtk(np.stack([p, z], axis=1), deep=1)
    both.SetName("AB")
    grid.GetPointData().AddArray(both)
    with tempfile.TemporaryDirectory() as d:
        mesh = os.path.join(d, "two.vtu")
        w = vtk.vtkXMLUnstructuredGridWriter()
        w.SetFileName(mesh)
        w.SetInputData(grid)
        w.Write()
        two = dict(s, mesh=mesh, field="A", path=os.path.join(d, "two.json"))
        two["transfer_function"] = {"color": s["transfer_function"]["color"],
                                    "extinction": [[float(z.min()), 0.2], [float(z.max()), 3.0]]}
        with open(two["path"], "w") as f:
            json.dump({k: v for k, v in two.items() if k != "path"}, f)
        m = vtkCellprojVolumeMapper()
        m.SetInputData(grid)
        m.SetScalarModeToUsePointFieldData()
        m.SelectScalarArray("AB")
        win = Window(two, m)
        win.volume.GetProperty().IndependentComponentsOff()
        got = win.picture()
        assert m.GetLastError() == "", m.GetLastError()
        want = cli(two, "--opacity-field", "B")
        assert rmse(got, want, "two dependent components against the CLI's --opacity-field") <= RMSE_8BIT
        assert rmse(got, cli(two)) > 5 * RMSE_8BIT  # not the picture of A alone
        m.SetMethod("pt-linear")  # a Gouraud method cannot: said, nothing drawn
        assert win.picture().max() == 0.0 and "opacity" in m.GetLastError()
