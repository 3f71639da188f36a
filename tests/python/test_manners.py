"""Python manners (issue 28): warnings, Scene as a mapping, messages in Python's words, integer
arrays, one last progress call, shipped scenes, python -m arnoldweb, extras, a clean namespace."""
import copy
import os
import subprocess
import sys
import warnings

import numpy as np
import pytest

import arnoldweb as aw
from conftest import SMALL, small_dict


def test_plan_warnings_go_through_warnings(small_scene):
    small_scene = small_scene.set("integrator.step", 0.05).set("integrator.allow_unsafe_step", True)
    with pytest.warns(aw.PlanWarning, match="integrator.step") as caught:
        r = aw.run(small_scene)
    assert issubclass(aw.PlanWarning, UserWarning)
    assert caught[0].filename == __file__  # pointed at the caller of run()
    assert [str(w.message) for w in caught] == r.summary["warnings"]


def test_plan_warning_as_error_stops_before_computing(small_scene):
    small_scene = small_scene.set("integrator.step", 0.05).set("integrator.allow_unsafe_step", True)
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


def test_scene_is_a_mapping_of_dotted_keys(small_scene):
    from collections.abc import Mapping, MutableMapping
    assert isinstance(small_scene, Mapping) and not isinstance(small_scene, MutableMapping)
    assert "model.energy" in small_scene
    assert "model.energi" not in small_scene and 3 not in small_scene
    keys = list(small_scene)
    assert keys == list(small_scene.keys()) and len(small_scene) == len(keys)
    assert "ensemble.trajectories" in keys and "observe.velocity_map.nside" in keys
    assert all(k in small_scene for k in keys)
    assert list(small_scene.values()) == [small_scene[k] for k in keys]
    assert dict(small_scene.items())["ensemble.trajectories"] == 3000 and dict(small_scene) == dict(small_scene.items())
    assert small_scene.get("model.energi", "none") == "none"
    # a table is not a key: "in" agrees with list(scene), and [] says what its keys are
    assert "observe" not in small_scene and "observe" not in keys
    with pytest.raises(KeyError, match="'model' is a table.*model.energy"):
        small_scene["model"]
    with pytest.raises(TypeError):
        del small_scene["model.energy"]


def test_set_returns_a_new_scene_and_item_assignment_changes_in_place(small_scene):
    base = small_scene
    hot = base.set("model.energy", 30.0)
    assert hot is not base and hot["model.energy"] == 30.0 and base["model.energy"] == 15.0
    cold = base.set("model.energy", 5.0)
    assert hot["model.energy"] == 30.0 and cold["model.energy"] == 5.0  # no aliasing between them
    base["model.energy"] = 20
    assert base["model.energy"] == 20.0 and hot["model.energy"] == 30.0
    assert base.overrides == ["model.energy=20"]
    with pytest.raises(aw.SceneError) as e:
        base["model.energy"] = 2e6
    assert e.value.file == "Scene.set('model.energy', 2000000.0)" and base["model.energy"] == 20.0


def test_floats_with_whole_values_are_integers_where_integers_are_asked(small_scene):
    import numpy as np
    s = small_scene.set("ensemble.trajectories", 1e6).set("observe.velocity_map.nside", np.float64(32))
    assert s["ensemble.trajectories"] == 1_000_000 and isinstance(s["ensemble.trajectories"], int)
    assert s["observe.velocity_map.nside"] == 32
    s = s.set("observe.velocity_map", {"nside": 8.0}).set("model.energy", 20)  # in a table; a float key takes 20
    assert s["observe.velocity_map.nside"] == 8 and s["model.energy"] == 20.0
    d = aw.Scene.from_dict({"ensemble": {"trajectories": 2e3}, "ensemble.initial": "grid",
                            "ensemble.grid": {"kind": "lonlat", "resolution": [32.0, 24.0]}})
    assert d["ensemble.trajectories"] == 2000 and d["ensemble.grid.resolution"] == [32, 24]
    with pytest.raises(aw.SceneError, match="must be an integer") as e:  # not a whole number: the library says so
        small_scene.set("ensemble.trajectories", 2.5)
    assert "write it as an integer" not in str(e.value)
    assert aw.pixel_directions(2.0).shape == (48, 3) and len(aw.resonances(np.int64(1))) > 0
    with pytest.raises(TypeError, match="nside must be a whole number, not 2.5"):
        aw.pixel_directions(2.5)
    with pytest.raises(ValueError, match="power of two"):
        aw.pixel_directions(3.0)


def test_scene_equality_and_repr(small_scene):
    same = aw.Scene.from_dict(SMALL)
    assert small_scene == same and small_scene is not same
    assert small_scene == aw.Scene.from_toml(small_scene.to_toml())  # equal as run, wherever from
    same = same.set("model.energy", 20.0)
    assert small_scene != same
    assert small_scene != "a scene"
    with pytest.raises(TypeError):
        hash(small_scene)
    text = repr(same)
    assert text.startswith("<arnoldweb.Scene <dict>") and "model.energy=20.0" in text
    assert "ensemble.trajectories=3000" in text and "1 overrides" in text
    shipped = repr(aw.scene("default"))  # by the name aw.scene takes, not its place in site-packages
    assert shipped.startswith("<arnoldweb.Scene scene('default'): ") and "/" not in shipped


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
    s = s.set("ensemble.grid", {"kind": "lonlat", "resolution": [32, 24]})
    assert "resolution = [32, 24]" in s.to_toml()
    assert s["ensemble.grid.resolution"] == [32, 24]
    assert all(isinstance(v, int) for v in s["ensemble.grid.resolution"])


def test_progress_last_call_once(small_scene):
    small_scene = small_scene.set("ensemble.chunk", 1000)
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


