"""Runs: numpy dtypes and shapes, zero-copy views, summary, outputs, progress, the GIL."""
import json
import threading
import time

import numpy as np
import pytest

import arnoldweb as aw


def test_done_when_command(repo):
    # the "done when", at 2000 trajectories
    r = aw.run(aw.Scene.from_file(repo / "scenes" / "default.toml").set("ensemble.trajectories", 2000)
               .set("run.device", "cpu"))
    assert r.map.sum() == r.binned == r.completed == 2000


def test_a_device_list_gives_one_device_bits(small_scene):
    opencl = [d["id"] for d in aw.devices() if d["id"].startswith("opencl:")]
    if not opencl:
        pytest.skip("no OpenCL device (PoCL) beside the cpu backend")
    one = aw.run(small_scene, device="cpu")
    both = aw.run(small_scene, device="cpu," + opencl[0])
    assert np.array_equal(one.map, both.map)
    assert one.digests == both.digests
    assert both.device["id"] == "cpu," + opencl[0]


def test_map_dtype_shape_and_ring_order(small_scene):
    r = aw.run(small_scene)
    assert r.nside == 16 and r.ordering == "RING"
    assert r.map.dtype == np.uint64 and r.map.shape == (12 * 16 * 16,)
    assert not r.map.flags.writeable
    assert r.map.sum() == r.binned  # one window per trajectory
    assert r.frames is None and r.zoom is None and r.states is None and r.indicators is None
    assert r.counters.dtype.names == aw.COUNTER_NAMES
    assert r.counters["trajectories"] == 3000 and r.counters["completed"] == 3000
    assert r.counters["binned"] + r.counters["flagged_energy"] + r.counters["flagged_nonfinite"] \
        + r.counters["flagged_initial"] == 3000
    assert r.energy["tracked"] and 0 < r.energy["max"] < 1e-2
    assert r.energy["log_hist"].dtype == np.uint64 and r.energy["log_hist"].sum() == 3000


def test_map_is_a_view_of_the_library_memory(small_scene):
    r = aw.run(small_scene)
    a = r._record.map(0)
    b = r._record.map(0)
    assert np.shares_memory(a, b)  # two views of one buffer: no copy was made
    del r
    assert a.sum() == b.sum() > 0  # the view keeps the run alive


def test_states_shapes_and_dtypes(small_scene):
    small_scene = small_scene.set("observe.initial_states", True).set("observe.final_states", True)
    r = aw.run(small_scene)
    n = r.completed
    init, fin = r.states["initial"], r.states["final"]
    assert init["momentum"].shape == (n, 3) and init["momentum"].dtype == np.float64
    assert fin["winding"].shape == (n, 3) and fin["winding"].dtype == np.int64
    assert fin["status"].shape == (n,) and set(np.unique(fin["status"])) <= {0, 1, 2, 3, 4}
    assert np.all(np.abs(fin["position_turns"]) <= 0.5)
    np.testing.assert_allclose(fin["position"], 2 * np.pi * (fin["winding"] + fin["position_turns"]))
    # the energy shell: |P|^2 / 2 = E at the start for the shell kind
    p = init["momentum"]
    np.testing.assert_allclose(0.5 * (p ** 2).sum(axis=1).max(), 15.0, rtol=0.2)


def test_zoom_and_frames_shapes(small_scene):
    small_scene = small_scene.set("observe.zoom", {"center": [45.0, 0.0], "width": 60.0, "resolution": 32})
    small_scene = small_scene.set("run.duration", 10.0).set("observe.frames", {"times": [0.0, 5.0, 10.0]})
    r = aw.run(small_scene)
    assert r.zoom.shape == (32, 32) and r.zoom.dtype == np.uint64
    assert r.frames.shape == (2, 12 * 16 * 16) and r.frames.dtype == np.uint64
    assert np.array_equal(r.frames.sum(axis=0), r.map)  # every window binned in its frame
    assert r.map.sum() == 2 * r.binned  # two windows per trajectory


def test_summary_is_summary_json(small_scene, tmp_path):
    r = aw.run(small_scene)
    before = r.summary
    assert before["binned"] == r.binned and before["digests"]["map"] == r.digests["map"]
    assert before["files"] == []
    files = r.write(tmp_path / "out")
    with open(tmp_path / "out" / "summary.json") as f:
        written = json.load(f)
    assert r.summary == written
    assert sorted(written["files"]) == sorted(p.split("/out/", 1)[1] for p in files if not p.endswith("summary.json"))
    for key in ("trajectories", "binned", "flagged", "energy_error", "digests", "method", "schedule"):
        assert before[key] == written[key], key
    assert written["scene"]["output"]["dir"] == str(tmp_path / "out")  # write(out) is `--out out`
    assert {k: v for k, v in before["scene"].items() if k != "output"} == \
        {k: v for k, v in written["scene"].items() if k != "output"}


