"""The installed binary wheel (scripts/build-wheel.sh): it carries the libraries it links, needs
neither NVRTC nor MPI nor the CUDA driver to import and run, and its cpu kernels choose their
instruction set at run time (every set the CPU runs gives the same bits)."""
import json
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import arnoldweb as aw

PACKAGE = pathlib.Path(aw.__file__).resolve().parent
LIBS = PACKAGE.parent / "arnoldweb.libs"  # what auditwheel put in


def installed_from_wheel():
    if not LIBS.is_dir():
        pytest.skip(f"arnoldweb is not installed from the binary wheel here ({PACKAGE}): no {LIBS.name}/")


def needed(path):
    out = subprocess.run(["readelf", "-d", str(path)], capture_output=True, text=True, check=True).stdout
    return [line.split("[", 1)[1].rstrip("]") for line in out.splitlines() if "(NEEDED)" in line]


def test_the_wheel_needs_no_nvrtc_mpi_or_driver():
    installed_from_wheel()
    if not shutil.which("readelf"):
        pytest.skip("no readelf (binutils) to read the ELF files' needs")
    elfs = [p for p in list(PACKAGE.rglob("*.so")) + [PACKAGE / "bin" / "arnoldweb"] + list(LIBS.iterdir())]
    assert len(elfs) > 10
    for path in elfs:
        for lib in needed(path):
            assert not lib.startswith(("libnvrtc", "libcuda", "libcudart", "libmpi", "libopen-")), (path, lib)
    bundled = {p.name.split("-")[0] for p in LIBS.iterdir()}
    assert {"libhdf5", "libcfitsio", "libcairo", "libOpenCL", "libgomp"} <= bundled


# What Debian's HDF5 (libcurl for its ROS3 driver) and CFITSIO (libcurl-gnutls) dragged in:
# network and crypto libraries nobody asked for (scripts/wheel-deps.sh builds them without)
NETWORK_OR_CRYPTO = ("libcurl", "libssl", "libcrypto", "libgnutls", "libnettle", "libhogweed", "libgmp", "libkrb5",
                     "libk5crypto", "libgssapi", "libldap", "liblber", "libsasl2", "libssh", "librtmp", "libpsl",
                     "libnghttp2", "libidn2", "libp11-kit", "libtasn1", "libunistring", "libkeyutils")


def test_no_network_or_crypto_library_inside_and_none_grown():
    installed_from_wheel()
    names = sorted(p.name for p in LIBS.iterdir())
    assert not [n for n in names if n.startswith(NETWORK_OR_CRYPTO)], names
    # a bundled library is about its original's size (patchelf 0.18+ laid Debian's libXdmcp out by its
    # 2 MiB segment alignment: 22 KB became 6.3 MB); the originals are this build machine's
    for p in LIBS.iterdir():
        base = p.name.split("-")[0]
        originals = list(pathlib.Path("/usr/lib/x86_64-linux-gnu").glob(base + ".so.*"))
        originals = [o for o in originals if not o.is_symlink()]
        if originals:
            assert p.stat().st_size < 1.2 * max(o.stat().st_size for o in originals) + 65536, p.name


SCRIPT = """
import json, arnoldweb as aw
r = aw.run(aw.scene("default").set("ensemble.trajectories", 2000), device="cpu")
print(json.dumps({"devices": [d["id"] for d in aw.devices()], "problems": aw.backend_problems(),
                  "binned": r.binned, "map": r.digests["map"], "kernel": r.summary["kernel"]}))
"""


def test_imports_and_runs_without_nvrtc_or_mpi(tmp_path):
    env = dict(os.environ, ARNOLDWEB_NVRTC="/nonexistent/libnvrtc.so.13", LD_LIBRARY_PATH="",
               CUDA_HOME=str(tmp_path), CUDA_PATH=str(tmp_path), PATH="/usr/bin:/bin")
    done = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, cwd=tmp_path,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    out = json.loads(done.stdout)
    assert out["devices"][0] == "cpu" and out["binned"] == 2000
    assert any(p.startswith("cuda:") for p in out["problems"])  # CUDA absent, and said why


def cpu_runs(isa):
    flags = set()
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("flags"):
                flags = set(line.split(":", 1)[1].split())
                break
    v3 = {"avx", "avx2", "fma", "bmi1", "bmi2", "f16c", "movbe"}
    v4 = v3 | {"avx512f", "avx512bw", "avx512cd", "avx512dq", "avx512vl"}
    return {"x86-64": True, "x86-64-v3": v3 <= flags, "x86-64-v4": v4 <= flags}[isa]


def wheel_isas():
    """The instruction sets the wheel was built for, best first: every set by default;
    with ARNOLDWEB_CPU_ISAS (scripts/test-python.sh passes build/'s) that list, where
    "host" is the baseline and the best level this CPU runs (cmake/ArnoldwebCpuKernels.cmake)."""
    isas = os.environ.get("ARNOLDWEB_CPU_ISAS", "") or "x86-64;x86-64-v3;x86-64-v4"
    if isas == "host":
        best = [i for i in ("x86-64-v4", "x86-64-v3") if cpu_runs(i)][:1]
        isas = ";".join(["x86-64"] + best)
    return list(reversed(isas.split(";")))


def test_every_instruction_set_gives_the_same_bits(small_scene, monkeypatch):
    installed_from_wheel()
    small_scene = small_scene.set("observe.final_states", True)
    digests = {}
    compiled = wheel_isas()
    for isa in compiled:
        if not cpu_runs(isa):
            continue
        monkeypatch.setenv("ARNOLDWEB_CPU_ISA", isa)
        r = aw.run(small_scene)
        assert f"({isa}," in r.summary["kernel"]
        digests[isa] = (r.digests["map"], r.digests["final_states"])
    assert len(digests) >= 2, "this CPU runs fewer than two of the wheel's instruction sets"
    assert len(set(digests.values())) == 1, digests
    monkeypatch.setenv("ARNOLDWEB_CPU_ISA", "x86-64-v9")
    with pytest.raises(aw.DeviceError, match="compiled for " + ", ".join(compiled) + r"($|[^,])"):
        aw.run(small_scene)
