"""arnoldweb: maps the Arnold web with ensembles of symplectic trajectories.

The Python interface to the arnoldweb C++ library (the same library as the
``arnoldweb`` command): scenes are read and validated by the library, runs
compute on its devices (cpu, OpenCL, CUDA) and return numpy arrays.

    import arnoldweb as aw
    scene = aw.scene("default").set("ensemble.trajectories", 20_000)
    result = aw.run(scene, progress=True)
    result.map          # HEALPix RING counts, nside = result.nside
    result.write("out/py")

See docs/python.md.
"""
# (no `from __future__ import annotations` here: it would put the name
# "annotations" into the package's namespace)
from . import _arnoldweb as _core
from ._errors import BuildError, DeviceError, Error, OutputError, OutputRefused, PlanWarning, SceneError, StateError
from ._result import COUNTER_NAMES, INDICATOR_NAMES, Result
from ._explorer import serve, view
from ._model import energy, potential, shell_momenta
from ._orbit import Orbit, orbit
from ._run import accuracy, check_states, continue_run, run
from ._saved import load
from ._scene import Scene
from ._scenes import scene, scenes

__version__: str = _core.__version__

__all__ = ["Scene", "Result", "run", "continue_run", "orbit", "Orbit", "load", "view", "serve", "scene", "scenes", "accuracy", "check_states",
           "potential", "energy", "shell_momenta", "devices", "methods",
           "scene_keys", "backend_problems", "default_device", "pixel_directions", "resonances", "compare_maps", "Error",
           "SceneError", "DeviceError", "BuildError", "OutputError", "OutputRefused", "PlanWarning", "StateError",
           "COUNTER_NAMES", "INDICATOR_NAMES", "__version__"]


def devices() -> list:
    """The devices present, cpu first, as dicts: id ("cpu", "opencl:0", "cuda:0"), backend,
    name, vendor, version, fp64, compute_units, memory, max_allocation, is_cpu."""
    return _core.devices()


def methods() -> list:
    """The integration methods (integrator.method), as dicts: name, title, source, order,
    eps_orders, stages, kick_first, family, stability, drift and kick coefficients, and the
    force-gradient coefficients ("gradient", empty for most) and "work" (cost of a step in plain
    force evaluations)."""
    return _core.methods()


def scene_keys() -> list:
    """Every scene key, as dicts: key, type, allowed, default, meaning (docs/scenes.md)."""
    return _core.scene_keys()


def backend_problems() -> list:
    """Why a backend contributes no device here, one line each (e.g. no CUDA driver)."""
    return _core.backend_problems()


def pixel_directions(nside: int):
    """Unit vectors to the HEALPix RING pixel centres, a float64 array of shape (12 nside², 3):
    row i is the direction that ``result.map[i]`` counts (the library's own pix2vec). ``nside``
    is a power of two from 1 to 8192 (a float with a whole value, such as 2.0, is taken as one)."""
    return _core.pixel_directions(_whole_number(nside, "nside"))


def resonances(max_order: int) -> list:
    """The resonances m·P = 0 with max |m_i| <= max_order, lowest order first, as dicts
    (m, order, label): each is the great circle of directions P with m·P = 0."""
    return _core.resonances(_whole_number(max_order, "max_order"))


def _whole_number(value, name: str) -> int:
    """An integer argument: an int, a numpy integer, or a float with a whole value (2.0)."""
    import numbers
    if isinstance(value, numbers.Integral) and not isinstance(value, bool):
        return int(value)
    if isinstance(value, numbers.Real) and float(value).is_integer():
        return int(value)
    raise TypeError(f"{name} must be a whole number, not {value!r}")


def compare_maps(a, b, min_count: float = 5) -> dict:
    """Are two count maps (e.g. ``result.map`` of two runs) samples of the same distribution? The
    two-sample chi-square test of ``arnoldweb compare`` (docs/outputs.md), for maps with different
    totals: bins with fewer than ``min_count`` counts in both together are pooled into one bin.
    Returns a dict: chi2, dof, chi2_per_dof, p_value, total_a, total_b, bins, used_bins,
    pooled_bins, empty_bins. Runs of the same seed are not independent samples (p comes out too
    large). The maps hold counts: integers >= 0 of any numpy type (a float array of whole
    numbers is taken as it is); ValueError for negative, fractional, non-finite or too large
    values (``healpy.ud_grade`` averages a map by default: pass ``power=-2`` to add its counts),
    for maps of different sizes, an empty map or one without counts."""
    return _core.compare_maps(_counts(a, "a"), _counts(b, "b"), float(min_count))


def _counts(values, name: str):
    """A map of counts as contiguous uint64, or ValueError naming what is wrong (never a silent cast)."""
    import numpy as np

    x = np.asarray(values)
    if x.ndim != 1:
        raise ValueError(f"compare_maps: {name} must be a 1-D array of counts, got shape {x.shape}")
    if x.dtype.kind == "u":
        return np.ascontiguousarray(x, dtype=np.uint64)
    if x.dtype.kind not in "if":
        raise ValueError(f"compare_maps: {name} must hold counts (integers >= 0), got dtype {x.dtype}")
    if x.dtype.kind == "f":
        bad = ~np.isfinite(x)
        if bad.any():
            raise ValueError(f"compare_maps: {name} holds a non-finite value ({x[bad][0]!r} at index "
                             f"{int(np.flatnonzero(bad)[0])}); counts are integers >= 0")
        bad = x != np.floor(x)
        if bad.any():
            raise ValueError(f"compare_maps: {name} holds a value that is not a whole number ({x[bad][0]!r} at "
                             f"index {int(np.flatnonzero(bad)[0])}); counts are integers >= 0 (healpy.ud_grade "
                             "averages a map unless given power=-2)")
        bad = x >= 2.0 ** 64
        if bad.any():
            raise ValueError(f"compare_maps: {name} holds a count too large for 64 bits ({x[bad][0]!r})")
    bad = x < 0
    if bad.any():
        raise ValueError(f"compare_maps: {name} holds a negative count ({x[bad][0]!r} at index "
                         f"{int(np.flatnonzero(bad)[0])}); counts are integers >= 0")
    return np.ascontiguousarray(x, dtype=np.uint64)


def default_device() -> str:
    """The device id that run.device = "auto" resolves to on this machine."""
    return _core.default_device()

