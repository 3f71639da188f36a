#!/usr/bin/env python3
"""Makes the seeds of the fuzz target of render/compare inputs (fuzz_saved_run.cpp):
small output directories written by the arnoldweb CLI, each as summary.json, a NUL byte and
map.h5, in tests/fuzz/corpus-saved/, and map.h5 files that lead out of themselves (an external
link, external storage, a virtual dataset, all naming the harness's FIFO fifo.h5) or declare
more than they store, written with h5py. Run it again when summary.json or map.h5 change, with
a Python that has h5py (Debian: python3-h5py):

    /usr/bin/python3 tests/fuzz/make_saved_corpus.py [build/arnoldweb]
"""
import io
import json
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
CLI = sys.argv[1] if len(sys.argv) > 1 else str(HERE.parents[1] / "build" / "arnoldweb")
SCENE = """[model]
energy = 15.0
[ensemble]
trajectories = 500
[integrator]
step = 0.02
[run]
average = 1.0
duration = 2.0
[observe]
velocity_map = { nside = 4 }
energy_error = false
[output]
images = false
"""
# name: --set overrides
RUNS = {
    "nside1": ["observe.velocity_map.nside=1"],
    "nside4": [],
    "nside8-zoom-frames": ["observe.velocity_map.nside=8", "observe.zoom.resolution=16",
                           "observe.frames.times=[0,1,2]"],
    "zoom-only": ["observe.velocity_map=false", "observe.zoom.resolution=16"],
    "cap-seed9": ["ensemble.initial=\"cap\"", "ensemble.seed=9"],
}


def seed(summary: dict, map_bytes) -> bytes:
    text = json.dumps(summary, indent=2).encode()
    return text if map_bytes is None else text + b"\0" + map_bytes


def hostile_maps(npix: int) -> dict:
    """map.h5 files that the HDF5 reader refuses (docs/reliability.md, "Reading HDF5 files")."""
    import h5py
    import numpy as np

    def external_link(f):
        f["map"] = h5py.ExternalLink("fifo.h5", "/map")

    def external_storage(f):
        f.create_dataset("map", shape=(npix,), dtype="u8", external=[("fifo.h5", 0, npix * 8)])

    def virtual(f):
        layout = h5py.VirtualLayout(shape=(npix,), dtype="u8")
        layout[:] = h5py.VirtualSource("fifo.h5", "/map", shape=(npix,))
        f.create_virtual_dataset("map", layout)

    def unwritten(f):
        f.create_dataset("map", shape=(npix,), dtype="u8", chunks=(64,))
        f["map"].attrs["nside"] = np.int64(round((npix / 12) ** 0.5))

    out = {}
    for write in (external_link, external_storage, virtual, unwritten):
        buf = io.BytesIO()
        with h5py.File(buf, "w") as f:
            write(f)
        out[write.__name__.replace("_", "-")] = buf.getvalue()
    return out


def main() -> None:
    out = HERE / "corpus-saved"
    out.mkdir(exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        scene = pathlib.Path(tmp) / "scene.toml"
        scene.write_text(SCENE)
        for name, sets in RUNS.items():
            d = pathlib.Path(tmp) / name
            args = [CLI, "run", str(scene), "--quiet", "--device", "cpu", "--out", str(d)]
            for s in sets:
                args += ["--set", s]
            subprocess.run(args, check=True)
            summary = json.loads((d / "summary.json").read_text())
            summary["scene_toml"] = summary["scene_toml"].replace(str(d), "out").replace(str(scene), "scene.toml")
            summary["scene"]["output"]["dir"] = "out"
            map_bytes = (d / "map.h5").read_bytes()
            (out / name).write_bytes(seed(summary, map_bytes))
            trusted = json.loads(json.dumps(summary))
            trusted["file_digests"]["map.h5"]["xxh3_128"] = "trust"  # mutated maps reach the HDF5 reader
            (out / (name + "-trust")).write_bytes(seed(trusted, map_bytes))
            older = {k: v for k, v in summary.items() if k != "file_digests"}  # before the digests
            (out / (name + "-older")).write_bytes(seed(older, map_bytes))
        (out / "summary-without-map").write_bytes(seed(summary, None))
        # map.h5 that leads out of itself, its digest trusted (so that it reaches the HDF5 reader)
        for name, map_bytes in hostile_maps(12 * summary["maps"]["nside"] ** 2).items():
            trusted = json.loads(json.dumps(summary))
            trusted["file_digests"]["map.h5"]["xxh3_128"] = "trust"
            (out / ("map-" + name + "-trust")).write_bytes(seed(trusted, map_bytes))


if __name__ == "__main__":
    main()
