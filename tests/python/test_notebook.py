"""examples/arnold_web.ipynb runs headless (nbclient) against the installed package, at its own
small size (well under a minute), so that it stays true."""
import os

import pytest


def test_the_notebook_runs(repo, tmp_path, monkeypatch):
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    monkeypatch.setenv("MPLBACKEND", "module://matplotlib_inline.backend_inline")  # figures as outputs
    monkeypatch.setenv("AW_NOTEBOOK_TRAJECTORIES", "20000")
    monkeypatch.setenv("AW_NOTEBOOK_FLI_NSIDE", "16")
    nb = nbformat.read(repo / "examples" / "arnold_web.ipynb", as_version=4)
    assert all(not c.get("outputs") for c in nb.cells if c.cell_type == "code"), "commit the notebook without outputs"
    client = nbclient.NotebookClient(nb, timeout=300, kernel_name="python3", resources={"metadata": {"path": str(tmp_path)}})
    client.execute()
    outputs = [o for c in nb.cells if c.cell_type == "code" for o in c.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    assert sum(1 for o in outputs if "image/png" in o.get("data", {})) >= 3  # map, FLI, spectrum
    # progress=True in a notebook: a bar (tqdm's text bar here, without ipywidgets), no warning
    text = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "arnoldweb: 100%" in text and "IProgress" not in text and "TqdmWarning" not in text
