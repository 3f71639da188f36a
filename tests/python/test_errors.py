"""Errors: the library's checks and messages (the CLI's), as exceptions with fields."""
import os
import subprocess

import arnoldweb as aw
import pytest

from conftest import cli_path


def test_value_out_of_range_names_file_line_key():
    with pytest.raises(aw.SceneError) as e:
        aw.Scene.from_toml("[model]\nenergy = 2e6\n", name="bad.toml")
    err = e.value
    assert (err.file, err.line, err.column, err.key) == ("bad.toml", 2, 10, "model.energy")
    assert "from -1e6 to 1e6" in err.reason
    assert str(err).startswith("bad.toml:2:10: model.energy: ")
    assert isinstance(err, ValueError)


def test_message_is_the_clis(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text("[model]\nenergy = 2e6\n")
    with pytest.raises(aw.SceneError) as e:
        aw.Scene.from_file(path)
    cli = subprocess.run([cli_path(), "check", str(path)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == f"arnoldweb: error: {e.value}"


def test_unknown_key_suggests():
    with pytest.raises(aw.SceneError) as e:
        aw.Scene.from_dict({"model": {"energi": 3}})
    assert e.value.key == "model.energi"
    assert "did you mean 'model.energy'" in str(e.value)


def test_missing_file():
    with pytest.raises(aw.SceneError) as e:
        aw.Scene.from_file("/nonexistent/scene.toml")
    assert e.value.file == "/nonexistent/scene.toml" and e.value.line == 0


def test_bad_set_leaves_scene_as_it_was(small_scene):
    with pytest.raises(aw.SceneError) as e:
        small_scene.set("ensemble.trajectories", -5)
    assert e.value.key == "ensemble.trajectories"
    assert "Scene.set('ensemble.trajectories', -5)" in str(e.value)
    assert small_scene["ensemble.trajectories"] == 3000
    assert small_scene.overrides == []


def test_values_wrong_together_fail_at_check(small_scene):
    small_scene.set("integrator.step", 0.013)
    with pytest.raises(aw.SceneError) as e:
        small_scene.check()
    assert e.value.key == "run.average"


def test_unknown_device(small_scene):
    with pytest.raises(aw.DeviceError) as e:
        aw.run(small_scene, device="opencl:99")
    assert e.value.device == "opencl:99"
    assert "devices present" in str(e.value)


def test_device_lists_refused_before_any_work(small_scene):
    with pytest.raises(aw.SceneError) as e:
        aw.run(small_scene, device="cpu,cpu")
    assert "cpu is listed twice" in str(e.value)
    with pytest.raises(aw.DeviceError) as e:
        aw.run(small_scene, device="cpu,opencl:99")
    assert e.value.device == "opencl:99"


def test_device_is_a_value_never_toml(small_scene):
    # '"cpu" #' was spliced into TOML and read as cpu (issue 37): the text as it is names no device
    for device in ('"cpu" #', ' cpu'):
        with pytest.raises(aw.SceneError) as e:
            aw.run(small_scene, device=device)
        assert e.value.key == "run.device"
        with pytest.raises(aw.SceneError):
            aw.accuracy(small_scene, device=device)


def test_output_rules(small_scene, tmp_path):
    out = tmp_path / "res"
    r = aw.run(small_scene, out=out)
    assert (out / "summary.json").exists()
    with pytest.raises(aw.OutputError) as e:  # exists: refused without force
        r.write(out)
    assert e.value.path.endswith("res")
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep me")
    with pytest.raises(aw.OutputRefused):  # not arnoldweb's: refused even with force
        r.write(tmp_path / "mine", force=True)
    assert (tmp_path / "mine" / "notes.txt").read_text() == "keep me"
    files = r.write(out, force=True)  # arnoldweb's own: replaced
    assert str(out / "summary.json") in files


def test_refused_output_is_checked_before_computing(small_scene, tmp_path, monkeypatch):
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep me")
    calls = []
    with pytest.raises(aw.OutputRefused):
        aw.run(small_scene, out=tmp_path / "mine", force=True, progress=lambda *a: calls.append(a))
    assert calls == []


def test_accuracy_arguments(small_scene):
    with pytest.raises(ValueError):
        aw.accuracy(small_scene, target=2.0)
    with pytest.raises(ValueError):
        aw.accuracy(small_scene, methods=["nope"])
