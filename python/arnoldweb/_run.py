"""Running scenes and the accuracy pilot."""
from __future__ import annotations

import os
from typing import Callable, Optional, Sequence, Union

import numpy as np

from . import _arnoldweb as _core
from ._progress import make_progress
from ._result import Result
from ._scene import Scene

__all__ = ["run", "continue_run", "accuracy", "check_states"]

SceneLike = Union[Scene, str, "os.PathLike[str]"]


def _scene_of(scene: SceneLike) -> Scene:
    if isinstance(scene, Scene):
        return scene.copy()
    if isinstance(scene, (str, os.PathLike)):
        return Scene.from_file(scene)
    raise TypeError(f"scene must be an arnoldweb.Scene or a path, not {type(scene).__name__}")


def run(scene: SceneLike, device: Optional[str] = None,
        progress: "bool | Callable[[int, int, float], None] | None" = None,
        out: "str | os.PathLike[str] | None" = None, force: bool = False,
        initial: "tuple | None" = None, units: str = "radians") -> Result:
    """Runs a scene (and its [[panel]] runs) and returns the main run's :class:`Result`.

    - ``device``: "cpu", "opencl:N", "cuda:N", "auto", "all" (every GPU) or a list such as
      "cuda:0,cuda:1" (one thread per device, the same bits as one device), as ``--device``;
      None: run.device.
    - ``initial``: the initial states as ``(X, P)``, two arrays of shape (N, 3): positions in
      ``units`` ("radians" or "turns"; unwrapped is fine) and momenta. They are checked as a
      state file is (:func:`check_states`: StateError naming the row), and the trajectories start
      from them (``ensemble.initial`` becomes "file", one trajectory per state; each state keeps
      its own energy).
    - ``progress``: True for a bar (tqdm when installed, else lines on stderr), or a
      callable ``progress(done, total, seconds)`` called after every chunk; None: quiet.
    - ``out``: an output directory to write as ``arnoldweb run --out`` does (checked before
      anything is computed; ``force`` as ``--force``). None: nothing is written (see
      :meth:`Result.write`).

    The GIL is released while the device computes. Ctrl-C (SIGINT) stops the run after the
    current chunk and raises KeyboardInterrupt whose ``result`` attribute holds what was
    computed (and, with ``out``, was written); an exception raised by the progress callback
    stops it the same way. Raises SceneError, DeviceError, BuildError, OutputError, StateError.
    """
    s = _scene_of(scene)
    if device is not None:
        s._apply(f"run.device={_quote(device)}", f"device={device!r}")
    x = p = None
    if initial is not None:
        x, p = (np.ascontiguousarray(a, dtype=np.float64) for a in _pair(initial))
    if out is not None:
        out = os.fspath(out)
        if out == "":
            from ._errors import OutputRefused
            raise OutputRefused("out was given an empty directory name", path="")
        s._apply(f"output.dir={_quote(out)}", f"out={out!r}")
    callback, close = make_progress(progress)
    try:
        record = _core._run(s._scene, callback, out is not None, force, x, p, units)
    finally:
        close()
    result = Result(record)
    stop = record.take_stop_exception()
    try:
        record.raise_write_error()
    except Exception as e:  # the outputs failed: keep the result on the error
        e.result = result
        raise e from stop
    if stop is not None:
        stop.result = result
        raise stop
    return result