def test_run_out_writes_like_the_cli(small_scene, tmp_path):
    r = aw.run(small_scene, out=tmp_path / "o")
    assert (tmp_path / "o" / "map.h5").exists()
    assert r.summary["scene"]["output"]["dir"].endswith("/o")
    h5py = pytest.importorskip("h5py")
    with h5py.File(tmp_path / "o" / "map.h5") as f:
        assert np.array_equal(f["map"][...], r.map)


def test_progress_callback_sees_every_chunk(small_scene):
    small_scene = small_scene.set("ensemble.chunk", 500)
    seen = []
    r = aw.run(small_scene, progress=lambda done, total, seconds: seen.append((done, total)))
    dones = [d for d, _ in seen]
    assert dones[:6] == [500, 1000, 1500, 2000, 2500, 3000]
    assert all(t == 3000 for _, t in seen)
    assert r.completed == 3000


def test_progress_true_prints(small_scene, capsys):
    aw.run(small_scene, progress=True)
    assert "3" in capsys.readouterr().err  # tqdm or plain lines, on stderr


def test_exception_in_callback_stops_with_partial_result(small_scene):
    small_scene = small_scene.set("ensemble.chunk", 500)

    def cb(done, total, seconds):
        if done >= 1000:
            raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough") as e:
        aw.run(small_scene, progress=cb)
    r = e.value.result
    assert r.interrupted and r.completed == 1000 and r.map.sum() == r.binned


def test_gil_is_released_while_computing(small_scene):
    small_scene = small_scene.set("ensemble.trajectories", 100000)  # long enough on a fast CPU (20000: 0.09 s on AVX-512)
    ticks = []
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks.append(1)
            time.sleep(0.001)

    t = threading.Thread(target=count)
    t.start()
    start = time.monotonic()
    aw.run(small_scene)
    elapsed = time.monotonic() - start
    stop.set()
    t.join()
    # a thread that needs the GIL kept ticking during the run (held, it would tick at most
    # once or twice: the run's Python parts take microseconds)
    assert elapsed > 0.1 and len(ticks) >= 20


def test_panels_are_results(small_scene):
    from conftest import SMALL
    small_scene = aw.Scene.from_dict({
        **SMALL, "panel": [{"name": "b", "title": "fewer", "set": ["ensemble.trajectories=500"]}]})
    r = aw.run(small_scene)
    assert list(r.panels) == ["b"]
    assert r.panels["b"].completed == 500 and r.panels["b"].title == "fewer"
    assert r.panels["b"].map.sum() == r.panels["b"].binned


def test_accuracy_report(small_scene):
    rep = aw.accuracy(small_scene, target=1e-6, pilot=64, pilot_duration=1.0, methods=["leapfrog", "yoshida6a"])
    assert [f["method"] for f in rep["fits"]] == ["leapfrog", "yoshida6a"]
    assert rep["pilot_trajectories"] == 64
    assert rep["found"] == (rep["best"] is not None)
    if rep["found"]:
        assert rep["best"]["meets"] and rep["best"]["measured_max"] * 4 <= 1e-6


def test_no_indicators_unless_asked(small_scene):
    assert aw.run(small_scene).indicators is None


def test_indicators_on_a_healpix_grid(small_scene):
    small_scene = small_scene.set("ensemble.initial", "grid").set("ensemble.grid", {"kind": "healpix", "nside": 2})
    small_scene = small_scene.set("ensemble.trajectories", 48).set("observe.fli", True).set("observe.megno", True)
    r = aw.run(small_scene)
    ind = r.indicators
    assert ind.shape == (48,) and ind.dtype.names == aw.INDICATOR_NAMES
    assert np.all(np.isfinite(ind["fli"])) and np.all(ind["fli"] >= 0)
    assert np.all(np.isnan(ind["lyapunov"]))  # not asked
    assert np.all(np.isfinite(ind["megno"])) and np.all(ind["megno"] > 0)
    assert r.digests["indicators"] != ""


def test_indicators_on_a_lonlat_grid_have_its_shape(small_scene):
    small_scene = small_scene.set("ensemble.initial", "grid").set("ensemble.grid", {"kind": "lonlat", "resolution": [6, 4]})
    small_scene = small_scene.set("ensemble.trajectories", 24).set("observe.lyapunov", True)
    r = aw.run(small_scene)
    assert r.indicators.shape == (4, 6)  # [n2][n1], as in indicators.h5
    assert np.all(np.isfinite(r.indicators["lyapunov"]))


