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
