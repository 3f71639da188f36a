"""Persistence (issue 28): Scene and Result pickle and deep-copy; arnoldweb.load gives back the
Result of a run's output directory, checked against its digests."""
import copy
import json
import pickle

import numpy as np
import pytest

import arnoldweb as aw
from conftest import small_dict


def assert_same_arrays(a, b):
    """Equal bit for bit: same dtype, shape and bytes (NaNs included)."""
    assert type(a) is type(b)
    if isinstance(a, dict):
        assert a.keys() == b.keys()
        for k in a:
            assert_same_arrays(a[k], b[k])
    elif isinstance(a, np.ndarray):
        assert a.dtype == b.dtype and a.shape == b.shape
        assert a.tobytes() == b.tobytes()
    else:
        assert a == b


@pytest.fixture
def full_result():
    """A run with every kind of array: map, zoom, frames, states, indicators, and a panel."""
    d = small_dict(observe={"initial_states": True, "final_states": True, "fli": True,
                            "zoom": {"center": [45.0, 0.0], "width": 60.0, "resolution": 16},
                            "frames": {"times": [0.0, 5.0]}})
    d["panel"] = [{"name": "hot", "title": "E = 16", "set": ["model.energy=16", "ensemble.trajectories=500"]}]
    return aw.run(aw.Scene.from_dict(d))


FIELDS = ("map", "frames", "zoom", "states", "indicators", "outputs", "counters", "digests", "device", "nside", "name")


def test_scene_pickles_and_deep_copies(small_scene):
    small_scene = small_scene.set("model.energy", 20.0)
    for other in (pickle.loads(pickle.dumps(small_scene)), copy.deepcopy(small_scene), copy.copy(small_scene)):
        assert other == small_scene and other is not small_scene
        assert other.overrides == small_scene.overrides and other.file == small_scene.file
        other["model.energy"] = 30.0  # changed in place: the copy is independent
        assert small_scene["model.energy"] == 20.0 and other["model.energy"] == 30.0


def test_result_pickles_bit_for_bit(full_result):
    r = full_result
    back = pickle.loads(pickle.dumps(r))
    for name in FIELDS:
        assert_same_arrays(getattr(back, name), getattr(r, name))
    assert back.summary == r.summary and back.energy.keys() == r.energy.keys()
    assert back.binned == r.binned and back.interrupted is False
    assert not back.map.flags.writeable
    assert list(back.panels) == ["hot"]
    assert_same_arrays(back.panels["hot"].map, r.panels["hot"].map)
    assert back.panels["hot"].title == "E = 16"
    assert repr(back) == repr(r)


def test_result_deep_copy_is_independent(full_result):
    r = full_result
    c = copy.deepcopy(r)
    for name in FIELDS:
        assert_same_arrays(getattr(c, name), getattr(r, name))
    assert not np.shares_memory(c.map, r.map)
    with pytest.raises(aw.OutputError, match="loaded, unpickled or copied"):
        c.write("/tmp/never-written")


def test_load_gives_the_saved_run(full_result, tmp_path):
    r = full_result
    out = tmp_path / "run"
    r.write(out)
    back = aw.load(out)
    for name in ("map", "frames", "zoom", "nside", "counters", "device"):
        assert_same_arrays(getattr(back, name), getattr(r, name))
    assert back.digests["map"] == r.digests["map"] and back.digests["final_states"] == r.digests["final_states"]
    for group in ("initial", "final"):
        for k, v in r.states[group].items():
            np.testing.assert_array_equal(back.states[group][k], v)
    assert back.indicators.dtype.names == aw.INDICATOR_NAMES
    np.testing.assert_array_equal(back.indicators["fli"], r.indicators["fli"])
    assert back.summary == json.loads((out / "summary.json").read_text())
    assert back.energy["max"] == r.energy["max"]
    assert back.panels["hot"].binned == r.panels["hot"].binned
    assert_same_arrays(back.panels["hot"].map, r.panels["hot"].map)
    assert_same_arrays(pickle.loads(pickle.dumps(back)).map, r.map)


def test_load_gives_every_output_back(tmp_path):
    # frequencies.h5, diffusion.h5, indicators.h5 and states.h5 of an fgl grid: Result.outputs of
    # the loaded directory (and of a pickle of it) equal the run's, dataset for dataset
    scene = aw.scene("fgl_frequency_map").set("ensemble.grid.resolution", [6, 5]).set("output.images", False)
    scene = scene.set("observe.diffusion", {"every": 40.96, "along": [1, 1, 0], "across": [1, -1, 0]})
    scene = scene.set("observe.final_states", True).set("run.device", "cpu")
    r = aw.run(scene, out=tmp_path / "run")
    assert {"frequencies", "actions", "indicators", "final_states"} <= set(r.outputs)
    for back in (aw.load(tmp_path / "run"), pickle.loads(pickle.dumps(aw.load(tmp_path / "run")))):
        assert back.outputs.keys() == r.outputs.keys()
        for name, datasets in r.outputs.items():
            assert back.outputs[name].keys() == datasets.keys(), name
            for k, v in datasets.items():
                np.testing.assert_array_equal(back.outputs[name][k], v)
                assert back.outputs[name][k].shape == v.shape


def test_load_checks_the_digest_and_names_bad_files(small_scene, tmp_path):
    out = tmp_path / "run"
    aw.run(small_scene, out=out)
    summary = json.loads((out / "summary.json").read_text())
    summary["digests"]["map"] = "0" * 32
    (out / "summary.json").write_text(json.dumps(summary))
    with pytest.raises(aw.OutputError, match="map.h5") as e:
        aw.load(out)
    assert e.value.path.endswith("map.h5")
    with pytest.raises(aw.OutputError, match="summary.json"):
        aw.load(tmp_path / "nothing-here")


def test_results_are_equal_when_their_numbers_are(full_result, small_scene, tmp_path):
    r = full_result
    r.write(tmp_path / "run")
    loaded = aw.load(tmp_path / "run")
    for other in (pickle.loads(pickle.dumps(r)), copy.deepcopy(r), loaded, pickle.loads(pickle.dumps(loaded))):
        assert other == r and r == other and not (other != r)
    assert loaded.panels["hot"] == r.panels["hot"] and loaded.panels["hot"] != r
    # the energy histogram and its edges come back from the directory too
    assert_same_arrays(loaded.energy["log_hist"], r.energy["log_hist"])
    assert_same_arrays(loaded.energy["log_hist_edges"], r.energy["log_hist_edges"])
    # another run of the same scene (another wall time) is equal; another seed is not
    again = aw.run(aw.Scene.from_dict(r.summary["scene"]))
    assert again == r
    other_seed = aw.run(small_scene.set("ensemble.seed", 8))
    assert other_seed != aw.run(small_scene) and r != "a result"
    with pytest.raises(TypeError):
        hash(r)
