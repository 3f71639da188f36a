"""Single orbits (issue 38, item 2): aw.orbit(scene, id=N) gives trajectory N with the bits it has in
the run of all (Result.outputs["trajectories"] of observe.trajectories ids = [N]), and
aw.orbit(scene, X, P, duration, every) the time series of given states."""
import numpy as np
import pytest

import arnoldweb as aw
from conftest import small_dict


def test_orbit_of_an_id_is_its_row_in_the_run_of_all():
    scene = aw.Scene.from_dict(small_dict(observe={"trajectories": {"ids": [40, 2999], "every": 1.0},
                                                   "final_states": True}))
    all_ = aw.run(scene)
    rows = all_.outputs["trajectories"]
    assert rows["momentum"].shape == (2, 6, 3) and rows["energy_error"].shape == (2, 6)
    # the last sample is the final state of states.h5
    assert np.array_equal(rows["momentum"][1, -1], all_.outputs["final_states"]["momentum"][2999])
    o = aw.orbit(scene, id=2999)
    assert o.X.shape == (6, 3) and o.P.shape == (6, 3) and o.dE.shape == (6,)
    assert np.array_equal(o.t, np.arange(6.0))
    assert np.array_equal(o.P, rows["momentum"][1])
    assert np.array_equal(o.X, rows["position"][1])
    assert np.array_equal(o.dE, rows["energy_error"][1])
    assert o.result.completed == 1
    assert o.dE[0] == 0 and 0 < np.abs(o.dE).max() < 1e-4


def test_orbit_of_states_and_refusals():
    scene = aw.Scene.from_dict(small_dict())
    x = np.array([[0.1, 0.2, 0.3], [1.0, -2.0, 0.5]])
    p = aw.shell_momenta(scene, x, np.array([[1.0, 0.3, 0.2], [0.2, -1.0, 0.4]]))
    o = aw.orbit(scene, x, p, 4.0, 0.5)
    assert o.X.shape == (2, 9, 3) and o.dE.shape == (2, 9)
    assert np.array_equal(o.t, np.arange(9) * 0.5)
    assert np.allclose(o.X[:, 0], x, rtol=0, atol=1e-15) and np.array_equal(o.P[:, 0], p)
    assert np.abs(o.dE).max() < 1e-4
    one = aw.orbit(scene, x[1], p[1], 4.0, 0.5)  # one state: no first axis
    assert one.X.shape == (9, 3) and np.array_equal(one.P, o.P[1])
    with pytest.raises(aw.SceneError, match="observe.trajectories.ids"):
        aw.orbit(scene, id=3000)
    with pytest.raises(aw.SceneError, match="observe.trajectories.every"):
        aw.orbit(scene, id=3, every=0.3)
    with pytest.raises(TypeError):
        aw.orbit(scene)


def test_orbit_frequencies_of_free_motion_are_its_momenta():
    # the paper's model with its six harmonics at amplitude 0 (fourier): free motion, nu = P turns per T
    harmonics = [[1, 1, 0, 0.0, 0.0], [1, -1, 0, 0.0, 0.0], [1, 1, 2, 0.0, 0.0], [1, 1, -2, 0.0, 0.0],
                 [1, -1, 2, 0.0, 0.0], [1, -1, -2, 0.0, 0.0]]
    scene = aw.Scene.from_dict(small_dict(model={"kind": "fourier", "harmonics": harmonics, "energy": 1.0},
                                          integrator={"method": "yoshida6a", "step": 0.01},
                                          observe={"velocity_map": False, "energy_error": {"every": 0.05}}))
    x = np.array([[0.1, 0.2, 0.3], [2.0, -1.0, 5.0]])
    p = np.array([[1.1, -0.7, np.sqrt(0.3)], [0.2, 1.3, -np.sqrt(2 - 0.04 - 1.69)]])  # |P|^2 = 2E
    o = aw.orbit(scene, x, p, 5.0, 0.05)
    t, nu = o.frequencies(32, step=8)
    assert nu.shape == (2, 9, 3) and t.shape == (9,)
    assert np.allclose(t, 0.05 * (np.arange(9) * 8 + 15.5), rtol=0, atol=1e-12)  # the windows' centres
    assert np.abs(nu - p[:, None, :]).max() < 1e-12  # measured: 1.2e-14
    for p_order in (0, 2, 4):
        assert np.abs(o.frequencies(100, window=p_order)[1] - p[:, None, :]).max() < 1e-12


