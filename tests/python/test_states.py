"""Initial states as arrays (issue 25, item 1): aw.check_states and aw.run(initial=(X, P))
follow the rules of a state file (docs/outputs.md, "State files"); errors name the row."""
import numpy as np
import pytest

import arnoldweb as aw


def shell_states(n, energy=15.0, seed=3):
    """States on the energy shell of the paper's model: H = |P|^2/2 + cos x cos y (1 + cos 2z)."""
    rng = np.random.default_rng(seed)
    x = rng.uniform(-40.0, 40.0, size=(n, 3))  # unwrapped radians
    v = np.cos(x[:, 0]) * np.cos(x[:, 1]) * (1 + np.cos(2 * x[:, 2]))
    d = rng.normal(size=(n, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    return x, d * np.sqrt(2 * (energy - v))[:, None]


def test_check_states_gives_each_state_its_energy(small_scene):
    x, p = shell_states(500)
    r = aw.check_states(small_scene, x, p)
    assert r["count"] == 500
    assert r["energy"].shape == (500,)
    assert np.allclose(r["energy"], 15.0, rtol=0, atol=1e-12)
    assert r["energy_min"] <= r["energy_max"]
    # the same positions in turns
    r = aw.check_states(small_scene, x / (2 * np.pi), p, units="turns")
    assert np.allclose(r["energy"], 15.0, rtol=0, atol=1e-12)


def test_bad_arrays_name_the_array_and_the_row(small_scene):
    x, p = shell_states(50)
    with pytest.raises(aw.StateError) as e:
        aw.check_states(small_scene, x[:, :2], p)
    assert e.value.dataset == "X" and e.value.row == -1 and "must be (N, 3)" in str(e.value)
    p2 = p.copy()
    p2[17, 1] = np.nan
    with pytest.raises(aw.StateError) as e:
        aw.check_states(small_scene, x, p2)
    assert (e.value.source, e.value.dataset, e.value.row) == ("initial", "P", 17)
    with pytest.raises(aw.StateError) as e:
        aw.check_states(small_scene, x, 2 * p)
    assert e.value.row == 0 and "far from model.energy" in str(e.value)
    with pytest.raises(aw.StateError):
        aw.check_states(small_scene, x, p, units="degrees")
    assert isinstance(e.value, ValueError)


def test_run_with_initial_checks_the_states_then_starts_from_them(small_scene):
    x, p = shell_states(20)
    with pytest.raises(aw.StateError):
        aw.run(small_scene, initial=(x, 3 * p))
    with pytest.raises(TypeError):
        aw.run(small_scene, initial=x)
    small_scene = small_scene.set("observe.initial_states", True).set("observe.final_states", True)
    r = aw.run(small_scene, initial=(x, p))
    assert r.trajectories == 20 and r.completed == 20
    start = r.states["initial"]
    assert np.array_equal(start["momentum"], p)  # the momenta as given, bit for bit
    turns = x / (2 * np.pi)
    assert np.allclose(start["position_turns"], turns - np.rint(turns), rtol=0, atol=1e-15)
    # the same states again give the same bits; from turns too
    again = aw.run(small_scene, initial=(x, p))
    assert again.digests["final_states"] == r.digests["final_states"]
    in_turns = aw.run(small_scene, initial=(turns, p), units="turns")
    assert np.array_equal(in_turns.states["initial"]["momentum"], p)
