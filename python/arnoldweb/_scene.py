"""Scenes: read, validated and planned by the C++ library (the CLI's reader)."""
from __future__ import annotations

import os
from typing import Any, Iterator, List, Mapping, Sequence

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
        self._apply(override, f"Scene.set({key!r}, {value!r})")  # how messages name it
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
        if not isinstance(key, str):
            raise KeyError(key)
        node: Any = self.to_dict()
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(key)
            node = node[part]
        return node

    def __contains__(self, key: object) -> bool:
        """``"model.energy" in scene``: whether a dotted key (or a table such as ``"observe"``) is
        part of the scene as run."""
        try:
            self[key]  # type: ignore[index]
        except KeyError:
            return False
        return True

    def keys(self) -> List[str]:
        """The dotted keys of the scene as run, every value's (tables spread out), in the
        order of :meth:`to_toml`; ``list(scene)`` and ``for key in scene`` give the same."""
        out: List[str] = []

        def walk(prefix: str, node: Any) -> None:
            for k, v in node.items():
                if isinstance(v, dict):
                    walk(prefix + k + ".", v)
                else:
                    out.append(prefix + k)
        walk("", self.to_dict())
        return out

    def items(self) -> List["tuple[str, Any]"]:
        """(dotted key, value) pairs of the scene as run, as :meth:`keys` orders them."""
        return [(k, self[k]) for k in self.keys()]

    def get(self, key: str, default: Any = None) -> Any:
        """``scene[key]``, or ``default`` when the scene has no such key."""
        return self[key] if key in self else default

    def __iter__(self) -> Iterator[str]:
        return iter(self.keys())

    def __len__(self) -> int:
        return len(self.keys())

    def __eq__(self, other: object) -> bool:
        """Scenes are equal when they run the same: every key as run is equal (wherever
        they were read from, however the values were set)."""
        if not isinstance(other, Scene):
            return NotImplemented
        return self.to_dict() == other.to_dict()

    __hash__ = None  # type: ignore[assignment]  # a Scene changes (set)

    # pickle and copy.deepcopy: the text, its name and the overrides, read again by the library
    def __reduce__(self):
        return (_rebuild, (self._text, self._name, list(self._overrides), list(self._labels)))

    def __copy__(self) -> "Scene":
        return self.copy()

    def __deepcopy__(self, memo: dict) -> "Scene":
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
        return f"<arnoldweb.Scene {self._name}: {', '.join(shown)}{extra}>"


def _rebuild(text: str, name: str, overrides: Sequence[str], labels: Sequence[str]) -> Scene:
    """A pickled Scene, read again by the library."""
    return Scene._make(text, name, overrides, labels)