def continue_run(out_dir: "str | os.PathLike[str]", duration: float, device: Optional[str] = None,
                 progress: "bool | Callable[[int, int, float], None] | None" = None,
                 out: "str | os.PathLike[str] | None" = None, force: bool = False,
                 sets: "dict | None" = None) -> Result:
    """Goes on from where a finished run ended, as ``arnoldweb continue OUT_DIR --for DURATION``:
    the run's scene as it ran (summary.json's ``scene_toml``), its trajectories started from the
    final states, windings and time of its ``states.h5`` (checked against the size and digest
    summary.json records: OutputError otherwise), for ``duration`` more T. A run of 2T is bit for
    bit a run of T continued for T (the final states, and the map of the second window).

    ``sets``: further keys, as ``{"observe.fli": True}``: only keys that leave the trajectories
    unchanged (outputs, device, checkpoints; docs/cluster.md), else SceneError; ``run.duration``
    is ``duration``. ``device``, ``progress``, ``out`` and ``force`` as in
    :func:`run`: with ``out`` None nothing is written. Raises OutputError (no summary.json, no
    final states, a damaged states.h5), SceneError, DeviceError, StateError."""
    if not (isinstance(duration, (int, float)) and duration > 0 and duration != float("inf")):
        raise ValueError(f"duration must be a time in T greater than 0, not {duration!r}")
    from ._toml import literal
    items = list((sets or {}).items())
    c = _core._continuation_of(os.path.abspath(os.fspath(out_dir)), float(duration),
                               [f"{k}={literal(v)}" for k, v in items],
                               [f"sets[{k!r}] = {v!r}" for k, v in items])
    s = Scene._make(c["scene_toml"], c["source"], c["overrides"], c["labels"])
    return run(s, device=device, progress=progress, out=out, force=force)


def _pair(initial) -> tuple:
    if not isinstance(initial, (tuple, list)) or len(initial) != 2:
        raise TypeError("initial must be a pair (X, P) of arrays of shape (N, 3)")
    return initial[0], initial[1]


def check_states(scene: SceneLike, positions, momenta, units: str = "radians") -> dict:
    """Checks initial states given as arrays against the scene's model, with the rules of a
    state file (docs/outputs.md, "State files"): ``positions`` and ``momenta`` of shape (N, 3)
    (anything numpy converts to float64), positions in ``units`` ("radians" or "turns"), every
    value finite, positions within 2^52 turns, and each state's energy H = T(P) + V(X) within 1%
    of max(|E|, max V - min V) of model.energy. Returns a dict: count, energy (H of each state,
    a numpy array), energy_min, energy_max. Raises StateError naming the array and the row."""
    x = np.ascontiguousarray(positions, dtype=np.float64)
    p = np.ascontiguousarray(momenta, dtype=np.float64)
    return _core._check_states(_scene_of(scene)._scene, x, p, units)


def _quote(text: str) -> str:
    from ._toml import literal
    return literal(text)


def accuracy(scene: SceneLike, target: Optional[float] = None, device: Optional[str] = None,
             safety: float = 4.0, pilot: int = 512, pilot_duration: float = 5.0,
             methods: Optional[Sequence[str]] = None, prefilter: bool = True) -> dict:
    """A pilot ensemble predicts the energy error and cost of the scene as written and finds
    the cheapest method and step with max|dE| <= ``target`` (default integrator.tolerance), as
    ``arnoldweb accuracy`` does (docs/accuracy.md). Returns the report as a dict: device,
    pilot_*, fits (per method: points of step, max, median), as_written, best, per_method,
    found, why_not. Computes only the pilot; writes nothing."""
    s = _scene_of(scene)
    if device is not None:
        s._apply(f"run.device={_quote(device)}", f"device={device!r}")
    if target is not None and not (0 < target < 1):
        raise ValueError(f"target must be greater than 0 and less than 1, got {target}")
    if not 1 <= safety <= 1000:
        raise ValueError(f"safety must be in [1, 1000], got {safety}")
    if not 1 <= pilot <= 100_000_000:
        raise ValueError(f"pilot must be in [1, 100000000] trajectories, got {pilot}")
    if not pilot_duration > 0:
        raise ValueError(f"pilot_duration must be positive, got {pilot_duration}")
    names = [m["name"] for m in _core.methods()]
    for m in methods or []:
        if m not in names:
            raise ValueError(f"unknown method {m!r}; known: {', '.join(names)}")
    return _core._accuracy(s._scene, target or 0.0, safety, pilot, pilot_duration, list(methods or []), prefilter)
