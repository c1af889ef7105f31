"""examples/notebooks/first_render.ipynb runs end to end (issue 44): render,
sense, plot, a CW-ToF frequency sweep. Skipped where nbclient, nbformat,
ipykernel or matplotlib are missing (Debian: python3-nbclient,
python3-ipykernel, python3-matplotlib; not installed by install-deps.sh)."""

import os
import shutil

import pytest

nbformat = pytest.importorskip("nbformat")
nbclient = pytest.importorskip("nbclient")
pytest.importorskip("ipykernel")
pytest.importorskip("matplotlib")

from conftest import SOURCE_DIR

NOTEBOOK = os.path.join(SOURCE_DIR, "examples", "notebooks", "first_render.ipynb")


def test_the_notebook_renders_senses_and_plots(tmp_path):
    # Run in a scratch copy: its pictures are written beside it, not into the sources.
    path = tmp_path / "first_render.ipynb"
    shutil.copy(NOTEBOOK, path)
    notebook = nbformat.read(str(path), as_version=4)
    os.environ.setdefault("TOFSIM_SOURCE_DIR", SOURCE_DIR)
    client = nbclient.NotebookClient(notebook, timeout=300, kernel_name="python3",
                                     resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    text = "".join(o.get("text", "") for c in notebook.cells for o in c.get("outputs", [])
                   if o.get("output_type") == "stream")
    assert "48 x 48 pixels, 320 bins" in text
    assert "median depth error" in text
    assert (tmp_path / "transient.png").stat().st_size > 0
    assert (tmp_path / "spad.png").stat().st_size > 0
