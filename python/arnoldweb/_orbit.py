"""Single orbits: the sampled states of chosen trajectories (observe.trajectories)."""
from __future__ import annotations

from typing import Optional

import numpy as np

from . import _arnoldweb as _core
from ._result import Result
from ._run import SceneLike, _on_device, _pair, _state_arrays, scene_of

__all__ = ["orbit", "Orbit"]


class Orbit:
    """The time series of one or more trajectories (:func:`orbit`), as trajectories.h5 holds
    them (docs/outputs.md):

    - ``t``: the sample times, shape (S + 1,), in T (0, every, ..., duration);
    - ``X``: the position, unwrapped, in radians: shape (n, S + 1, 3);
    - ``P``: the momentum: shape (n, S + 1, 3);
    - ``dE``: the energy error E(t) - E(0): shape (n, S + 1);
    - ``ids``: the trajectories (their index in the ensemble), shape (n,);
    - ``result``: the run's :class:`Result` (``result.outputs["trajectories"]`` holds every dataset).

    For a single trajectory (``id=``, or one state ``X`` of shape (3,)) the first axis is left
    out: ``X`` is (S + 1, 3) and ``dE`` (S + 1,)."""

    def __init__(self, result: Result, ids: np.ndarray, every: float, single: bool):
        d = result.outputs["trajectories"]
        self.result = result
        self.ids = ids
        self.X = d["position"]
        self.P = d["momentum"]
        self.dE = d["energy_error"]
        self.t = np.arange(self.dE.shape[1]) * every
        if single:
            self.X, self.P, self.dE = self.X[0], self.P[0], self.dE[0]

    def __repr__(self) -> str:
        return (f"Orbit(ids={self.ids.tolist()}, samples={self.t.size}, every={self.t[1] if self.t.size > 1 else 0:g} T, "
                f"max |dE|={float(np.max(np.abs(self.dE))):.3g})")


def orbit(scene: SceneLike, X=None, P=None, duration: Optional[float] = None, every: Optional[float] = None, *,
          id: Optional[int] = None, device: Optional[str] = None, units: str = "radians") -> Orbit:
    """The orbit of trajectories sampled every ``every`` T (default: the scene's
    observe.trajectories.every), as an :class:`Orbit` of numpy arrays (t, X, P, dE).

    - ``orbit(scene, X, P, duration, every)``: from the states ``X`` (positions in ``units``)
      and ``P`` (momenta), each of shape (3,) or (n, 3), for ``duration`` T (default:
      run.duration, which is then run.average too), as :func:`run` with ``initial=(X, P)``
      (checked the same way: StateError); the energy is sampled every ``every`` T.
    - ``orbit(scene, id=N, every=T)``: trajectory N of the scene's ensemble alone, with the bits
      it has in a run of the whole ensemble (as ``arnoldweb orbit SCENE --id N``).

    The scene's schedule is kept (integrator.step, the energy sample interval); its velocity
    maps, zoom and frames are left out (they sample nothing of an orbit). Nothing is written.
    Raises SceneError (an id outside the ensemble, an interval that does not divide the
    duration or is not a multiple of the shortest sample interval), StateError, DeviceError."""
    s = scene_of(scene)
    _on_device(s, device)
    for key in ("observe.velocity_map", "observe.zoom", "observe.frames"):
        s[key] = False
    s["run.slice"] = 0.0
    if every is None:  # the scene's (its key is echoed only while observe.trajectories is on), else the default
        every = s.to_dict()["observe"].get("trajectories") or {}
        every = every.get("every") or next(float(k["default"]) for k in _core.scene_keys()
                                           if k["key"] == "observe.trajectories.every")
    if (id is None) == (X is None):
        raise TypeError("orbit takes the states X, P or id=N (a trajectory of the scene's ensemble), one of them")
    if id is not None:
        if duration is not None:
            s["run.duration"] = duration
        s["observe.trajectories"] = {"ids": [int(id)], "every": float(every)}
        record = _core._run(s._scene, None, False, False, None, None, units, int(id))
        return Orbit(Result(record), np.array([int(id)]), float(every), True)
    single = np.ndim(X) == 1
    x, p = _state_arrays(*_pair((np.atleast_2d(X), np.atleast_2d(P))))
    if duration is not None:
        s["run.duration"] = duration
        s["run.average"] = duration
    s["observe.energy_error"] = {"every": float(every)}  # the segment: the orbit's sample interval
    s["observe.trajectories"] = {"count": len(x), "every": float(every)}
    record = _core._run(s._scene, None, False, False, x, p, units)
    return Orbit(Result(record), np.arange(len(x)), float(every), single)
