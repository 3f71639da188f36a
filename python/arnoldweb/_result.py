"""What a run produced, as numpy arrays (views of the library's memory where it owns it)."""
from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Optional

import numpy as np

from . import _arnoldweb as _core

__all__ = ["Result", "COUNTER_NAMES", "INDICATOR_NAMES"]

#: The fields of Result.counters, in order.
COUNTER_NAMES = ("trajectories", "completed", "binned", "flagged_nonfinite", "flagged_energy",
                 "flagged_initial", "left_region")
_COUNTER_DTYPE = np.dtype([(n, np.uint64) for n in COUNTER_NAMES])
#: The fields of Result.indicators, in the library's record order: the indicators row's
#: datasets in the output table (lib/src/output_table/output_table.cpp), so a new one is here too.
INDICATOR_NAMES = tuple(_core._output_fields("indicators"))
_INDICATOR_DTYPE = np.dtype([(n, np.float64) for n in INDICATOR_NAMES])


class Lazy:
    """A value read when first asked for (a loaded result's states.h5, indicators.h5, outputs)."""

    def __init__(self, make):
        self.make = make


#: What a Result keeps when it is pickled, copied or loaded (arnoldweb.load): its public
#: values, so that a pickle does not depend on the library's internal arrays.
SAVED_FIELDS = ("map", "nside", "frames", "zoom", "states", "indicators", "outputs", "counters", "energy", "interrupted",
                "digests", "device", "wall_seconds", "rate", "summary", "name", "title")


