"""The scene's model from Python: V(X), H(X, P) and momenta on the energy shell, evaluated by
the library's own code for the model (the kernels' device code compiled for the host)."""
from __future__ import annotations

import os
from typing import Union

import numpy as np

from . import _arnoldweb as _core
from ._scene import Scene

__all__ = ["potential", "energy", "shell_momenta"]

SceneLike = Union[Scene, str, "os.PathLike[str]"]


def _scene(scene: SceneLike):
    from ._run import scene_of
    return scene_of(scene)._scene


def _rows(name: str, *arrays) -> tuple:
    """The arrays as float64 rows of three, broadcast against each other: (rows..., leading shape)."""
    values = [np.asarray(a, dtype=np.float64) for a in arrays]
    for label, v in zip(name.split(","), values):
        if v.ndim == 0 or v.shape[-1] != 3:
            raise ValueError(f"{label} has the shape {v.shape}; it must be (3,) or (..., 3): rows of x, y, z")
    try:
        values = np.broadcast_arrays(*values)
    except ValueError:
        raise ValueError(f"{' and '.join(name.split(','))} have the shapes {', '.join(str(np.shape(a)) for a in arrays)}, "
                         "which do not broadcast (numpy's rules) against each other") from None
    lead = values[0].shape[:-1]
    return tuple(np.ascontiguousarray(v.reshape(-1, 3)) for v in values) + (lead,)


def potential(scene: SceneLike, X, units: str = "radians") -> np.ndarray:
    """V(X) of the scene's model (model.kind and its parameters): ``X`` of shape (3,) or
    (..., 3), positions in ``units`` ("radians" or "turns"; any value, the torus is periodic).
    Returns float64 of shape X.shape[:-1] (a 0-d array for one position). Evaluated in double
    precision by the model's own device code compiled for the host: the kernels' operations."""
    x, lead = _rows("X", X)
    return _core._potential(_scene(scene), x, units).reshape(lead)


def energy(scene: SceneLike, X, P, units: str = "radians") -> np.ndarray:
    """H = T(P) + V(X) of the scene's model for positions ``X`` (in ``units``) and momenta
    ``P``, each of shape (3,) or (..., 3), broadcast against each other. Returns float64 of the
    broadcast shape without its last axis: the energy :func:`check_states` gives each state
    (the same code), e.g. ``energy(scene, X, P) - scene["model.energy"]`` for the error."""
    x, p, lead = _rows("X,P", X, P)
    return _core._energy(_scene(scene), x, p, units).reshape(lead)


def shell_momenta(scene: SceneLike, X, directions, units: str = "radians") -> np.ndarray:
    """Momenta on the energy shell H = model.energy: for each position ``X`` (in ``units``)
    and direction (any length > 0; broadcast against each other, shapes (3,) or (..., 3)),
    P = s n with n the unit direction and s > 0 solving T(s n) = E - V(X), made as the kernels
    make their initial states. Rows where the shell has no momentum in that direction
    (E < V(X), or a kinetic form that never reaches it) are NaN. Returns float64 of the
    broadcast shape, ready for ``run(scene, initial=(X, P))``:
    ``P = aw.shell_momenta(scene, X, aw.pixel_directions(4))`` gives one state per direction."""
    x, d, lead = _rows("X,directions", X, directions)
    norm = np.sqrt(np.einsum("ij,ij->i", d, d))
    bad = ~(np.isfinite(norm) & (norm > 0))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise ValueError(f"directions: row {i} is {tuple(d[i])}; a direction must be finite with a length > 0")
    return _core._shell_momenta(_scene(scene), x, d / norm[:, None], units).reshape(lead + (3,))
