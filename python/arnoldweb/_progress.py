"""Progress of a run: a tqdm bar when tqdm is installed, plain lines on stderr otherwise."""
from __future__ import annotations

import sys
from typing import Callable, Optional

ProgressCallback = Callable[[int, int, float], None]


def _tqdm():
    """tqdm's bar class: the notebook widget where a notebook can show it (Jupyter with
    ipywidgets), else the text bar (which a notebook shows as text); None without tqdm."""
    try:
        from tqdm.std import tqdm
    except ImportError:
        return None
    if _in_notebook():
        try:
            import ipywidgets  # noqa: F401  (tqdm.notebook needs it, and warns without it)
            from tqdm.notebook import tqdm as widget
            return widget
        except ImportError:
            pass
    return tqdm


def _in_notebook() -> bool:
    """Running in a Jupyter kernel (the one place tqdm's widget bar can be drawn)."""
    shell = sys.modules.get("IPython")
    get = getattr(shell, "get_ipython", None)
    return bool(get and get() is not None and "IPKernelApp" in getattr(get(), "config", {}))


class _Bar:
    """progress=True: one bar per part of the job (a new part starts again at 0)."""

    def __init__(self) -> None:
        self._tqdm = _tqdm()
        self._bar = None
        self._last = (0, 0)
        self._part = 0
        self._next_print = 0.0

    def __call__(self, done: int, total: int, seconds: float) -> None:
        new_part = total != self._last[1] or done < self._last[0]
        if new_part and self._last != (0, 0):
            self.close()
            self._part += 1
        self._last = (done, total)
        label = "arnoldweb" if self._part == 0 else f"panel {self._part}"
        if self._tqdm is not None:
            if self._bar is None:
                self._bar = self._tqdm(total=total, desc=label, unit="traj", unit_scale=True)
            self._bar.update(done - self._bar.n)
        elif seconds >= self._next_print or done == total:
            self._next_print = seconds + 1.0
            rate = done / seconds if seconds > 0 else 0.0
            print(f"{label}: {done}/{total} trajectories ({100.0 * done / max(total, 1):.0f}%, "
                  f"{rate:.3g}/s)", file=sys.stderr, flush=True)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()
            self._bar = None


def make_progress(progress: "bool | ProgressCallback | None") -> "tuple[Optional[ProgressCallback], Callable[[], None]]":
    """The callback to give the library and what to call when the run ends."""
    if progress is None or progress is False:
        return None, lambda: None
    if progress is True:
        bar = _Bar()
        return bar, bar.close
    if callable(progress):
        return progress, lambda: None
    raise TypeError("progress must be None, True or a callable(done, total, seconds)")
