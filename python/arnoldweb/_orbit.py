"""Single orbits: the sampled states of chosen trajectories (observe.trajectories)."""
from __future__ import annotations

from typing import Optional, Tuple

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
    out: ``X`` is (S + 1, 3) and ``dE`` (S + 1,). :meth:`frequencies` gives the angles'
    frequencies over sliding windows, :meth:`plot_frequencies` draws them."""

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

    def frequencies(self, samples: int, step: Optional[int] = None,
                    window: int = 1) -> Tuple[np.ndarray, np.ndarray]:
        """The leading frequency of each angle over sliding windows of ``samples`` samples, the
        first window from the first sample, the next ``step`` samples later (default
        ``samples``: consecutive windows): returns ``(t, nu)``, ``t`` the windows' centre times
        (T), shape (W,), and ``nu`` in turns per T, shape (W, 3), or (n, W, 3) for several
        trajectories.

        Each is the frequency of the largest term of the angle's signal exp(i X(t)), the
        maximum observe.frequencies finds (docs/frequencies.md), in numpy: under Laskar's window
        chi_p of order ``window`` (1: Hanning, 0 to 4), the highest peak of the windowed samples'
        FFT (padded to at least twice the window), refined by Newton steps on the windowed
        transform to round-off, and of its aliases (every ``every`` T) the one nearest the
        angle's mean rate over the window (two maxima less than a bin apart: either may win).
        For a rotating angle that is its rate of rotation; for a librating one a harmonic of
        the libration about the centre's rate (docs/frequencies.md, "Limits").
        observe.frequencies' first window is samples 1 to ``samples`` of an orbit sampled at its
        interval (``step=1``: window 1), the second the next ``samples``: their nu_first and
        nu_second are these to round-off (pytest
        ``test_orbit_frequencies_are_those_of_observe_frequencies``). A window of a
        flagged trajectory (not finite) gives NaN. Raises ValueError naming the argument and its
        allowed range, TypeError where it is not a whole number."""
        n = _in_range("samples", samples, 16, self.t.size, f" (the orbit's {self.t.size} samples)")
        step = _in_range("step", n if step is None else step, 1, None)
        p = _in_range("window", window, 0, 4)
        every = float(self.t[1])
        series = np.moveaxis(self.X, -1, -2).reshape(-1, self.t.size)  # (trajectories x 3 angles, S + 1)
        starts = np.arange(0, self.t.size - n + 1, step)
        chunk = max(1, (1 << 20) // (n * len(series)))  # windows at a time: ~16 MiB of complex samples
        parts = []
        for first in np.split(starts, range(chunk, len(starts), chunk)):
            q = series[:, first[:, None] + np.arange(n)]  # (trajectories x 3, windows, n)
            parts.append(_leading_frequencies(q.reshape(-1, n), p).reshape(len(series), -1))
        nu = np.concatenate(parts, axis=1)  # (trajectories x 3, W)
        nu = np.moveaxis(nu.reshape(self.X.shape[:-2] + (3, len(starts))), -2, -1) / every  # (..., W, 3)
        return self.t[starts] + (n - 1) / 2 * every, nu

    def plot_frequencies(self, samples: int, step: Optional[int] = None, window: int = 1, ax=None):
        """Draws :meth:`frequencies` (nu_x, nu_y, nu_z against the windows' centre times) on the
        matplotlib axes ``ax`` (default: a new figure's) and returns the axes; one trajectory
        only. Needs matplotlib (``pip install matplotlib``, or the ``[plots]`` extra)."""
        if self.X.ndim != 2:
            raise ValueError(f"plot_frequencies draws one trajectory: this orbit has {self.X.shape[0]} "
                             "(take aw.orbit(scene, X[i], P[i], ...) or id=N)")
        try:
            import matplotlib.pyplot as plt
        except ImportError:
            raise ImportError("plot_frequencies needs matplotlib: pip install matplotlib") from None
        t, nu = self.frequencies(samples, step, window)
        if ax is None:
            ax = plt.subplots()[1]
        for d, name in enumerate("xyz"):
            ax.plot(t, nu[:, d], ".-", label=f"$\\nu_{name}$")
        ax.set_xlabel("t (T), the window's centre")
        ax.set_ylabel("frequency (turns per T)")
        ax.set_title(f"frequencies over windows of {samples:g} samples ({samples * float(self.t[1]):g} T)")
        ax.legend()
        return ax


def _in_range(name: str, value, low: int, high: Optional[int], what: str = "") -> int:
    """An integer argument (as the package's: a float with a whole value too; TypeError
    otherwise) in [low, high] (high None: no bound), else ValueError naming it and the range."""
    from . import _whole_number  # (the package's __init__ imports this module first)
    whole = _whole_number(value, name)
    if whole < low or (high is not None and whole > high):
        allowed = f"{low} to {high}{what}" if high is not None else f">= {low}"
        raise ValueError(f"{name} = {whole}: outside the allowed range, {allowed}")
    return whole


_NEWTON_PASSES = 40  # as AW_NAFF_MAX_ITER; round-off is reached in 2-3 from the FFT's peak


def _leading_frequencies(q: np.ndarray, p: int) -> np.ndarray:
    """The frequency (cycles per sample) of the largest term of exp(i q) for each row of q
    (n samples of an angle, radians, unwrapped) by NAFF's first step, with aw_naff.h's conventions:
    m_k = k - (n - 1)/2, the window chi_p = (1 + cos(2 pi m_k / (n - 1)))^p, the transform
    S_j(sigma) = sum m_k^j chi_p z_k exp(-2 pi i sigma m_k); of the maximum's aliases the one
    nearest the mean rate. Returns shape (rows,)."""
    n = q.shape[-1]
    m = np.arange(n) - (n - 1) / 2
    weighted = (1 + np.cos(2 * np.pi * m / (n - 1))) ** p * np.exp(1j * q)
    # coarse: the largest bin of the padded FFT, moved to the vertex of the parabola through its neighbours
    size = 1 << int(np.ceil(np.log2(2 * n)))
    power = np.abs(np.fft.fft(weighted, size, axis=-1)) ** 2
    peak = np.argmax(power, axis=-1)
    rows = np.arange(len(q))
    left, mid, right = (power[rows, (peak + j) % size] for j in (-1, 0, 1))
    bend = left - 2 * mid + right
    shift = np.where(bend < 0, 0.5 * (left - right) / np.where(bend < 0, bend, -1.0), 0.0)
    sigma = (peak + shift) / size
    sigma = sigma - np.floor(sigma + 0.5)
    # refinement: Newton steps on |S_0|^2 (docs/frequencies.md), at most half a bin each
    half_bin = 0.5 / n
    active = np.arange(len(q))  # the rows still moving
    for _ in range(_NEWTON_PASSES):
        terms = weighted[active] * np.exp(-2j * np.pi * sigma[active, None] * m)
        s0, s1, s2 = terms.sum(-1), (terms * m).sum(-1), (terms * m * m).sum(-1)
        slope = np.imag(np.conj(s0) * s1)
        curvature = np.abs(s1) ** 2 - np.real(np.conj(s0) * s2)  # < 0 near a maximum
        newton = -slope / (2 * np.pi * np.where(curvature < 0, curvature, -np.inf))
        delta = np.where(curvature < 0, np.clip(newton, -half_bin, half_bin), np.sign(slope) * half_bin)
        sigma[active] += delta
        active = active[np.abs(delta) > np.finfo(float).eps * (np.abs(sigma[active]) + half_bin)]  # NaN: stops
        if active.size == 0:
            break
    rate = (q[:, -1] - q[:, 0]) / (2 * np.pi * (n - 1))  # the mean rate, cycles per sample
    nu = sigma + np.rint(rate - sigma)
    nu[~np.isfinite(q).all(-1)] = np.nan
    return nu


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


Orbit.__module__ = "arnoldweb"  # help() and reprs name the public package, not _orbit
