#!/usr/bin/env bash
# Issue 28, "verify where nothing was built": the binary wheel built on the
# Debian machine (scripts/build-wheel.sh; bench/gpu/prepare-wheel.sh puts it
# and a numpy wheel into .device-deps/wheels), installed on the GPU machine
# (Ubuntu 24.04) into a fresh virtual environment with nothing else, timed;
# then a scene from Python on every CUDA device, NVIDIA OpenCL device and the
# cpu, each next to the CLI of the same wheel (same scene, same device): the
# map and state digests must agree everywhere (portable math: the same bits
# on every backend); one orbit per device (the same bits) and a HEALPix FITS map read back
# (issue 38). Needs no build and no network there.
#
#   bash bench/gpu/run.sh wheel          (the device tool, carry .device-deps)
#   bash bench/gpu/wheel.sh [WHEEL_DIR]  (directly; default .device-deps/wheels)
set -uo pipefail
dir=${1:-.device-deps/wheels}
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT"
python=${PYTHON:-python3}
echo "machine: $(. /etc/os-release && echo "$PRETTY_NAME"), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2), $(nproc) cores"
echo "python: $("$python" -c 'import sys; print(sys.version.split()[0], sys.executable)')"
ls "$dir"/arnoldweb-*.whl >/dev/null 2>&1 || { echo "wheel: no arnoldweb wheels in $dir (bench/gpu/prepare-wheel.sh)"; exit 1; }
# NVIDIA's OpenCL driver, registered with the ICD loader (the image ships only PoCL's)
if [ ! -f /etc/OpenCL/vendors/nvidia.icd ] && ldconfig -p | grep -q libnvidia-opencl.so.1; then
  mkdir -p /etc/OpenCL/vendors && echo libnvidia-opencl.so.1 > /etc/OpenCL/vendors/nvidia.icd \
    || echo "wheel: could not register NVIDIA's OpenCL driver"
fi

# what the wheel takes from the system (the manylinux policy's libraries; the rest is inside)
echo "system libraries the wheel uses: $(ldconfig -p | grep -oE '(libX11\.so\.6|libXext\.so\.6|libXrender\.so\.1|libexpat\.so\.1|libz\.so\.1|libstdc\+\+\.so\.6) ' | sort -u | tr -d '\n')"
venv=$(mktemp -d /tmp/aw-wheel-venv.XXXXXX)
"$python" -m venv "$venv"
t0=$(date +%s.%N)
# pip picks the wheel of this Python from the wheelhouse (3.12: cp312-abi3)
"$venv/bin/python" -m pip --disable-pip-version-check install -q --no-index --find-links "$dir" arnoldweb
rc=$?
t1=$(date +%s.%N)
install_s=$(python3 -c "print(f'{$t1 - $t0:.1f}')")
picked=$("$venv/bin/python" -c 'import importlib.metadata as m; print([l for l in [f for f in m.files("arnoldweb") if f.name == "WHEEL"][0].read_text().splitlines() if l.startswith("Tag")][0])' 2>/dev/null)
echo "install: pip install --no-index --find-links $dir arnoldweb (and numpy) into a fresh venv: ${install_s} s (exit $rc), $picked"
[ $rc = 0 ] || exit 1
"$venv/bin/python" -m pip list 2>/dev/null | grep -Ei "^(arnoldweb|numpy) "

cd "$OUT" && "$venv/bin/python" - <<'PY'
import json, os, subprocess, tempfile, time
import arnoldweb as aw
from arnoldweb import _cli

print("devices:", [f'{d["id"]} {d["name"]}' for d in aw.devices()])
for p in aw.backend_problems():
    print("problem:", p)
