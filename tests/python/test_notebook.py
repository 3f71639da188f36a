"""examples/arnold_web.ipynb runs headless (nbclient) against the installed package, at its own
small size (well under a minute), so that it stays true."""
import os
import re

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
    # (the text bar is a stream; tqdm's widget, where ipywidgets is installed, a display whose
    # text/plain is the same bar)
    text = "".join(o.get("text", "") if o.output_type == "stream" else o.get("data", {}).get("text/plain", "")
                   for o in outputs)
    # (the widget's text/plain is its first state, 0 %; the text bar ends at 100 %)
    bar = re.search(r"arnoldweb: +(\d+)%", text)
    assert bar and "IProgress" not in text and "TqdmWarning" not in text, text
    assert "application/vnd.jupyter.widget-view+json" in str(outputs) or "arnoldweb: 100%" in text