def test_shipped_scenes_by_name_for_run_and_the_cli(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # no file "default" here
    from arnoldweb._run import scene_of  # what run(), check_states() and accuracy() read
    assert scene_of("default") == aw.scene("default")
    (tmp_path / "default").write_text("[model]\nenergy = 20.0\n")  # a file of that name is read first
    assert scene_of("default")["model.energy"] == 20.0
    from conftest import cli_path
    (tmp_path / "default").unlink()
    done = subprocess.run([cli_path(), "check", "fig3_e15"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "fig3_e15.toml" in done.stdout


def test_internal_names_stay_inside():
    import inspect
    import traceback
    try:
        aw.Scene.from_toml("[model]\nenergy = 2e6\n")
    except aw.SceneError:
        text = traceback.format_exc()
    assert "arnoldweb.SceneError: " in text and "_errors" not in text
    for cls in (aw.Scene, aw.Result, aw.Orbit, aw.Error, aw.SceneError, aw.StateError, aw.PlanWarning, aw.OutputRefused):
        assert cls.__module__ == "arnoldweb", cls
    for fn in (aw.run, aw.continue_run, aw.load, aw.orbit, aw.potential, aw.Scene.set, aw.Scene.from_file, aw.Result.write):
        sig = inspect.signature(fn)  # help() shows each annotation once quoted ('str | None'), not twice
        hints = [p.annotation for p in sig.parameters.values()] + [sig.return_annotation]
        assert not [h for h in hints if isinstance(h, str) and ("'" in h or '"' in h)], sig
        assert "_scene" not in str(sig) and "_result" not in str(sig), sig
    usage = subprocess.run([sys.executable, "-m", "arnoldweb", "run", "--help"], capture_output=True, text=True,
                           timeout=120)
    assert usage.returncode == 0 and "Usage: arnoldweb run [OPTIONS] scene" in usage.stdout
    assert "site-packages" not in usage.stdout + usage.stderr


def test_map_of_a_run_without_one_is_empty_not_none(small_scene):
    r = aw.run(small_scene.set("observe.velocity_map", False).set("observe.final_states", True))
    assert isinstance(r.map, np.ndarray) and r.map.shape == (0,) and r.map.dtype == np.uint64 and r.nside == 0
    assert r.map.sum() == 0
    assert "nside 0" not in repr(r) and "no velocity map" in repr(r)
    assert "nside 16" in repr(aw.run(small_scene))


def test_energy_histogram_comes_with_its_edges(small_scene):
    e = aw.run(small_scene).energy
    hist, edges = e["log_hist"], e["log_hist_edges"]
    assert hist.dtype == np.uint64 and edges.dtype == np.float64 and edges.shape == (hist.size + 1,)
    assert edges[0] == 0 and edges[1] == 2.0 ** -64 and edges[-2] == 2.0 ** 16 and edges[-1] == np.inf
    assert np.all(np.diff(edges) > 0) and edges[5] == 2.0 ** -63  # four bins per octave
    assert hist.sum() == 3000
    # the largest error lies in the last bin that counts one, and the median bound is an edge
    last = np.flatnonzero(hist)[-1]
    assert edges[last] <= e["max"] < edges[last + 1]
    assert e["median_upper_bound"] in edges


def test_device_all_without_a_gpu_says_so(small_scene):
    if any(not d["is_cpu"] for d in aw.devices()):
        pytest.skip("this machine has a GPU: device='all' runs on it")
    with pytest.warns(aw.PlanWarning, match='device "all" runs on every GPU, and this machine has none') as caught:
        r = aw.run(small_scene.set("ensemble.trajectories", 200), device="all")
    assert aw.default_device() in str(caught[0].message) and r.device["id"] == aw.default_device()


def test_check_states_names_the_shape_numpy_has(small_scene):
    with pytest.raises(aw.StateError) as e:
        aw.check_states(small_scene, np.zeros(3), np.zeros((1, 3)))
    assert e.value.dataset == "X" and "has the shape (3,);" in str(e.value) and "(3, 1)" not in str(e.value)
    with pytest.raises(aw.StateError, match=r"P: has the shape \(2, 3, 1\)"):
        aw.check_states(small_scene, np.zeros((2, 3)), np.zeros((2, 3, 1)))


def test_out_dot_is_refused_without_suggesting_force(small_scene, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    for force in (False, True):
        with pytest.raises(aw.OutputRefused) as e:
            aw.run(small_scene, out=".", force=force)
        assert "current directory" in str(e.value) and "force=True" not in str(e.value)


def test_docstrings_name_what_there_is(small_scene):
    plan = small_scene.check()
    documented = aw.Scene.check.__doc__.split("Returns the plan as a dict:")[1]
    for key in plan:
        assert key in documented, key
    for word in ("schedule", "work ("):
        assert word not in documented


def test_a_missing_tool_names_a_pip_install_that_works(monkeypatch, tmp_path):
    from arnoldweb import _saved
    monkeypatch.setitem(sys.modules, "h5py", None)  # as without h5py
    with pytest.raises(ImportError) as e:
        _saved._h5py(str(tmp_path / "states.h5"))
    assert "pip install h5py" in str(e.value) and "[plots]" not in str(e.value)


def test_the_docstring_example_warns_nothing(repo):
    # Scene.set's own example: a higher energy with the step it needs (the step is in T, not E)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        aw.scene("default").set("model.energy", 30).set("integrator.step", 0.01).check()
    assert 'set("integrator.step", 0.01)' in aw.Scene.set.__doc__


def test_progress_in_a_notebook_is_a_bar_without_warnings(small_scene):
    from arnoldweb import _progress
    pytest.importorskip("tqdm")
    assert _progress._tqdm().__module__ == "tqdm.std"  # outside a notebook: the text bar
    assert not _progress._in_notebook()
