"""Interop: maps are HEALPix RING (healpy reads them), the example draws its figure."""
import os
import subprocess
import sys

import numpy as np
import pytest

import arnoldweb as aw


def test_pixel_directions_are_ring_centres(small_scene):
    d = aw.pixel_directions(16)
    assert d.shape == (12 * 16 * 16, 3) and d.dtype == np.float64
    np.testing.assert_allclose((d ** 2).sum(axis=1), 1.0, atol=1e-14)
    assert d[0, 2] > d[-1, 2]  # RING: north to south
    with pytest.raises(ValueError):
        aw.pixel_directions(12)


def test_binned_velocities_lie_on_the_shell_directions(small_scene):
    # each map pixel counts averaged velocities; the averaged velocity of a trajectory that
    # starts on the shell points near its initial momentum on this short run
    small_scene = small_scene.set("observe.initial_states", True)
    r = aw.run(small_scene)
    d = aw.pixel_directions(r.nside)
    p = r.states["initial"]["momentum"]
    p = p / np.linalg.norm(p, axis=1, keepdims=True)
    hit = d[r.map > 0]
    nearest = (p @ hit.T).max(axis=1)
    assert np.median(nearest) > 0.95


def test_healpy_reads_the_map(small_scene, tmp_path):
    hp = pytest.importorskip("healpy")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    r = aw.run(small_scene)
    assert hp.npix2nside(r.map.size) == r.nside
    np.testing.assert_allclose(np.array(hp.pix2vec(r.nside, np.arange(r.map.size))).T,
                               aw.pixel_directions(r.nside), atol=1e-12)
    hp.mollview(r.map)
    plt.savefig(tmp_path / "m.png")
    assert (tmp_path / "m.png").stat().st_size > 10000


def test_resonances():
    rs = aw.resonances(2)
    assert rs[0]["order"] == 1 and rs[-1]["order"] == 2
    assert {"m": (1, -1, 0), "order": 1, "label": "(1,-1,0)"} in rs


@pytest.mark.parametrize("flags", [[], ["--no-healpy"]])
def test_example_draws_its_figure(repo, tmp_path, flags):
    out = tmp_path / "web.png"
    done = subprocess.run([sys.executable, str(repo / "examples" / "web.py"), "--trajectories", "3000",
                           "--device", "cpu", "--out", str(out)] + flags, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "3000 of 3000 trajectories binned" in done.stdout
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20000


def test_healpy_reads_the_fits_map(small_scene, tmp_path):
    hp = pytest.importorskip("healpy")
    r = aw.run(small_scene.set("output.formats", ["hdf5", "fits"]), out=tmp_path / "run")
    assert r.map_file == str(tmp_path / "run" / "map.fits") and os.path.isfile(r.map_file)
    m, header = hp.read_map(r.map_file, h=True, dtype=None)
    header = dict(header)
    assert header["ORDERING"] == "RING" and header["NSIDE"] == r.nside == 16 and header["PIXTYPE"] == "HEALPIX"
    assert header["INDXSCHM"] == "IMPLICIT" and hp.get_nside(m) == 16
    np.testing.assert_array_equal(m, r.map)
    assert "map.fits" in r.summary["files"] and "map.fits" in r.summary["file_digests"]
    loaded = aw.load(tmp_path / "run")
    assert loaded.map_file == r.map_file and loaded == r
    assert aw.run(small_scene).map_file is None  # not written anywhere
    r.write(tmp_path / "again")
    assert r.map_file == str(tmp_path / "again" / "map.fits")