class Result:
    """One run of a scene (the main run; its panels are in :attr:`panels`).

    Arrays are read-only numpy views of the library's own memory where it holds
    them contiguously (map, zoom, states): no copy is made, and each keeps the
    run alive. A Result pickles and deep-copies (its arrays bit for bit), and
    :func:`arnoldweb.load` makes one from a run's output directory.
    """

    def __init__(self, record: Any, part: int = 0, saved: Optional[dict] = None):
        self._record = record
        self._part = part
        # a pickled, copied or loaded result: {"parts": [values of SAVED_FIELDS], "files", "written_dir"}
        self._saved = saved
        self._cache: Dict[str, Any] = dict(saved["parts"][part]) if saved is not None else {}

    def _cached(self, name: str, make):
        if name not in self._cache:
            self._cache[name] = make()
        value = self._cache[name]
        if isinstance(value, Lazy):  # a loaded result's file, read when first asked for
            value = self._cache[name] = _read_only(value.make())
        return value

    # ------------------------------------------------------------------ maps
    @property
    def map(self) -> np.ndarray:
        """The velocity map: counts of binned windows per HEALPix pixel in RING order,
        shape (12 nside²,), dtype uint64; ``healpy.mollview(result.map)`` draws it. Without
        observe.velocity_map it is empty, shape (0,), as its nside is 0 (``result.map.sum()``
        is then 0)."""
        return self._cached("map", lambda: _empty_if_none(self._record.map(self._part)))

    @property
    def nside(self) -> int:
        """HEALPix nside of :attr:`map` (0 without a map)."""
        return self._cached("nside", lambda: self._record.nside(self._part))

    @property
    def map_file(self) -> Optional[str]:
        """The path of the map as a HEALPix FITS file, ``map.fits`` (written with
        ``output.formats = ["hdf5", "fits"]``; ``healpy.read_map(result.map_file)`` gives
        :attr:`map`), once the outputs are written (:meth:`write`, ``run(out=...)``) or for a
        :func:`arnoldweb.load` of a directory that has it; else None."""
        folder = self._written_folder()
        return os.path.join(folder, "map.fits") if folder and "map.fits" in self.summary.get("files", []) else None

    @property
    def ordering(self) -> str:
        """HEALPix pixel ordering of the maps: always "RING"."""
        return "RING"

    @property
    def frames(self) -> Optional[np.ndarray]:
        """One map per observe.frames span, shape (frames, 12 nside²), uint64 (a copy); None without frames."""
        return self._cached("frames", lambda: self._record.frames(self._part))

    @property
    def zoom(self) -> Optional[np.ndarray]:
        """The observe.zoom histogram, shape (R, R) (row y, column x), uint64; None without a zoom."""
        return self._cached("zoom", lambda: self._record.zoom(self._part))

    # ---------------------------------------------------------------- states
    @property
    def states(self) -> Optional[dict]:
        """State records of the completed trajectories in index order, when the scene asked for
        them (observe.initial_states / final_states), as in states.h5:
        ``{"initial": {"position_turns", "momentum"}, "final": {"position_turns", "winding",
        "momentum", "status", "position"}}``; arrays of shape (n, 3) (status: (n,)); float64
        and int64. Positions are in turns (x / 2π, wrapped to [-1/2, 1/2]); ``position`` is the
        unwrapped 2π (winding + position_turns). None when no states were asked for."""
        return self._cached("states", self._make_states)

    def _make_states(self) -> Optional[dict]:
        out = {}
        init = self._record.records(self._part, "initial_states", False)
        if init is not None:
            out["initial"] = {"position_turns": init[:, 0:3], "momentum": init[:, 3:6]}
        fin = self._record.records(self._part, "final_states", False)
        if fin is not None:
            ints = self._record.records(self._part, "final_states", True)
            out["final"] = {
                "position_turns": fin[:, 0:3],
                "winding": ints[:, 0:3],
                "momentum": fin[:, 3:6],
                "status": ints[:, 3],
                "position": 2 * np.pi * (ints[:, 0:3].astype(np.float64) + fin[:, 0:3]),
            }
        return out or None

    @property
    def outputs(self) -> Dict[str, Dict[str, np.ndarray]]:
        """Every per-trajectory output of the run as its files hold it (docs/outputs.md, the
        output table): ``{output: {dataset: array}}``, e.g. ``result.outputs["final_states"]["momentum"]``
        (shape (n, 3)) or ``result.outputs["indicators"]["fli"]`` (the grid's shape). Copies."""
        return self._cached("outputs", lambda: self._record.output_datasets(self._part))

    # --------------------------------------------------------------- numbers
    @property
    def counters(self) -> np.ndarray:
        """The run's counts as a numpy record (dtype fields COUNTER_NAMES, uint64):
        ``result.counters["binned"]``."""
        def make():
            c = self._record.counts(self._part)
            return np.array(tuple(c[n] for n in COUNTER_NAMES), dtype=_COUNTER_DTYPE)
        return self._cached("counters", make)

    @property
    def indicators(self) -> Optional[np.ndarray]:
        """Chaos indicators of the completed trajectories (observe.fli, observe.megno,
        observe.lyapunov; docs/indicators.md), or None when the scene asked for none: a
        zero-copy numpy record array with the fields of INDICATOR_NAMES (float64; NaN where not
        asked or flagged), e.g. ``result.indicators["fli"]``. For ``ensemble.initial = "grid"``
        it has the grid's shape, as in indicators.h5: (12 nside²,) in HEALPix RING order
        (``healpy.mollview(result.indicators["fli"])``), or (n2, n1) for lonlat and plane grids."""
        return self._cached("indicators", self._make_indicators)

    def _make_indicators(self) -> Optional[np.ndarray]:
        records = self._record.records(self._part, "indicators", False)
        if records is None:
            return None
        layout = self._record.indicator_layout(self._part)
        table = records.view(_INDICATOR_DTYPE).reshape(records.shape[0])
        return table.reshape(layout["shape"]) if int(np.prod(layout["shape"])) == table.size else table

    @property
    def energy(self) -> dict:
        """Energy error statistics: tracked, max, mean, median_upper_bound, p99_upper_bound,
        log_hist (the quarter-octave histogram of max|dE| over all trajectories, uint64) and
        log_hist_edges (its bin edges, float64, one more than the bins: bin i counts
        ``log_hist_edges[i] <= max|dE| < log_hist_edges[i + 1]``, the first from 0 to 2^-64, the
        last from 2^16 to inf; ``matplotlib.pyplot.stairs(e["log_hist"], e["log_hist_edges"])``)."""
        return self._cached("energy", lambda: _with_edges(self._record.energy(self._part)))

    @property
    def trajectories(self) -> int:
        """Trajectories asked for."""
        return int(self.counters["trajectories"])

    @property
    def completed(self) -> int:
        """Trajectories integrated (fewer than asked when the run was interrupted)."""
        return int(self.counters["completed"])

    @property
    def binned(self) -> int:
        """Trajectories that contributed every window to the map (map.sum() / windows)."""
        return int(self.counters["binned"])

    @property
    def interrupted(self) -> bool:
        """True when a stop (Ctrl-C, an exception in the progress callback) ended the run early."""
        return self._cached("interrupted", lambda: self._record.interrupted_part(self._part))

    @property
    def digests(self) -> dict:
        """XXH3-128 digests of the map and the states (as in summary.json): identical bits give
        identical digests on every device."""
        return self._cached("digests", lambda: self._record.digests(self._part))

    @property
    def device(self) -> dict:
        """The device it ran on: id, backend, name, vendor, version."""
        return self._cached("device", lambda: self._record.device(self._part))

    @property
    def wall_seconds(self) -> float:
        """Wall time of the run."""
        return self._cached("wall_seconds", lambda: self._record.wall_seconds(self._part))

    @property
    def rate(self) -> float:
        """Trajectory-steps per second."""
        return self._cached("rate", lambda: self._record.rate(self._part))

    @property
    def summary(self) -> dict:
        """The run's summary.json as a dict: the library's own summary (same function as the
        CLI's). Once :meth:`write` (or run(out=...)) has written the outputs, it is the
        summary.json written there, file list included; before, its ``files`` list is empty."""
        if self._saved is not None:
            return self._cache["summary"]
        if self._record.written_dir:  # read back as render and compare read it: checked (OutputError if damaged)
            return _core.read_saved_summary(self._written_folder())
        return self._cached("summary", lambda: json.loads(self._record.summary_json(self._part)))

    @property
    def analyses(self) -> dict:
        """What was computed from the records once the run ended, as summary.json holds it
        under "analyses" (docs/frequencies.md): ``result.analyses["diffusion"]`` for
        observe.diffusion, with ``["along_fit"]["D"]``, its bootstrap ``["D_error"]`` and the
        moments at every sample time (``["moments"]["along_variance"]``). {} without."""
        return self.summary.get("analyses", {})

    # ---------------------------------------------------------------- panels
    @property
    def name(self) -> str:
        """"" for the main run, else the panel's name."""
        return self._cached("name", lambda: self._record.name(self._part))

    @property
    def title(self) -> str:
        """The panel's caption ("" for the main run)."""
        return self._cached("title", lambda: self._record.title(self._part))

    @property
    def subdir(self) -> str:
        """Where this part's files go in the output directory ("" or "panel-<name>")."""
        return "" if self._part == 0 else f"panel-{self.name}"

    @property
    def panels(self) -> Dict[str, Result]:
        """The results of the scene's [[panel]] runs, by name (those that ran)."""
        if self._part != 0:
            return {}
        if self._saved is not None:
            return {p["name"]: Result(None, k, self._saved) for k, p in enumerate(self._saved["parts"]) if k > 0}
        return {self._record.name(k): Result(self._record, k) for k in range(1, self._record.parts_run)}

    @property
    def files(self) -> List[str]:
        """The paths the last write wrote ([] before)."""
        if self._saved is not None:
            return list(self._saved["files"])
        return list(self._record.files)

    def _written_root(self) -> str:
        """Where the job's files were written or loaded from ("" if nowhere)."""
        return self._saved.get("written_dir", "") if self._saved is not None else self._record.written_dir

    def _written_folder(self) -> str:
        """Where this part's files were written or loaded from ("" if nowhere)."""
        root = self._written_root()
        return os.path.join(root, self.subdir) if root and self.subdir else root

    # ---------------------------------------------------------------- output
    def write(self, out: str | os.PathLike[str], force: bool = False) -> List[str]:
        """Writes the output directory ``out`` exactly as ``arnoldweb run --out out`` does
        (summary.json, map.h5, states.h5, pictures, panel-<name>/, figure.png), through the
        library's output code: files are made in a staging directory and moved into place; an
        existing directory is refused (OutputError) unless ``force`` and arnoldweb wrote it, and
        refused always (OutputRefused) if it is not arnoldweb's. Returns the paths written."""
        if self._part != 0:
            raise ValueError("write() writes the whole job: call it on the main result")
        if self._saved is not None:
            from ._errors import OutputError
            where = self._saved.get("written_dir") or ""
            raise OutputError("this Result was loaded, unpickled or copied: its values are here, but write() needs "
                              "the run itself" + (f"; its outputs are in {where}" if where else ""), path=os.fspath(out))
        return self._record.write(os.fspath(out), force, self._record.scene_file())

    # ------------------------------------------------------------ persistence
    def _values(self) -> dict:
        return {name: getattr(self, name) for name in SAVED_FIELDS}

    def _state(self) -> dict:
        """This result (and, for the main run, its panels) as plain values and numpy arrays."""
        parts = [self._values()] + [p._values() for p in self.panels.values()]
        return {"parts": parts, "files": self.files, "written_dir": self._written_root()}

    def __reduce__(self):
        return (_restore, (self._state(),))

    def __copy__(self) -> Result:
        return self

    def __deepcopy__(self, memo: dict) -> Result:
        import copy
        return _restore(copy.deepcopy(self._state(), memo))

    def __eq__(self, other: object) -> bool:
        """Results are equal when they hold the same numbers: the maps, frames and zoom, every
        per-trajectory output (through their digests), the counts, the energy statistics,
        whether the run was interrupted, and the panels. Where and how fast a run went (device,
        wall_seconds, rate, summary) is not compared: a run, its pickle, its :func:`load`
        and the same scene run on another device (the same bits) are equal."""
        if not isinstance(other, Result):
            return NotImplemented
        return _same(self._numbers(), other._numbers())

    __hash__ = None  # type: ignore[assignment]  # equal results need not be the same object

    def _numbers(self) -> dict:
        """What == compares."""
        energy = {k: v for k, v in self.energy.items() if k in ("tracked", "max", "mean", "log_hist")}
        return {"map": self.map, "frames": self.frames, "zoom": self.zoom, "counters": self.counters,
                "digests": self.digests, "energy": energy, "interrupted": self.interrupted, "name": self.name,
                "title": self.title, "panels": {k: p._numbers() for k, p in self.panels.items()}}

    def __repr__(self) -> str:
        what = f"panel {self.name!r}" if self._part else "run"
        stop = ", interrupted" if self.interrupted else ""
        sphere = f"nside {self.nside}" if self.nside else "no velocity map"
        return (f"<arnoldweb.Result {what}: {self.completed}/{self.trajectories} trajectories, "
                f"{self.binned} binned, {sphere}{stop}>")


