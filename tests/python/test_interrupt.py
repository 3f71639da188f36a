"""Ctrl-C: a run stops after the current chunk and raises KeyboardInterrupt with the partial result."""
import json
import os
import signal
import threading

import pytest

import arnoldweb as aw


def _long(scene):
    # many small chunks: the stop comes long before the end
    return scene.set("ensemble.trajectories", 200000).set("ensemble.chunk", 500)


def test_sigint_from_the_progress_callback(small_scene):
    sent = []

    def cb(done, total, seconds):
        if done >= 1000 and not sent:
            sent.append(done)
            os.kill(os.getpid(), signal.SIGINT)

    with pytest.raises(KeyboardInterrupt) as e:
        aw.run(_long(small_scene), progress=cb)
    r = e.value.result
    assert r.interrupted
    assert r.completed == 1000  # stopped after the chunk during which Ctrl-C came
    assert r.trajectories == 200000
    assert r.map.sum() == r.binned and r.binned > 0
    assert r.summary["interrupted"] is True and r.summary["completed"] == 1000


def test_sigint_from_another_thread_during_a_run(small_scene, tmp_path):
    # 2e6 trajectories x 250 steps: seconds even on a fast CPU (1.2e8 steps/s on 2 AVX-512 cores)
    timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as e:
            aw.run(_long(small_scene).set("ensemble.trajectories", 2000000), out=tmp_path / "partial")
    finally:
        timer.cancel()
    r = e.value.result
    assert r.interrupted and 0 < r.completed < r.trajectories
    # what was computed was written, as `arnoldweb run` does on SIGINT
    with open(tmp_path / "partial" / "summary.json") as f:
        summary = json.load(f)
    assert summary["interrupted"] is True and summary["completed"] == r.completed
    assert summary["digests"]["map"] == r.digests["map"]


def test_a_custom_handler_that_does_not_raise_lets_the_run_finish(small_scene):
    seen = []
    old = signal.signal(signal.SIGINT, lambda *a: seen.append(1))
    try:
        small_scene = small_scene.set("ensemble.chunk", 500)
        r = aw.run(small_scene, progress=lambda d, t, s: d == 500 and os.kill(os.getpid(), signal.SIGINT))
    finally:
        signal.signal(signal.SIGINT, old)
    assert seen == [1] and not r.interrupted and r.completed == 3000
