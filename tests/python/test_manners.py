"""Python manners (issue 28): warnings, Scene as a mapping, messages in Python's words, integer
arrays, one last progress call, shipped scenes, python -m arnoldweb, extras, a clean namespace."""
import copy
import os
import subprocess
import sys
import warnings

import pytest

import arnoldweb as aw
from conftest import SMALL, small_dict


def test_plan_warnings_go_through_warnings(small_scene):
    small_scene.set("integrator.step", 0.05).set("integrator.allow_unsafe_step", True)
    with pytest.warns(aw.PlanWarning, match="integrator.step") as caught:
        r = aw.run(small_scene)
    assert issubclass(aw.PlanWarning, UserWarning)
    assert caught[0].filename == __file__  # pointed at the caller of run()
    assert [str(w.message) for w in caught] == r.summary["warnings"]


def test_plan_warning_as_error_stops_before_computing(small_scene):
    small_scene.set("integrator.step", 0.05).set("integrator.allow_unsafe_step", True)
    calls = []
    with warnings.catch_warnings():
        warnings.simplefilter("error", aw.PlanWarning)
        with pytest.raises(aw.PlanWarning):
            aw.run(small_scene, progress=lambda *a: calls.append(a))
    assert calls == []


def test_a_plain_scene_warns_nothing(small_scene):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        aw.run(small_scene)


def test_scene_in_iteration_len_and_items(small_scene):
    assert "model.energy" in small_scene
    assert "observe" in small_scene  # a table
    assert "model.energi" not in small_scene and 3 not in small_scene
    keys = list(small_scene)
    assert keys == small_scene.keys() and len(small_scene) == len(keys)
    assert "ensemble.trajectories" in keys and "observe.velocity_map.nside" in keys
    assert all(k in small_scene for k in keys)
    assert dict(small_scene.items())["ensemble.trajectories"] == 3000
    assert small_scene.get("model.energi", "none") == "none"


def test_scene_equality_and_repr(small_scene):
    same = aw.Scene.from_dict(SMALL)
    assert small_scene == same and small_scene is not same
    assert small_scene == aw.Scene.from_toml(small_scene.to_toml())  # equal as run, wherever from
    same.set("model.energy", 20.0)
    assert small_scene != same
    assert small_scene != "a scene"
    with pytest.raises(TypeError):
        hash(small_scene)
    text = repr(same)
    assert text.startswith("<arnoldweb.Scene <dict>") and "model.energy=20.0" in text
    assert "ensemble.trajectories=3000" in text and "1 overrides" in text


def test_set_errors_name_scene_set(small_scene):
    with pytest.raises(aw.SceneError) as e:
        small_scene.set("model.energi", 30)
    assert e.value.file == "Scene.set('model.energi', 30)"
    assert "--set" not in str(e.value) and "Scene.set('model.energi', 30)" in str(e.value)


def test_output_errors_name_force_and_out(small_scene, tmp_path):
    r = aw.run(small_scene, out=tmp_path / "res")
    with pytest.raises(aw.OutputError) as e:
        aw.run(small_scene, out=tmp_path / "res")
    message = str(e.value)
    assert "--force" not in message and "--out" not in message
    assert "force=True" in message and "out=" in message
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("keep me")
    with pytest.raises(aw.OutputRefused) as e:
        r.write(tmp_path / "mine", force=True)
    assert "--" not in str(e.value)


def test_integer_arrays_stay_integers():
    keys = {k["key"]: k for k in aw.scene_keys()}
    assert keys["ensemble.grid.resolution"]["default"] == "[64, 64]"
    assert keys["ensemble.grid.axes"]["default"] == "[0, 1]"
    s = aw.Scene.from_dict(small_dict(ensemble={"initial": "grid", "trajectories": 12 * 64},
                                      observe={"fli": True}))
    s.set("ensemble.grid", {"kind": "lonlat", "resolution": [32, 24]})
    assert "resolution = [32, 24]" in s.to_toml()
    assert s["ensemble.grid.resolution"] == [32, 24]
    assert all(isinstance(v, int) for v in s["ensemble.grid.resolution"])


def test_progress_last_call_once(small_scene):
    small_scene.set("ensemble.chunk", 1000)
    seen = []
    aw.run(small_scene, progress=lambda done, total, seconds: seen.append(done))
    assert seen == [1000, 2000, 3000]


def test_shipped_scenes():
    names = aw.scenes()
    assert {"default", "fig3_e15", "fli_e15"} <= set(names)
    s = aw.scene("default")
    assert s["model.energy"] == 15.0 and s.file.endswith("default.toml")
    with pytest.raises(ValueError, match="did you mean 'default'"):
        aw.scene("defualt")


def test_python_m_arnoldweb_runs_the_cli():
    done = subprocess.run([sys.executable, "-m", "arnoldweb", "methods"], capture_output=True, text=True,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    assert "yoshida6" in done.stdout
    bad = subprocess.run([sys.executable, "-m", "arnoldweb", "run", "/nonexistent.toml"], capture_output=True,
                         text=True, timeout=120)
    assert bad.returncode == 2 and "/nonexistent.toml" in bad.stderr


def test_extras_name_h5py_and_healpy():
    from importlib import metadata
    requires = metadata.requires("arnoldweb") or []
    plots = [r for r in requires if 'extra == "plots"' in r]
    assert any(r.startswith("h5py") for r in plots) and any(r.startswith("healpy") for r in plots)
    assert not any(r.startswith(("h5py", "healpy")) for r in requires if "extra ==" not in r)


def test_namespace_is_clean():
    assert not hasattr(aw, "annotations")
    public = {n for n in dir(aw) if not n.startswith("_")}
    assert public <= set(aw.__all__), public - set(aw.__all__)
    assert set(aw.__all__) <= set(dir(aw))


def test_without_the_pictures_plugin_import_and_run_work_and_say_why(tmp_path):
    # as on a machine without cairo's X11 libraries (the GPU machine's image lacks libXrender):
    # the package imports, runs write their numbers, and a run that writes says why it drew no
    # pictures; one that writes nothing warns nothing
    code = f"""
import os, warnings, arnoldweb as aw
scene = aw.Scene.from_dict({small_dict(output={"images": True})!r})
with warnings.catch_warnings():
    warnings.simplefilter("error")
    aw.run(scene)
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    aw.run(scene, out={str(tmp_path / "out")!r})
print("WARN", [str(w.message) for w in caught if issubclass(w.category, aw.PlanWarning)])
print("FILES", sorted(os.listdir({str(tmp_path / "out")!r})))
"""
    env = dict(os.environ, ARNOLDWEB_PICTURES=str(tmp_path / "gone" / "libarnoldweb_pictures.so"))
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    warned = [line for line in done.stdout.splitlines() if line.startswith("WARN")][0]
    assert "no pictures will be drawn" in warned and "gone/libarnoldweb_pictures.so" in warned
    files = [line for line in done.stdout.splitlines() if line.startswith("FILES")][0]
    assert "map.h5" in files and "summary.json" in files and ".png" not in files