Result.__module__ = "arnoldweb"


def _empty_if_none(values: Optional[np.ndarray]) -> np.ndarray:
    """A map as an array: the empty map of nside 0 (shape (0,)) for a run without one."""
    if values is not None:
        return values
    empty = np.zeros(0, dtype=np.uint64)
    empty.flags.writeable = False
    return empty


def _with_edges(energy: dict) -> dict:
    """The energy statistics with the histogram's bin edges (and the histogram as uint64)."""
    if "log_hist" in energy:
        energy["log_hist"] = np.asarray(energy["log_hist"], dtype=np.uint64)
        energy["log_hist_edges"] = _core._energy_hist_edges()
    return energy


def _same(a: Any, b: Any) -> bool:
    """Equal values, arrays compared element by element (NaN equal to NaN, dtypes and shapes equal)."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        if not (isinstance(a, np.ndarray) and isinstance(b, np.ndarray)) or a.shape != b.shape or a.dtype != b.dtype:
            return False
        if a.dtype.names:
            return all(_same(a[n], b[n]) for n in a.dtype.names)
        return bool(np.array_equal(a, b, equal_nan=a.dtype.kind in "fc"))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, float) and isinstance(b, float) and a != a and b != b:
        return True
    return bool(a == b)


def _read_only(value: Any) -> Any:
    """The arrays of a saved result, read-only like a run's own (in place; returns value)."""
    if isinstance(value, np.ndarray):
        value.flags.writeable = False
    elif isinstance(value, dict):
        for v in value.values():
            _read_only(v)
    return value


def _restore(state: dict) -> Result:
    """A pickled or copied Result (and its panels) from its values."""
    for part in state["parts"]:
        _read_only(part)
    return Result(None, 0, state)
