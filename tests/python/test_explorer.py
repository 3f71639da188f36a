"""arnoldweb.view and arnoldweb.serve (docs/viewer.md): the explorer through the package's own
arnoldweb command. (The page itself is tested in a browser by ctest explorer.view/.serve.)"""
import json
import os
import urllib.request

import pytest

import arnoldweb as aw


def test_view_of_a_result_and_of_its_directory(small_scene, tmp_path):
    r = aw.run(small_scene, out=str(tmp_path / "run"))
    v = aw.view(r, to=tmp_path / "v")
    assert v.path == str(tmp_path / "v" / "view.html") and os.path.isfile(v.path)
    inline = v._repr_html_()  # a notebook's frame: every script inlined, nothing fetched
    assert inline.startswith("<iframe srcdoc=") and "AW.addRun(" in inline and "src=&quot;" not in inline
    assert aw.view(aw.load(tmp_path / "run"), to=tmp_path / "v").path == v.path  # a view's directory is reused
    with pytest.raises(ValueError):
        aw.view(aw.run(small_scene))  # not written anywhere
    with pytest.raises(aw.OutputError, match="summary.json"):
        aw.view(tmp_path / "nothing")


def test_serve_answers_and_stops(small_scene, tmp_path):
    aw.run(small_scene, out=str(tmp_path / "run"))
    with aw.serve(tmp_path / "run", zooms=tmp_path / "zooms", max_trajectories=1000) as s:
        runs = json.load(urllib.request.urlopen(s.url + "api/runs", timeout=30))["runs"]
        assert [r["id"] for r in runs] == ["r0"] and runs[0]["map"]["nside"] == 16
    assert s.process.returncode == 0
