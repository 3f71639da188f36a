"""The scenes that come with the package (the repository's scenes/ folder)."""
from __future__ import annotations

import os
from typing import List

from ._scene import Scene

__all__ = ["scene", "scenes", "shipped_name", "scene_or_file"]


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


def _unknown(name: str, names: List[str]) -> str:
    import difflib
    near = difflib.get_close_matches(name, names, n=1)
    hint = f"; did you mean {near[0]!r}?" if near else ""
    return f"no scene {name!r} comes with arnoldweb{hint} (scenes: {', '.join(names)})"


def scene(name: str) -> Scene:
    """A scene that comes with the package, by name: ``aw.scene("default")`` is
    scenes/default.toml (the paper's figures: "fig2_e400", "fig3_e15", "fig4_diffusion"; chaos
    indicators: "fli_e15", ...; :func:`scenes` lists them). Raises ValueError for an unknown name."""
    names = scenes()
    if name not in names:
        raise ValueError(_unknown(name, names))
    return Scene.from_file(os.path.join(_folder(), name + ".toml"))


def shipped_name(path: str) -> str:
    """The name of a shipped scene's file ("default" for .../arnoldweb/scenes/default.toml), or ""."""
    folder, file = os.path.split(os.path.abspath(path)) if path and not path.startswith("<") else ("", "")
    if file.endswith(".toml") and os.path.isdir(folder) and os.path.samefile(folder, _folder()):
        return file[:-5]
    return ""


def scene_or_file(path: str | os.PathLike[str]) -> Scene:
    """A scene file, or, where no such file exists and the name is a shipped scene's ("default"),
    that scene: what aw.run("default") and `arnoldweb run default` read. FileNotFoundError naming
    both places otherwise."""
    text = os.fspath(path)
    if os.path.exists(text) or os.sep in text or text.endswith(".toml"):
        return Scene.from_file(text)
    names = scenes()
    if text in names:
        return scene(text)
    import errno
    raise FileNotFoundError(errno.ENOENT, f"no scene file {text!r} (in {os.getcwd()}), and {_unknown(text, names)}",
                            text)