def test_compare_maps_float_against_double(small_scene):
    """compare_maps: two independent runs (float, double) agree; a map against itself with half
    its pixels doubled does not; bad input is a ValueError."""
    import numpy as np
    s = small_scene.set("ensemble.trajectories", 20000).set("observe.velocity_map.nside", 4)
    double = aw.run(s.copy().set("ensemble.seed", 1))
    float_ = aw.run(s.copy().set("ensemble.seed", 2).set("integrator.precision", "float"))
    same = aw.compare_maps(double.map, float_.map)
    assert same["total_a"] == double.map.sum() and same["total_b"] == float_.map.sum()
    assert same["dof"] == same["used_bins"] - 1 and same["bins"] == 192
    assert same["p_value"] > 1e-3, same
    assert aw.compare_maps(double.map, double.map)["chi2"] == 0.0
    skewed = np.array(double.map)
    skewed[:96] *= 2
    different = aw.compare_maps(double.map, skewed)
    assert different["p_value"] < 1e-6, different
    with pytest.raises(ValueError, match="different sizes"):
        aw.compare_maps(double.map, double.map[:-1])


def test_frequencies_and_diffusion_from_python(repo, tmp_path):
    """observe.frequencies and observe.diffusion: the records as their files hold them, the
    diffusion analysis as summary.json holds it, the same from a saved run (docs/frequencies.md)."""
    s = aw.Scene.from_file(repo / "scenes" / "fgl_frequency_map.toml")
    s = s.set("ensemble.grid.resolution", [6, 4]).set("observe.fli", False).set("run.device", "cpu")
    s = s.set("observe.diffusion", {"every": 10.24, "along": [1, 1, 0], "across": [1, -1, 0], "fit_from": 40.96})
    r = aw.run(s, out=tmp_path / "fm")
    f = r.outputs["frequencies"]
    assert f["nu_first"].shape == (4, 6, 3) and f["diffusion_index"].shape == (4, 6)
    # at eps = 0.01 the frequencies are the actions to ~1e-2, phi3 turns at 1 per T
    assert np.allclose(f["nu_first"][..., 0], r.outputs["frequencies"]["nu_second"][..., 0], atol=0.05)
    assert np.allclose(f["nu_first"][..., 2], 1.0, atol=1e-6)
    a = r.outputs["actions"]
    assert a["momentum"].shape == (24, 17, 3)  # 16 sample times after t = 0
    d = r.analyses["diffusion"]
    assert d["trajectories"] == 24 and len(d["moments"]["t"]) == 17
    assert np.isfinite(d["along_fit"]["D"])
    for name in ("frequencies.h5", "frequency_map.png", "diffusion_index.png", "diffusion.h5", "diffusion.csv",
                 "diffusion.png"):
        assert (tmp_path / "fm" / name).is_file(), name
    back = aw.load(tmp_path / "fm")
    assert back.analyses == json.loads(json.dumps(r.analyses))
    assert back.digests["frequencies"] == r.digests["frequencies"]


def test_continue_run_is_one_longer_run(small_scene, tmp_path):
    """aw.continue_run(out, T): a run of 2T is bit for bit a run of T continued for T (the final
    states and windings, the map of the second window, the time), as `arnoldweb continue`."""
    small_scene = small_scene.set("observe.final_states", True).set("ensemble.trajectories", 1000)
    whole = aw.run(small_scene.copy().set("run.duration", 10.0))
    first = aw.run(small_scene, out=tmp_path / "first")
    rest = aw.continue_run(tmp_path / "first", 5.0)
    a, b = whole.states["final"], rest.states["final"]
    for name in ("position_turns", "winding", "momentum", "status"):
        assert np.array_equal(a[name], b[name]), name
    # the map counts one velocity per window: the 2T run's is the first window's plus the second's
    assert np.array_equal(whole.map, first.map + rest.map)
    assert rest.summary["time"]["start"] == 5.0 and rest.summary["time"]["end"] == 10.0
    with pytest.raises(ValueError):
        aw.continue_run(tmp_path / "first", -1.0)
    aw.run(small_scene.copy().set("observe.final_states", False), out=tmp_path / "nostates")
    with pytest.raises(aw.OutputError, match="final states"):
        aw.continue_run(tmp_path / "nostates", 5.0)
    (tmp_path / "first" / "states.h5").write_bytes(b"changed")
    with pytest.raises(aw.OutputError, match="states.h5"):
        aw.continue_run(tmp_path / "first", 5.0)
