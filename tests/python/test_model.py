"""The scene's model from Python (issue 38, item 2): aw.potential, aw.energy, aw.shell_momenta,
evaluated by the library's own model code; held against the C++ (check_states, the same code)
and against the initial states every device makes."""
import numpy as np
import pytest

import arnoldweb as aw
from conftest import small_dict


def paper_v(x):
    """V of the paper's model, H = |P|^2/2 + cos x cos y (1 + cos 2z), in numpy."""
    return np.cos(x[..., 0]) * np.cos(x[..., 1]) * (1 + np.cos(2 * x[..., 2]))


def test_values_shapes_and_units(small_scene):
    v0 = aw.potential(small_scene, [0.0, 0.0, 0.0])
    assert v0.shape == () and v0 == 2.0  # cos 0 cos 0 (1 + cos 0)
    rng = np.random.default_rng(1)
    x = rng.uniform(-20, 20, size=(4, 5, 3))  # any leading shape, unwrapped radians
    v = aw.potential(small_scene, x)
    assert v.shape == (4, 5) and v.dtype == np.float64
    np.testing.assert_allclose(v, paper_v(x), rtol=0, atol=1e-13)
    np.testing.assert_array_equal(aw.potential(small_scene, x / (2 * np.pi), units="turns"), v)
    p = rng.normal(size=(4, 5, 3))
    np.testing.assert_allclose(aw.energy(small_scene, x, p), 0.5 * (p ** 2).sum(-1) + paper_v(x), rtol=1e-15,
                               atol=1e-13)
    # broadcasting: one position, many momenta
    assert aw.energy(small_scene, x[0, 0], p).shape == (4, 5)
    assert aw.potential("default", x).shape == (4, 5)  # a shipped scene by name


def test_energy_is_what_check_states_gives_bit_for_bit(small_scene):
    rng = np.random.default_rng(2)
    x = rng.uniform(-40, 40, size=(300, 3))
    d = rng.normal(size=(300, 3))
    p = aw.shell_momenta(small_scene, x, d)
    checked = aw.check_states(small_scene, x, p)  # the C++ rules of a state file
    np.testing.assert_array_equal(aw.energy(small_scene, x, p), checked["energy"])
    np.testing.assert_allclose(checked["energy"], 15.0, rtol=1e-13)


def test_shell_momenta_lie_on_the_shell_along_the_directions(small_scene):
    rng = np.random.default_rng(3)
    x = rng.uniform(-np.pi, np.pi, size=(200, 3))
    d = rng.normal(size=(200, 3)) * rng.uniform(0.1, 10, size=(200, 1))  # any length
    p = aw.shell_momenta(small_scene, x, d)
    assert p.shape == (200, 3)
    np.testing.assert_allclose(aw.energy(small_scene, x, p), 15.0, rtol=1e-13)
    unit = d / np.linalg.norm(d, axis=1)[:, None]
    np.testing.assert_allclose(p / np.linalg.norm(p, axis=1)[:, None], unit, rtol=0, atol=1e-15)
    # one position, every HEALPix direction: the shell at that point
    shell = aw.shell_momenta(small_scene, x[0], aw.pixel_directions(4))
    assert shell.shape == (192, 3)
    np.testing.assert_allclose(np.linalg.norm(shell, axis=1), np.sqrt(2 * (15.0 - paper_v(x[0]))), rtol=1e-14)


def test_no_momentum_below_the_potential_is_nan():
    low = aw.Scene.from_dict(small_dict(model={"energy": 0.5}))
    p = aw.shell_momenta(low, [[0.0, 0.0, 0.0], [np.pi / 2, 0.0, 0.0]], [1.0, 0.0, 0.0])  # V = 2, then V = 0
    assert np.isnan(p[0]).all() and np.allclose(p[1], [1.0, 0.0, 0.0])


def test_bad_arguments_say_what_is_wrong(small_scene):
    with pytest.raises(ValueError, match=r"X has the shape \(4, 2\); it must be \(3,\) or \(\.\.\., 3\)"):
        aw.potential(small_scene, np.zeros((4, 2)))
    with pytest.raises(ValueError, match="do not broadcast"):
        aw.energy(small_scene, np.zeros((4, 3)), np.zeros((5, 3)))
    with pytest.raises(ValueError, match="directions: row 1 is .* length > 0"):
        aw.shell_momenta(small_scene, np.zeros(3), [[1.0, 0, 0], [0.0, 0, 0]])
    with pytest.raises(ValueError, match='units is "degrees"'):
        aw.potential(small_scene, np.zeros(3), units="degrees")
    with pytest.raises(aw.SceneError, match="model.epsilon"):  # another model's key: the planner's error
        aw.potential(small_scene.set("model.epsilon", 0.5), np.zeros(3))


def test_other_models_the_fourier_kinetic_form():
    s = aw.Scene.from_dict(small_dict(model={"kind": "fourier", "energy": 3.0,
                                             "harmonics": [[1, 0, 0, 0.5, 0.25], [0, 2, -1, 1.5, 0]],
                                             "kinetic_a": [1, 0.5, 2], "kinetic_b": [0, 0.25, -0.5]}))
    rng = np.random.default_rng(4)
    x = rng.uniform(-np.pi, np.pi, size=(100, 3))
    v = 0.5 * np.cos(x[:, 0] + 0.25) + 1.5 * np.cos(2 * x[:, 1] - x[:, 2])
    np.testing.assert_allclose(aw.potential(s, x), v, rtol=0, atol=1e-13)
    p = aw.shell_momenta(s, x, rng.normal(size=(100, 3)))
    ok = ~np.isnan(p[:, 0])
    assert ok.sum() > 50
    t = (np.array([1, 0.5, 2]) * p[ok] ** 2 / 2 + np.array([0, 0.25, -0.5]) * p[ok]).sum(1)
    np.testing.assert_allclose(t + v[ok], 3.0, rtol=1e-13)


@pytest.mark.parametrize("device", [d["id"] for d in aw.devices()])
def test_every_devices_initial_states_are_on_the_shell_and_found_again(device):
    scene = aw.Scene.from_dict(small_dict(ensemble={"trajectories": 2000, "seed": 11},
                                          observe={"initial_states": True, "velocity_map": False}))
    r = aw.run(scene, device=device)
    x = 2 * np.pi * r.states["initial"]["position_turns"]
    p = r.states["initial"]["momentum"]
    np.testing.assert_allclose(aw.energy(scene, x, p), 15.0, rtol=1e-13)
    again = aw.shell_momenta(scene, x, p)  # the directions of the states themselves
    assert np.abs(again - p).max() < 1e-15 * np.abs(p).max() * 8
    assert r.digests["initial_states"] == aw.run(scene, device="cpu").digests["initial_states"]


def test_states_built_with_shell_momenta_run(small_scene):
    rng = np.random.default_rng(6)
    x = rng.uniform(-np.pi, np.pi, size=(500, 3))
    p = aw.shell_momenta(small_scene, x, aw.pixel_directions(4)[rng.integers(0, 192, 500)])
    r = aw.run(small_scene, initial=(x, p))
    assert r.completed == 500 and r.map.sum() > 0
