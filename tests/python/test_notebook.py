"""examples/notebook.py, docs/python.md's notebook-style example, runs whole from the clone's folder."""
import os
import runpy

SOURCE = os.environ.get("CELLPROJ_SOURCE_DIR", ".")


def test_the_notebook_example_runs(tmp_path, monkeypatch, capsys):
    os.symlink(os.path.join(os.path.abspath(SOURCE), "scenes"), tmp_path / "scenes")
    monkeypatch.chdir(tmp_path)
    runpy.run_path(os.path.join(SOURCE, "examples", "notebook.py"), run_name="__main__")
    assert (tmp_path / "temperature.png").stat().st_size > 1000
    assert (tmp_path / "turn.gif").stat().st_size > 1000
    assert "pt-linear against exact: largest difference" in capsys.readouterr().out
