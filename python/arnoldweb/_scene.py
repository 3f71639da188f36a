"""Scenes: read, validated and planned by the C++ library (the CLI's reader)."""
from __future__ import annotations

import errno
import os
from collections.abc import Mapping
from typing import Any, Iterator, List, Sequence

from . import _arnoldweb as _core
from . import _toml

__all__ = ["Scene"]


class Scene(Mapping):
    """One experiment: a scene file's keys (docs/scenes.md), validated.

    Make one with :meth:`from_file`, :meth:`from_toml` or :meth:`from_dict` (or
    :func:`arnoldweb.scene` for a shipped one); :meth:`set` gives a new scene with a
    key changed (as ``arnoldweb run --set`` does), ``scene[key] = value`` changes this one;
    look at the plan with :meth:`check`; run it with :func:`arnoldweb.run`. Every check
    and message is the library's, the same as the CLI's; a bad scene raises
    :class:`arnoldweb.SceneError` naming the file, line, column and key, or the
    ``Scene.set(...)`` call that gave the value.

    A Scene is a :class:`collections.abc.Mapping` of its dotted keys (``"model.energy"``)
    to their values as run: ``len``, ``in``, iteration, ``keys()``, ``values()``,
    ``items()``, ``get()`` and ``==`` agree with each other. Keys cannot be deleted:
    every key has a value (its default when the scene does not write it).
    """

    __slots__ = ("_scene", "_text", "_name", "_overrides", "_labels")

    def __init__(self, *args: Any, **kwargs: Any):
        raise TypeError("make a Scene with Scene.from_file(path), Scene.from_toml(text) or Scene.from_dict(d)")

    @classmethod
    def _make(cls, text: str, name: str, overrides: Sequence[str] = (), labels: Sequence[str] = ()) -> Scene:
        self = object.__new__(cls)
        self._text = text
        self._name = name
        self._overrides = list(overrides)
        self._labels = list(labels)
        self._scene = _core._Scene.parse(text, name, self._overrides, self._labels)
        return self

    @classmethod
    def from_file(cls, path: str | os.PathLike[str]) -> Scene:
        """Reads and validates a scene file (TOML). Raises FileNotFoundError when there is no
        such file, SceneError when it cannot be read or run."""
        path = os.fspath(path)
        if not os.path.exists(path):
            raise FileNotFoundError(errno.ENOENT, f"no scene file {path!r} (in {os.getcwd()})", path)
        scene = _core._Scene.load(path)
        return cls._make(scene.text, scene.file)

    @classmethod
    def from_toml(cls, text: str, name: str = "<string>") -> Scene:
        """Reads and validates scene text; ``name`` stands for the file in messages. Raises SceneError."""
        return cls._make(text, name)

    @classmethod
    def from_dict(cls, d: Mapping[str, Any], name: str = "<dict>") -> Scene:
        """A scene from a dict: nested tables ({"model": {"energy": 30}}) or dotted keys
        ({"model.energy": 30}); ``"panel": [{...}, ...]`` gives [[panel]] tables. The dict is
        written as TOML and read by the library, so the checks and messages are the CLI's
        (lines then refer to that text, :meth:`to_toml` of the defaults aside). A float with a
        whole value (``1e6``) is written as an integer where the key takes one. Raises SceneError."""
        return cls._make(_toml.document(d, _toml.integer_keys()), name)

    def set(self, key: str, value: Any) -> Scene:
        """A new scene: this one with ``key`` set to ``value``, as ``--set key=value`` does.
        This scene is left as it was, so one scene can be the base of several
        (``hot = base.set("model.energy", 30)``) and calls chain:
        ``scene.set("model.energy", 30).set("integrator.step", 0.01)``. To change a scene in
        place, assign: ``scene["model.energy"] = 30``.

        ``value`` is a Python bool, number, string, list or dict (numpy scalars and arrays
        too); a float with a whole value (``1e6``) is an integer where the key takes one.
        Raises SceneError naming this call when the value is wrong for the key."""
        other = self.copy()
        other[key] = value
        return other

    def __setitem__(self, key: str, value: Any) -> None:
        """``scene[key] = value``: sets one key of this scene in place (as :meth:`set`, which
        leaves the scene alone and returns a new one). Raises SceneError naming
        ``Scene.set(key, value)``; the scene is then left as it was."""
        if not isinstance(key, str):
            raise TypeError(f"scene keys are dotted strings such as 'model.energy', not {type(key).__name__}")
        override = f"{key}={_toml.literal(value, _toml.integer_keys(), key)}"
        self._apply(override, f"Scene.set({key!r}, {value!r})")  # how messages name it

    def __delitem__(self, key: str) -> None:
        raise TypeError(f"scene keys cannot be deleted ({key!r}): every key has a value, its default unless "
                        "the scene sets another; set the default instead")

    def _apply(self, override: str, label: str) -> None:
        scene = _core._Scene.parse(self._text, self._name, self._overrides + [override], self._labels + [label])
        self._scene = scene
        self._overrides.append(override)
        self._labels.append(label)

    def copy(self) -> Scene:
        """An independent copy (changing it with ``copy[key] = value`` leaves this scene alone)."""
        return Scene._make(self._text, self._name, self._overrides, self._labels)

    def check(self) -> dict:
        """Validates the scene as a whole and plans it and its panels, as ``arnoldweb check``
        does; computes nothing (an ``integrator.step = "auto"`` is resolved by a pilot on the
        cpu backend). Returns the plan as a dict: method, stages, step, steps_per_segment,
        segments_per_window, windows, steps_per_trajectory, trajectories, trajectory_steps,
        force_evaluations, nside (0 without a velocity map), npix, frames, zoom_resolution,
        effects, kernel_defines, warnings, step_guard (value, limit, advised, safe_step),
        memory (largest_launch, device_bytes, host_bytes), device, output_dir, scene (the
        scene as run), panels (each a plan dict with name and title) and output_bytes.
        Values wrong together raise SceneError placed at the ``Scene.set(...)`` that gave one
        of them, when one did."""
        return self._scene.check()

    def to_toml(self) -> str:
        """The scene as run, as TOML: every key, defaults included (overrides applied)."""
        return self._scene.to_toml()

    def to_dict(self) -> dict:
        """The scene as run as a dict of tables (the ``scene`` echo of summary.json)."""
        import json
        return json.loads(self._scene.to_json())

    def __getitem__(self, key: str) -> Any:
        """The value of a dotted key as run, e.g. ``scene["model.energy"]``. KeyError for a
        key the scene does not have, and for a table (``scene["model"]``: its keys are
        ``"model.kind"``, ...; :meth:`to_dict` gives the tables)."""
        if not isinstance(key, str):
            raise KeyError(key)
        node: Any = self.to_dict()
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(key)
            node = node[part]
        if isinstance(node, dict):
            raise KeyError(f"{key!r} is a table, not a key: its keys are {key}.{', {key}.'.join(node)}")
        return node

    def __iter__(self) -> Iterator[str]:
        """The dotted keys of the scene as run, every value's (tables spread out), in the
        order of :meth:`to_toml`."""
        out: List[str] = []

        def walk(prefix: str, node: Any) -> None:
            for k, v in node.items():
                if isinstance(v, dict):
                    walk(prefix + k + ".", v)
                else:
                    out.append(prefix + k)
        walk("", self.to_dict())
        return iter(out)

    def __len__(self) -> int:
        return sum(1 for _ in self)

    def __eq__(self, other: object) -> bool:
        """Scenes are equal when they run the same: every key as run is equal (wherever
        they were read from, however the values were set)."""
        if not isinstance(other, Scene):
            return NotImplemented
        return self.to_dict() == other.to_dict()

    __hash__ = None  # type: ignore[assignment]  # a Scene changes (scene[key] = value)

    # pickle and copy.deepcopy: the text, its name and the overrides, read again by the library
    def __reduce__(self):
        return (_rebuild, (self._text, self._name, list(self._overrides), list(self._labels)))

    def __copy__(self) -> Scene:
        return self.copy()

    def __deepcopy__(self, memo: dict) -> Scene:
        return self.copy()

    @property
    def file(self) -> str:
        """The file the scene was read from, or its name ("<string>", "<dict>")."""
        return self._name

    @property
    def text(self) -> str:
        """The TOML text the scene was read from (before overrides)."""
        return self._text

    @property
    def overrides(self) -> list:
        """The key=value overrides applied on top, in order."""
        return list(self._overrides)

    def __repr__(self) -> str:
        d = self.to_dict()
        shown = []
        for key in ("model.kind", "model.energy", "ensemble.trajectories", "integrator.method", "integrator.step",
                    "run.duration"):
            table, _, name = key.partition(".")
            if name in d.get(table, {}):
                shown.append(f"{key}={d[table][name]!r}")
        extra = f", {len(self._overrides)} overrides" if self._overrides else ""
        return f"<arnoldweb.Scene {_shown_name(self._name)}: {', '.join(shown)}{extra}>"


Scene.__module__ = "arnoldweb"


def _shown_name(name: str) -> str:
    """A scene's name for its repr: a shipped scene by the name aw.scene() takes, not its path
    inside the installation."""
    from ._scenes import shipped_name
    shipped = shipped_name(name)
    return f"scene({shipped!r})" if shipped else name


def _rebuild(text: str, name: str, overrides: Sequence[str], labels: Sequence[str]) -> Scene:
    """A pickled Scene, read again by the library."""
    return Scene._make(text, name, overrides, labels)
