"""The scenes that come with the package (the repository's scenes/ folder)."""
from __future__ import annotations

import os
from typing import List

from ._scene import Scene

__all__ = ["scene", "scenes"]


def _folder() -> str:
    here = os.path.dirname(os.path.abspath(__file__))
    installed = os.path.join(here, "scenes")  # the wheel's copy
    if os.path.isdir(installed):
        return installed
    return os.path.join(os.path.dirname(os.path.dirname(here)), "scenes")  # a source checkout (python/arnoldweb)


def scenes() -> List[str]:
    """The names of the scenes that come with the package (``"default"``, ``"fig3_e15"``, ...),
    for :func:`scene`."""
    folder = _folder()
    if not os.path.isdir(folder):
        return []
    return sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".toml"))


def scene(name: str) -> Scene:
    """A scene that comes with the package, by name: ``aw.scene("default")`` is
    scenes/default.toml (the paper's figures: "fig2_e400", "fig3_e15", "fig4_diffusion"; chaos
    indicators: "fli_e15", ...; :func:`scenes` lists them). Raises ValueError for an unknown name."""
    names = scenes()
    if name not in names:
        import difflib
        near = difflib.get_close_matches(name, names, n=1)
        hint = f"; did you mean {near[0]!r}?" if near else ""
        raise ValueError(f"no scene {name!r} comes with arnoldweb{hint} (scenes: {', '.join(names)})")
    return Scene.from_file(os.path.join(_folder(), name + ".toml"))
