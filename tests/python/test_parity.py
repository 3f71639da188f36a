"""Parity: a run from Python and the same scene run by the CLI give identical bits."""
import json
import subprocess

import arnoldweb as aw

import numpy as np
import pytest

from arnoldweb import _toml
from conftest import cli_paths, small_dict


@pytest.mark.parametrize("cli", cli_paths())
def test_python_and_cli_give_identical_digests(cli, tmp_path):
    scene_file = tmp_path / "scene.toml"
    scene_file.write_text(_toml.document(small_dict(observe={"initial_states": True, "final_states": True})))
    cli_out = tmp_path / "cli"
    done = subprocess.run([cli, "run", "--quiet", "--out", str(cli_out), str(scene_file)],
                         capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(cli_out / "summary.json") as f:
        from_cli = json.load(f)

    r = aw.run(aw.Scene.from_file(scene_file), out=tmp_path / "py")
    py = r.summary
    assert py["digests"] == from_cli["digests"]
    assert all(r.digests[k] == v for k, v in from_cli["digests"].items() if k != "algorithm")
    assert from_cli["digests"]["final_states"] != ""
    for key in ("trajectories", "completed", "binned", "flagged", "energy_error", "method", "schedule",
                "step_guard", "effects", "maps"):
        assert py[key] == from_cli[key], key
    assert sorted(py["files"]) == sorted(from_cli["files"])


@pytest.mark.parametrize("cli", cli_paths())
def test_indicators_from_python_and_cli(cli, tmp_path):
    d = small_dict(ensemble={"trajectories": 48, "initial": "grid", "grid": {"kind": "healpix", "nside": 2}},
                   observe={"fli": True, "megno": True, "lyapunov": True})
    scene_file = tmp_path / "scene.toml"
    scene_file.write_text(_toml.document(d))
    done = subprocess.run([cli, "run", "--quiet", "--out", str(tmp_path / "cli"), str(scene_file)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "cli" / "summary.json") as f:
        from_cli = json.load(f)
    r = aw.run(aw.Scene.from_file(scene_file))
    assert r.summary["digests"] == from_cli["digests"]
    h5py = pytest.importorskip("h5py")
    with h5py.File(tmp_path / "cli" / "indicators.h5") as f:
        digest = f.attrs["digest"]
        assert (digest.decode() if isinstance(digest, bytes) else digest) == r.digests["indicators"] != ""
        for name in ("fli", "megno", "megno_lyapunov", "lyapunov"):
            assert np.array_equal(f[name][...], r.indicators[name]), name


@pytest.mark.parametrize("cli", cli_paths())
def test_default_scene_from_python_and_cli(cli, repo, tmp_path):
    scene = aw.Scene.from_file(repo / "scenes" / "default.toml").set("ensemble.trajectories", 2000)
    scene = scene.set("run.device", "cpu").set("output.images", False)
    done = subprocess.run([cli, "run", "--quiet", "--device", "cpu", "--set", "ensemble.trajectories=2000",
                          "--set", "output.images=false", "--out", str(tmp_path / "cli"),
                          str(repo / "scenes" / "default.toml")], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    with open(tmp_path / "cli" / "summary.json") as f:
        assert aw.run(scene).digests["map"] == json.load(f)["digests"]["map"]
