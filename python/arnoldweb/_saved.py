"""arnoldweb.load: the Result of a run's output directory (summary.json, map.h5, states.h5,
indicators.h5, panel-<name>/), as a run gave it."""
from __future__ import annotations

import io
import os
from typing import Any, Callable, Optional

import numpy as np

from . import _arnoldweb as _core
from ._errors import OutputError
from ._result import COUNTER_NAMES, INDICATOR_NAMES, Result, _COUNTER_DTYPE, _INDICATOR_DTYPE, _restore, Lazy

__all__ = ["load"]


def _h5py(path: str):
    try:
        import h5py
    except ImportError:
        raise ImportError(f"reading {path} needs h5py: pip install h5py (or arnoldweb[plots])") from None
    return h5py


def _checked(path: str):
    """The HDF5 file at path (in an output directory) as a file object of its bytes, read by the
    library's reader of saved runs: a plain file with the size and digest summary.json records,
    holding nothing that leads out of it (external links, external storage, virtual datasets;
    OutputError naming it otherwise). h5py then reads exactly the bytes that were checked."""
    folder, name = os.path.split(path)
    return io.BytesIO(_core._read_saved_hdf5_file(folder, name))


def _states(path: str) -> Optional[dict]:
    h5py = _h5py(path)
    out = {}
    with h5py.File(_checked(path), "r") as f:
        for group in ("initial", "final"):
            if group in f:
                out[group] = {name: f[group][name][()] for name in f[group] if isinstance(f[group][name], h5py.Dataset)}
    return out or None


def _indicators(path: str) -> Optional[np.ndarray]:
    h5py = _h5py(path)
    with h5py.File(_checked(path), "r") as f:
        present = [n for n in INDICATOR_NAMES if n in f and isinstance(f[n], h5py.Dataset)]
        if not present:
            return None
        shape = f[present[0]].shape
        table = np.full(shape, np.nan, dtype=_INDICATOR_DTYPE)
        for name in present:
            table[name] = f[name][()]
    return table


def _outputs(folder: str, files: list) -> dict:
    """Every per-trajectory output in the directory's HDF5 files, as Result.outputs gives a run's:
    {output: {dataset: array}}, read with h5py from the checked bytes of each file."""
    out: dict = {}
    opened: dict = {}
    try:
        for row in _core._output_locations():
            if row["file"] not in files:
                continue
            if row["file"] not in opened:
                path = os.path.join(folder, row["file"])
                opened[row["file"]] = _h5py(path).File(_checked(path), "r")
            f = opened[row["file"]]
            if row["group"] and row["group"] not in f:
                continue
            where = f[row["group"]] if row["group"] else f
            found = {name: where[name][()] for name in row["datasets"] if name in where}
            if found:
                out[row["output"]] = found
    finally:
        for f in opened.values():
            f.close()
    return out


def _lazy(path: str, read: Callable[[str], Any]) -> Any:
    """read(path) when the value is first asked for (h5py only then), None without the file."""
    return Lazy(lambda: read(path)) if os.path.exists(path) else None


def _part(folder: str, name: str, title: str) -> dict:
    # read as render and compare read it: a plain file, without blocking, of the form arnoldweb
    # writes (OutputError naming it otherwise); a panel's is also checked against the digest
    # that the main summary.json records for it
    if name:
        _core._read_saved_file(os.path.dirname(folder), f"panel-{name}/summary.json")
    summary = _core.read_saved_summary(folder)
    maps = {"nside": 0, "map": None, "frames": None, "zoom": None}
    if os.path.exists(os.path.join(folder, "map.h5")):
        maps = _core._read_maps(folder)  # the library's reader (as arnoldweb compare): OutputError when bad
        recorded = summary.get("digests", {}).get("map")
        if maps["map"] is not None and recorded and maps["map_digest"] != recorded:
            path = os.path.join(folder, "map.h5")
            raise OutputError(f"{path}: its map has digest {maps['map_digest']}, summary.json records {recorded}: "
                              "the file was changed or damaged", path=path)
    flagged = summary.get("flagged", {})
    counts = {"trajectories": summary.get("trajectories", 0), "completed": summary.get("completed", 0),
              "binned": summary.get("binned", 0), "flagged_nonfinite": flagged.get("nonfinite", 0),
              "flagged_energy": flagged.get("energy", 0), "flagged_initial": flagged.get("initial", 0),
              "left_region": summary.get("left_region", 0)}
    energy = {k: v for k, v in summary.get("energy_error", {"tracked": False}).items() if k != "note"}
    return {
        "map": maps["map"], "nside": maps["nside"], "frames": maps["frames"], "zoom": maps["zoom"],
        "states": _lazy(os.path.join(folder, "states.h5"), _states),
        "indicators": _lazy(os.path.join(folder, "indicators.h5"), _indicators),
        "outputs": Lazy(lambda: _outputs(folder, summary.get("files", []))),
        "counters": np.array(tuple(counts[n] for n in COUNTER_NAMES), dtype=_COUNTER_DTYPE),
        "energy": energy,
        "interrupted": bool(summary.get("interrupted", False)),
        "digests": {k: v for k, v in summary.get("digests", {}).items() if k != "algorithm"},
        "device": {k: v for k, v in summary.get("device", {}).items() if k in ("id", "backend", "name", "vendor", "version")},
        "wall_seconds": float(summary.get("wall_seconds", 0.0)),
        "rate": float(summary.get("trajectory_steps_per_second", 0.0)),
        "summary": summary, "name": name, "title": title,
    }


def load(out_dir: "str | os.PathLike[str]") -> Result:
    """The :class:`Result` of a run's output directory (written by ``arnoldweb run --out`` or
    :func:`arnoldweb.run` with ``out``): map, frames and zoom (read by the library, the map
    checked against the digest in summary.json), states, indicators and every per-trajectory
    output (:attr:`Result.outputs`: states.h5, indicators.h5, frequencies.h5, diffusion.h5, read
    with h5py when first asked for), counters, energy, digests, device and
    summary, and the panels (panel-<name>/). Every file is read as ``arnoldweb render`` reads it:
    a plain file, checked against the size and digest summary.json records for it. Raises
    OutputError naming a missing, unreadable, damaged or changed file. A loaded Result pickles; it cannot be written again (its files are there)."""
    folder = os.path.abspath(os.fspath(out_dir))
    main = _part(folder, "", "")
    titles = {p.get("name", ""): p.get("title", "") for p in main["summary"].get("scene", {}).get("panel", [])
              if isinstance(p, dict)}
    parts = [main]
    for entry in sorted(os.listdir(folder)):
        sub = os.path.join(folder, entry)
        if entry.startswith("panel-") and os.path.isdir(sub) and os.path.exists(os.path.join(sub, "summary.json")):
            name = entry[len("panel-"):]
            parts.append(_part(sub, name, titles.get(name, "")))
    return _restore({"parts": parts, "files": main["summary"].get("files", []), "written_dir": folder})
