"""Shared fixtures of the Python package's tests (run by scripts/test-python.sh)."""
import os
import pathlib

import pytest

import arnoldweb as aw

REPO = pathlib.Path(__file__).resolve().parents[2]

# A small scene: a second or less on two cores, every effect the tests look at.
SMALL = {
    "model": {"energy": 15.0},
    "ensemble": {"trajectories": 3000, "seed": 7},
    "integrator": {"method": "yoshida6a", "step": 0.02},
    "run": {"average": 5.0, "duration": 5.0, "device": "cpu"},
    "observe": {"velocity_map": {"nside": 16}, "energy_error": {"every": 1.0}},
    "output": {"images": False},
}


def small_dict(**tables):
    """SMALL with some tables' keys replaced: small_dict(observe={"fli": True})."""
    d = {k: dict(v) for k, v in SMALL.items()}
    for table, keys in tables.items():
        d.setdefault(table, {}).update(keys)
    return d


@pytest.fixture
def small_scene():
    return aw.Scene.from_dict(SMALL)


@pytest.fixture
def repo():
    return REPO


def cli_paths():
    """The arnoldweb programs to compare with: the one installed with the package (the same
    build of the library) and, when set, $ARNOLDWEB_CLI (ctest gives its build's)."""
    from arnoldweb import _cli
    paths = [_cli.executable()]
    if os.environ.get("ARNOLDWEB_CLI"):
        paths.append(os.environ["ARNOLDWEB_CLI"])
    return [p for p in paths if os.access(p, os.X_OK)]


def cli_path():
    """The first of cli_paths()."""
    paths = cli_paths()
    if not paths:
        pytest.fail("no arnoldweb program: neither the package's nor $ARNOLDWEB_CLI")
    return paths[0]