def test_orbit_frequencies_are_those_of_observe_frequencies():
    # the default scene's model (E = 15); observe.frequencies' windows are samples 1..256 and
    # 257..512 of the orbit sampled at its interval: windows 1 and 257 of step 1
    scene = aw.scene("default").set("ensemble.trajectories", 4000).set("observe.velocity_map", False)
    scene["observe.frequencies"] = {"samples": 256, "every": 0.05}
    regular = aw.orbit(scene, id=3298, every=0.05)  # its diffusion index: -6.2
    chaotic = aw.orbit(scene, id=0, every=0.05)     # +0.25
    for o in (regular, chaotic):
        f = o.result.outputs["frequencies"]
        t, nu = o.frequencies(256, step=1)
        assert t.shape == (746,) and abs(t[1] - 0.05 * (1 + 255 / 2)) < 1e-12
        assert np.abs(nu[1] - f["nu_first"][0]).max() < 1e-12
        assert np.abs(nu[257] - f["nu_second"][0]).max() < 1e-12
    spread = lambda o: np.ptp(o.frequencies(256, step=64)[1], axis=0).max()  # noqa: E731
    assert spread(regular) < 2e-6 < 0.1 < spread(chaotic)  # regular: constant up to the window's leakage


def test_orbit_frequencies_refuse_bad_arguments():
    scene = aw.Scene.from_dict(small_dict(observe={"energy_error": {"every": 0.1}}))
    o = aw.orbit(scene, id=3, every=0.1)  # 51 samples
    assert o.frequencies(51)[1].shape == (1, 3)
    with pytest.raises(ValueError, match=r"samples = 15: outside the allowed range, 16 to 51 \(the orbit's 51"):
        o.frequencies(15)
    with pytest.raises(ValueError, match="samples = 52: outside the allowed range, 16 to 51"):
        o.frequencies(52)
    with pytest.raises(TypeError, match="samples must be a whole number, not 20.5"):
        o.frequencies(20.5)
    with pytest.raises(ValueError, match="step = 0: outside the allowed range, >= 1"):
        o.frequencies(20, 0)
    with pytest.raises(ValueError, match="window = 5: outside the allowed range, 0 to 4"):
        o.frequencies(20, window=5)
    assert o.frequencies(20.0, 10.0)[1].shape == (4, 3)  # whole floats are whole numbers
    o.X = o.X.copy()
    o.X[25, 0] = np.nan  # a flagged trajectory's sample: the windows that hold it (10-29, 20-39) give NaN
    nu = o.frequencies(20, 10)[1]
    assert np.isnan(nu[1:3, 0]).all() and np.isfinite(nu[[0, 3], 0]).all() and np.isfinite(nu[:, 1:]).all()


def test_orbit_plot_frequencies():
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    scene = aw.Scene.from_dict(small_dict(observe={"energy_error": {"every": 0.1}}))
    o = aw.orbit(scene, id=3, every=0.1)
    ax = o.plot_frequencies(32, 4)
    t, nu = o.frequencies(32, 4)
    lines = ax.get_lines()
    assert len(lines) == 3 and all(np.array_equal(line.get_xdata(), t) for line in lines)
    assert np.array_equal(lines[2].get_ydata(), nu[:, 2])
    two = aw.orbit(scene, np.zeros((2, 3)), aw.shell_momenta(scene, np.zeros((2, 3)), np.eye(3)[:2]), 2.0, 0.1)
    with pytest.raises(ValueError, match="one trajectory"):
        two.plot_frequencies(16)
