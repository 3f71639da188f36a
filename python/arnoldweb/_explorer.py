"""arnoldweb.view and arnoldweb.serve: the explorer (docs/viewer.md) from Python, through the
arnoldweb command installed with the package (`arnoldweb view`, `arnoldweb serve`)."""
from __future__ import annotations

import html
import os
import re
import shutil
import socket
import subprocess
import time
from typing import Optional, Sequence, Union

from ._cli import executable

__all__ = ["view", "serve", "View", "Server"]

PathLike = Union[str, "os.PathLike[str]"]


def _command() -> str:
    """The arnoldweb command: the package's own, else $ARNOLDWEB_CLI, else one on PATH."""
    for path in (executable(), os.environ.get("ARNOLDWEB_CLI", ""), shutil.which("arnoldweb") or ""):
        if path and os.access(path, os.X_OK):
            return path
    raise FileNotFoundError("the arnoldweb command is not installed with this package (set ARNOLDWEB_CLI to one)")


def _folder(run) -> str:
    """An output directory: a path, or a Result that was written or loaded from one."""
    if isinstance(run, (str, os.PathLike)):
        return os.fspath(run)
    saved = getattr(run, "_saved", None)
    folder = saved.get("written_dir") if saved is not None else getattr(getattr(run, "_record", None), "written_dir", "")
    if folder:
        return folder
    raise ValueError("view and serve show runs written to a directory: write the result first (result.write(dir))")


class View:
    """A viewer written by :func:`view`: ``path`` is its view.html (open it in a browser); in a
    notebook it shows inline."""

    def __init__(self, path: str, height: int = 640):
        self.path, self.height = path, height

    def __repr__(self) -> str:
        return f"View({self.path!r})"

    def _repr_html_(self) -> str:
        # a notebook shows the page in a frame of its own: its scripts and data inlined, as the
        # files beside view.html hold them
        folder = os.path.dirname(self.path)
        page = open(self.path, encoding="utf-8").read()

        def inline(m: "re.Match[str]") -> str:
            name = m.group(1)
            text = open(os.path.join(folder, name), encoding="utf-8").read().replace("</script", "<\\/script")
            return f"<script>{text}</script>"

        page = re.sub(r'<script src="([A-Za-z0-9_./-]+)"></script>', inline, page)
        css = open(os.path.join(folder, "explorer.css"), encoding="utf-8").read()
        page = page.replace('<link rel="stylesheet" href="explorer.css">', f"<style>{css}</style>")
        return (f'<iframe srcdoc="{html.escape(page, quote=True)}" style="width:100%;height:{self.height}px;border:0">'
                "</iframe>")


def view(*runs, to: Optional[PathLike] = None) -> View:
    """Writes the explorer's page for one or more runs (output directories, or Results written to
    one) so that it opens from file:// (`arnoldweb view`): returns a :class:`View` (its ``path``;
    shown inline in a notebook). Two runs of one resolution are also compared."""
    if not runs:
        raise ValueError("view needs at least one run")
    words = [_command(), "view", *[_folder(r) for r in runs]]
    if to is not None:
        words += ["--to", os.fspath(to)]
    r = subprocess.run(words, capture_output=True, text=True)
    if r.returncode != 0:
        from ._errors import OutputError
        raise OutputError(r.stderr.strip().removeprefix("arnoldweb: error: "))
    path = r.stdout.split("\n", 1)[0].split(None, 1)[1].strip()
    return View(path)


class Server:
    """A running `arnoldweb serve`: ``url``; ``stop()`` ends it (as Ctrl-C does: a running zoom
    is checkpointed). Also a context manager."""

    def __init__(self, process: subprocess.Popen, url: str):
        self.process, self.url = process, url

    def __repr__(self) -> str:
        return f"Server({self.url!r})"

    def stop(self, timeout: float = 120) -> int:
        if self.process.poll() is None:
            self.process.send_signal(2)  # SIGINT
            try:
                self.process.wait(timeout)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        return self.process.returncode

    def __enter__(self) -> "Server":
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    def _repr_html_(self) -> str:
        return f'<iframe src="{html.escape(self.url)}" style="width:100%;height:640px;border:0"></iframe>'


def serve(*runs, scene: Optional[PathLike] = None, port: int = 0, host: str = "127.0.0.1",
          device: Optional[str] = None, max_trajectories: Optional[int] = None,
          zooms: Optional[PathLike] = None, sets: Sequence[str] = (), timeout: float = 120) -> Server:
    """Starts `arnoldweb serve` for runs (output directories or written Results) or a scene file
    (run first) and returns a :class:`Server` once it listens (``port=0``: a free port). Zooms run
    on ``device``, at most ``max_trajectories`` each."""
    words = [_command(), "serve"]
    words += [os.fspath(scene)] if scene is not None else [_folder(r) for r in runs]
    if port == 0:
        with socket.socket() as s:
            s.bind((host, 0))
            port = s.getsockname()[1]
    words += ["--port", str(port), "--host", host]
    if device:
        words += ["--device", device]
    if max_trajectories:
        words += ["--max-trajectories", str(max_trajectories)]
    if zooms is not None:
        words += ["--zooms", os.fspath(zooms)]
    for s in sets:
        words += ["--set", s]
    p = subprocess.Popen(words, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    t0 = time.time()
    while time.time() - t0 < timeout:
        if p.poll() is not None:
            from ._errors import Error
            raise Error(p.stderr.read().strip().removeprefix("arnoldweb: error: "))
        try:
            socket.create_connection((host, port), timeout=0.2).close()
            return Server(p, f"http://{host}:{port}/")
        except OSError:
            time.sleep(0.1)
    p.kill()
    raise TimeoutError(f"arnoldweb serve did not listen on {host}:{port} in {timeout} s")
