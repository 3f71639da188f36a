#!/usr/bin/env bash
# Installs what arnoldweb needs (Debian packages, scripts/packages.txt) and
# builds it into build/. Safe to run again: installs only what is missing and
# rebuilds only what changed. The CUDA backend is built when the CUDA toolkit
# (nvcc, NVRTC) is found, e.g. under /usr/local/cuda.
set -euo pipefail
cd "$(dirname "$0")/.."

mapfile -t packages < <(grep -v '^\s*#' scripts/packages.txt | grep -v '^\s*$')
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "bootstrap: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y --no-install-recommends "${missing[@]}"
fi

cuda_args=()
if ! command -v nvcc >/dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  export PATH="/usr/local/cuda/bin:$PATH"
fi
if command -v nvcc >/dev/null 2>&1; then
  cuda_args+=("-DCUDAToolkit_ROOT=$(dirname "$(dirname "$(command -v nvcc)")")")
fi

# ccache, when installed: the Python package's build (scripts/test-python.sh,
# build-python/ at the same depth) then reuses these objects
launcher_args=()
if command -v ccache >/dev/null 2>&1; then
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
  launcher_args+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi

# The cpu kernels for the instruction sets this machine runs (ARNOLDWEB_CPU_ISAS=host:
# the baseline x86-64 and the best level here; cmake/ArnoldwebCpuKernels.cmake): a build
# that runs where it is built compiles no set it can neither run nor test, a third less
# of the kernels' compile time. Packages and wheels keep every set
# (CMake's default: x86-64, x86-64-v3 and x86-64-v4); ARNOLDWEB_CPU_ISAS in the environment
# chooses the sets here (a list, "host", or empty for one set, ARNOLDWEB_CPU_ARCH).
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "-DARNOLDWEB_CPU_ISAS=${ARNOLDWEB_CPU_ISAS-host}" \
  "${cuda_args[@]}" "${launcher_args[@]}" "$@"
# ARNOLDWEB_BUILD_TARGETS="a b": only those (the ones this configuration has), e.g.
# scripts/run-default.sh's program and pictures' plugin; else everything
targets=()
for t in ${ARNOLDWEB_BUILD_TARGETS:-}; do
  ninja -C build -t query "$t" >/dev/null 2>&1 && targets+=(--target "$t")
done
cmake --build build -j"$(nproc)" "${targets[@]}"
