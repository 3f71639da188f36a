"""Scenes: read, validated and planned by the C++ library (the CLI's reader)."""
from __future__ import annotations

import os
from typing import Any, Mapping, Sequence

from . import _arnoldweb as _core
from . import _toml

__all__ = ["Scene"]


class Scene:
    """One experiment: a scene file's keys (docs/scenes.md), validated.

    Make one with :meth:`from_file`, :meth:`from_toml` or :meth:`from_dict`;
    change keys with :meth:`set` (as ``arnoldweb run --set`` does); look at the
    plan with :meth:`check`; run it with :func:`arnoldweb.run`. Every check and
    message is the library's, the same as the CLI's; a bad scene raises
    :class:`arnoldweb.SceneError` naming the file, line, column and key.
    """

    __slots__ = ("_scene", "_text", "_name", "_overrides", "_labels")

    def __init__(self, *args: Any, **kwargs: Any):
        raise TypeError("make a Scene with Scene.from_file(path), Scene.from_toml(text) or Scene.from_dict(d)")

    @classmethod
    def _make(cls, text: str, name: str, overrides: Sequence[str] = (), labels: Sequence[str] = ()) -> "Scene":
        self = object.__new__(cls)
        self._text = text
        self._name = name
        self._overrides = list(overrides)
        self._labels = list(labels)
        self._scene = _core._Scene.parse(text, name, self._overrides, self._labels)
        return self

    @classmethod
    def from_file(cls, path: "str | os.PathLike[str]") -> "Scene":
        """Reads and validates a scene file (TOML). Raises SceneError."""
        scene = _core._Scene.load(os.fspath(path))
        return cls._make(scene.text, scene.file)

    @classmethod
    def from_toml(cls, text: str, name: str = "<string>") -> "Scene":
        """Reads and validates scene text; ``name`` stands for the file in messages. Raises SceneError."""
        return cls._make(text, name)

    @classmethod
    def from_dict(cls, d: Mapping[str, Any], name: str = "<dict>") -> "Scene":
        """A scene from a dict: nested tables ({"model": {"energy": 30}}) or dotted keys
        ({"model.energy": 30}); ``"panel": [{...}, ...]`` gives [[panel]] tables. The dict is
        written as TOML and read by the library, so the checks and messages are the CLI's
        (lines then refer to that text, :meth:`to_toml` of the defaults aside). Raises SceneError."""
        return cls._make(_toml.document(d), name)

    def set(self, key: str, value: Any) -> "Scene":
        """Sets one key, as ``--set key=value`` does, and returns the scene (so calls chain:
        ``scene.set("model.energy", 30).set("ensemble.trajectories", 10**5)``).

        ``value`` is a Python bool, number, string, list or dict. The scene is read again with
        the override; if that fails, SceneError is raised and the scene is left as it was."""
        override = f"{key}={_toml.literal(value)}"
        self._apply(override, "")
        return self

    def _apply(self, override: str, label: str) -> None:
        scene = _core._Scene.parse(self._text, self._name, self._overrides + [override], self._labels + [label])
        self._scene = scene
        self._overrides.append(override)
        self._labels.append(label)

    def copy(self) -> "Scene":
        """An independent copy (set() on it leaves this scene alone)."""
        return Scene._make(self._text, self._name, self._overrides, self._labels)

    def check(self) -> dict:
        """Validates the scene as a whole and plans it and its panels, as ``arnoldweb check``
        does; computes nothing (an ``integrator.step = "auto"`` is resolved by a pilot on the
        cpu backend). Returns the plan as a dict: method, step, schedule, work
        (trajectory_steps, force_evaluations), effects, nside, step_guard, memory, warnings,
        panels (each a plan dict with name and title), output_bytes and the scene as run."""
        return self._scene.check()

    def to_toml(self) -> str:
        """The scene as run, as TOML: every key, defaults included (overrides applied)."""
        return self._scene.to_toml()

    def to_dict(self) -> dict:
        """The scene as run as a dict of tables (the ``scene`` echo of summary.json)."""
        import json
        return json.loads(self._scene.to_json())

    def __getitem__(self, key: str) -> Any:
        """The value of a dotted key as run, e.g. ``scene["model.energy"]``."""
        node: Any = self.to_dict()
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(key)
            node = node[part]
        return node

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
        extra = f", {len(self._overrides)} overrides" if self._overrides else ""
        return f"<arnoldweb.Scene {self._name}{extra}>"
