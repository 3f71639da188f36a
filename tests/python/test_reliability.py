"""Reliability of what the package compares and reads back (issue 27): compare_maps refuses what
is not a map of counts instead of casting it (item 13), and Result.summary reads summary.json
as render and compare read it, checked (items 2 to 4); the HDF5 files load hands to h5py and
continue_run's sets go through the library's rules (issue 37, items 1 and 7)."""
import json
import os
import threading

import numpy as np
import pytest

import arnoldweb as aw


def test_negative_counts_are_refused_not_wrapped_around():
    # cast to uint64, -1 became 2^64 - 1: total_a = 18446744073709551604
    with pytest.raises(ValueError, match="negative count"):
        aw.compare_maps(-np.ones(12), np.ones(12))
    with pytest.raises(ValueError, match="negative count"):
        aw.compare_maps(np.ones(12, dtype=np.int64), np.array([3] * 11 + [-2]))


@pytest.mark.parametrize("bad, says", [(np.nan, "non-finite"), (np.inf, "non-finite"), (-np.inf, "non-finite"),
                                       (2.5, "not a whole number"), (2.0 ** 70, "too large")])
def test_non_integer_or_non_finite_counts_are_refused(bad, says):
    a = np.full(12, 4.0)
    a[5] = bad
    with pytest.raises(ValueError, match=says):
        aw.compare_maps(a, np.full(12, 4.0))
    with pytest.raises(ValueError, match=says):  # either side
        aw.compare_maps(np.full(12, 4.0), a)


def test_averaged_maps_are_refused_summed_maps_compared():
    # what healpy.ud_grade(m.astype(float), ...) does by default: children averaged, not added
    rng = np.random.default_rng(3)
    p = rng.dirichlet(np.ones(3072))
    a, b = rng.multinomial(200000, p), rng.multinomial(200000, p)
    with pytest.raises(ValueError, match="power=-2"):
        aw.compare_maps(a.reshape(-1, 4).mean(axis=1), b.reshape(-1, 4).mean(axis=1))
    # whole-number floats (ud_grade with power=-2 adds the counts) are counts, compared as such
    c = aw.compare_maps(a.reshape(-1, 4).sum(axis=1).astype(float), b.reshape(-1, 4).sum(axis=1).astype(float))
    assert c["total_a"] == 200000 and c["total_b"] == 200000
    assert c["bins"] == 768


def test_other_types_and_shapes_are_refused():
    with pytest.raises(ValueError, match="counts"):
        aw.compare_maps(np.array(["a"] * 12), np.ones(12))
    with pytest.raises(ValueError, match="1-D"):
        aw.compare_maps(np.ones((3, 4)), np.ones((3, 4)))
    c = aw.compare_maps(list(range(12)), np.arange(12, dtype=np.uint32))  # integers of any type
    assert c["total_a"] == 66 and c["total_b"] == 66


def test_summary_is_read_back_checked(small_scene, tmp_path):
    out = tmp_path / "out"
    r = aw.run(small_scene, out=out)
    digests = r.summary["file_digests"]
    assert digests["map.h5"]["bytes"] == os.path.getsize(out / "map.h5")
    assert len(digests["map.h5"]["xxh3_128"]) == 32
    # a summary.json of the wrong form: OutputError naming it, not a KeyError later
    (out / "summary.json").write_text("[]\n")
    with pytest.raises(aw.OutputError, match="summary.json: must be a JSON object"):
        r.summary
    # a FIFO in its place is refused at once (it blocked for ever in open())
    os.remove(out / "summary.json")
    os.mkfifo(out / "summary.json")
    done = []
    t = threading.Thread(target=lambda: done.append(pytest.raises(aw.OutputError, lambda: r.summary)), daemon=True)
    t.start()
    t.join(10)
    assert done, "reading a FIFO as summary.json blocked"
    assert "pipe (FIFO)" in str(done[0].value)


def test_load_checks_every_file_it_reads(tmp_path):
    from conftest import small_dict
    d = small_dict(observe={"final_states": True, "fli": True})
    d["panel"] = [{"name": "hot", "set": ["model.energy=16"]}]
    out = tmp_path / "run"
    aw.run(aw.Scene.from_dict(d), out=out)
    assert aw.load(out).states["final"]  # intact: read
    # a flipped byte in states.h5 (read with h5py before, unchecked)
    with open(out / "states.h5", "r+b") as f:
        f.seek(os.path.getsize(out / "states.h5") // 2)
        byte = f.read(1)
        f.seek(-1, os.SEEK_CUR)
        f.write(bytes([byte[0] ^ 0xFF]))
    with pytest.raises(aw.OutputError, match="states.h5: its XXH3-128 digest is"):
        aw.load(out).states
    # a panel's summary.json changed after the run: its digest is in the main summary.json
    panel = out / "panel-hot" / "summary.json"
    panel.write_text(panel.read_text().replace('"interrupted": false', '"interrupted": true'))
    with pytest.raises(aw.OutputError, match="panel-hot/summary.json"):
        aw.load(out)
    # a FIFO as summary.json: refused at once (open() blocked for ever)
    os.remove(out / "summary.json")
    os.mkfifo(out / "summary.json")
    done = []
    t = threading.Thread(target=lambda: done.append(pytest.raises(aw.OutputError, aw.load, out)), daemon=True)
    t.start()
    t.join(10)
    assert done, "aw.load blocked on a FIFO as summary.json"
    assert "pipe (FIFO)" in str(done[0].value)


def test_load_refuses_hdf5_files_that_lead_out_of_themselves(small_scene, tmp_path):
    """Issue 37, item 1: the HDF5 files that load hands to h5py go through the library's HDF5
    reader first: an external link to a FIFO is refused at once (h5py would block on it)."""
    import h5py
    out = tmp_path / "run"
    aw.run(small_scene.copy().set("observe.final_states", True), out=out)
    os.mkfifo(tmp_path / "fifo.h5")
    os.remove(out / "states.h5")
    with h5py.File(out / "states.h5", "w") as f:
        f["final/momentum"] = h5py.ExternalLink(str(tmp_path / "fifo.h5"), "/momentum")
    j = json.loads((out / "summary.json").read_text())
    del j["file_digests"]  # an older directory: read without digests, still by the reader's policy
    (out / "summary.json").write_text(json.dumps(j))
    done = []
    t = threading.Thread(target=lambda: done.append(pytest.raises(aw.OutputError, lambda: aw.load(out).states)),
                         daemon=True)
    t.start()
    t.join(20)
    assert done, "aw.load blocked on an external link to a FIFO"
    assert "/final/momentum is an external link" in str(done[0].value)


def test_continue_run_sets_only_keys_that_keep_the_trajectories(small_scene, tmp_path):
    """Issue 37, item 7: continue_run's sets go through the library's one list (continue_keys)."""
    small_scene.set("observe.final_states", True)
    aw.run(small_scene, out=tmp_path / "first")
    with pytest.raises(aw.SceneError, match="a continuation keeps the run's trajectories"):
        aw.continue_run(tmp_path / "first", 5.0, sets={"integrator.step": 0.01})
    with pytest.raises(aw.SceneError, match="runs for the duration it is given"):
        aw.continue_run(tmp_path / "first", 5.0, sets={"run.duration": 10.0})
