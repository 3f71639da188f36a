"""The `arnoldweb` command of a pip install: the CLI built with the package (same library)."""
from __future__ import annotations

import os
import sys


def executable() -> str:
    """Path of the arnoldweb CLI installed with this package."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "arnoldweb")


def main() -> None:
    path = executable()
    if not os.access(path, os.X_OK):
        sys.exit(f"arnoldweb: the command-line program is not part of this installation ({path})")
    # argv[0] "arnoldweb": the usage and error lines name the command as it was typed, not the
    # program's place inside the installation
    os.execv(path, ["arnoldweb"] + sys.argv[1:])
