"""The errors arnoldweb raises: the C++ library's error types, with their fields.

Every message is the library's, word for word: the CLI prints the same text.
"""
from __future__ import annotations

import re

__all__ = ["Error", "SceneError", "DeviceError", "BuildError", "OutputError", "OutputRefused", "PlanWarning", "StateError"]


class PlanWarning(UserWarning):
    """A plan that will run but cost accuracy or time (e.g. a step close to the stability
    limit), issued through :mod:`warnings` by :func:`arnoldweb.run` (the CLI prints the
    same text); ``warnings.simplefilter("error", arnoldweb.PlanWarning)`` turns them into errors."""


# The library's output messages name the CLI's options; from Python they are run()'s and
# write()'s arguments.
_PYTHON_WORDS = ((re.compile(r"--force\b"), "force=True"), (re.compile(r"another --out\b"), "another out="),
                 (re.compile(r"--out\b"), "out="))


def python_words(message: str) -> str:
    """An output message with the CLI's options named as Python arguments (force=True, out=)."""
    for pattern, words in _PYTHON_WORDS:
        message = pattern.sub(words, message)
    return message


class Error(RuntimeError):
    """Base of every error the arnoldweb library reports.

    ``result`` holds what was computed when the error came after a run (e.g. the
    outputs could not be written), else None.
    """

    result = None


class SceneError(Error, ValueError):
    """A scene that cannot be run as written: unreadable file, TOML syntax,
    unknown key, wrong type, value out of range, values wrong together.

    Attributes: ``file`` (the scene's file or name), ``line`` and ``column``
    (1-based; 0 when the value did not come from the text, e.g. a default or an
    override), ``key`` (the dotted key, e.g. "model.energy"; "" if none),
    ``reason`` (the message without the position).
    """

    def __init__(self, message: str, file: str = "", line: int = 0, column: int = 0, key: str = "",
                 reason: str = ""):
        super().__init__(message)
        self.file = file
        self.line = line
        self.column = column
        self.key = key
        self.reason = reason or message


class DeviceError(Error):
    """A device that is missing or failed: ``device`` (its id), ``call`` (the API
    function), ``status`` (its return code)."""

    def __init__(self, message: str, device: str = "", call: str = "", status: int = 0):
        super().__init__(message)
        self.device = device
        self.call = call
        self.status = status


class BuildError(Error):
    """A kernel that failed to compile: ``options`` and the full ``log``."""

    def __init__(self, message: str, options: str = "", log: str = ""):
        super().__init__(message)
        self.options = options
        self.log = log


class OutputError(Error, OSError):
    """An output that cannot be written (exists without force, no permission,
    disk full): ``path`` names it."""

    def __init__(self, message: str, path: str = ""):
        Error.__init__(self, python_words(message))
        self.path = path

    def __str__(self) -> str:
        return str(self.args[0]) if self.args else ""


class OutputRefused(OutputError):
    """An output place arnoldweb refuses whatever the options: it would replace
    something arnoldweb did not write (the current directory, a directory holding
    the scene or other files)."""


class StateError(Error, ValueError):
    """Initial states that cannot be used (a state file, or ``initial=(X, P)``): a shape, a
    type, a value that is not finite or out of range, or a state whose energy is far from
    model.energy (docs/outputs.md, "State files").

    Attributes: ``source`` (the file, or "initial" for arrays), ``dataset`` (the HDF5 dataset or
    the array, "X" or "P"; "" if none), ``row`` (the state, counted from 0; -1 if none),
    ``reason`` (the message without the place).
    """

    def __init__(self, message: str, source: str = "", dataset: str = "", row: int = -1, reason: str = ""):
        super().__init__(message)
        self.source = source
        self.dataset = dataset
        self.row = row
        self.reason = reason or message


# Tracebacks and reprs name them as users import them (arnoldweb.SceneError), not by this module.
for _public in (PlanWarning, Error, SceneError, DeviceError, BuildError, OutputError, OutputRefused, StateError):
    _public.__module__ = "arnoldweb"
del _public