n = int(os.environ.get("AW_WHEEL_N", "200000"))
scene = aw.scene("default").set("ensemble.trajectories", n).set("observe.final_states", True)
scene_file = os.path.join(os.path.dirname(aw.__file__), "scenes", "default.toml")
wanted = [d for d in aw.devices() if d["backend"] == "cuda" or (d["backend"] == "opencl" and "NVIDIA" in d["vendor"])]
wanted += [d for d in aw.devices() if d["id"] == "cpu"]
rows, work = [], tempfile.mkdtemp()
for d in wanted:
    t = time.time()
    r = aw.run(scene, device=d["id"])
    py_s = time.time() - t
    out = os.path.join(work, d["id"].replace(":", "_"))
    cli = subprocess.run([_cli.executable(), "run", scene_file, "--quiet", "--device", d["id"], "--out", out,
                          "--set", f"ensemble.trajectories={n}", "--set", "observe.final_states=true",
                          "--set", "output.images=false"], capture_output=True, text=True)
    if cli.returncode != 0:
        print(d["id"], "CLI failed:", cli.stderr[-2000:])
        continue
    s = json.load(open(os.path.join(out, "summary.json")))
    rows.append((d["id"], d["name"], r.digests["map"], s["digests"]["map"], r.digests["final_states"],
                 s["digests"]["final_states"], py_s, s["wall_seconds"], r.binned))
print(f"\nscene: default.toml, {n} trajectories, portable math, final states; python vs the wheel's CLI")
print(f"{'device':10} {'python map digest':34} {'CLI map digest':34} {'states equal':12} {'py s':>6} {'cli s':>6} binned")
for dev, name, pm, cm, ps, cs, pt, ct, b in rows:
    print(f"{dev:10} {pm:34} {cm:34} {str(ps == cs):12} {pt:6.2f} {ct:6.2f} {b}")
maps = {r[2] for r in rows} | {r[3] for r in rows}
states = {r[4] for r in rows} | {r[5] for r in rows}
print("all digests identical (python, CLI, every device):", len(maps) == 1 and len(states) == 1)

# pictures: drawn by the plugin where cairo's libraries are on the machine; else the run
# says why it drew none (a PlanWarning from Python, a warning line from the CLI)
import warnings
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    aw.run(aw.scene("default").set("ensemble.trajectories", 2000), device="cpu", out=os.path.join(work, "pictures"))
drawn = sorted(f for f in os.listdir(os.path.join(work, "pictures")) if f.endswith(".png"))
print("pictures drawn:", drawn or "none")
for w in caught:
    print("warning:", w.category.__name__, str(w.message))

# issue 38 on the GPU machine: one orbit on each device (the same bits as the cpu's) and a
# HEALPix FITS map from the wheel (its own CFITSIO), its header read back
import numpy as np
orbits = {}
for d in wanted:
    o = aw.orbit(aw.scene("default").set("ensemble.trajectories", 20000).set("run.duration", 50), id=1234,
                 every=5, device=d["id"])
    orbits[d["id"]] = o
    print(f"orbit 1234 on {d['id']}: {len(o.t)} samples, max|dE| {np.max(np.abs(o.dE)):.3e}")
ref = orbits.get("cpu")
if ref is not None:
    same = all(np.array_equal(o.X, ref.X) and np.array_equal(o.P, ref.P) and np.array_equal(o.dE, ref.dE)
               for o in orbits.values())
    print("orbits identical on every device:", same)
r = aw.run(aw.scene("default").set("ensemble.trajectories", 20000).set("output.formats", ["hdf5", "fits"]),
           device=wanted[0]["id"], out=os.path.join(work, "fits"))
with open(r.map_file, "rb") as f:
    cards = f.read(2880 * 4).decode("ascii", "replace")
keys = {c[:8].strip(): c[10:30].strip() for c in (cards[i:i + 80] for i in range(0, len(cards), 80)) if c[8:10] == "= "}
print("fits:", os.path.basename(r.map_file), {k: keys.get(k) for k in ("PIXTYPE", "ORDERING", "NSIDE", "INDXSCHM")})
PY
