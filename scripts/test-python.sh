#!/usr/bin/env bash
# Tests of the Python package (docs/python.md), as a user installs it: a
# virtual environment (build-python/venv, kept between runs), `pip install .`
# into it, then pytest on tests/python. ctest runs it as the test `python`.
#
# The build tools (scikit-build-core, nanobind) and the test tools (pytest,
# numpy, h5py, matplotlib, tqdm, healpy) come from PyPI; the C++ dependencies are the
# Debian packages of scripts/packages.txt. The wheel is built in
# build-python/ (pyproject.toml), so a second run rebuilds only what changed;
# ccache is used when it is installed.
#
# Exit 77 (skipped, with the reason) when python3, its venv module or PyPI is
# not available here; with ARNOLDWEB_REQUIRE_CHECKS=1 (CI) that is a failure.
#
#   scripts/test-python.sh              everything
#   scripts/test-python.sh -k interrupt other pytest arguments
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

skip() {
  echo "test-python: SKIPPED: $*"
  if [ "${ARNOLDWEB_REQUIRE_CHECKS:-0}" = 1 ]; then
    echo "test-python: ARNOLDWEB_REQUIRE_CHECKS=1: a skipped check fails"
    exit 1
  fi
  exit 77
}

python=${PYTHON:-python3}
command -v "$python" >/dev/null 2>&1 || skip "no $python on PATH"
"$python" -c 'import venv, ensurepip' 2>/dev/null || skip "$python has no venv/ensurepip module (Debian: python3-venv)"

build_dir=build-python
venv="$build_dir/venv"
start=$SECONDS
if [ ! -x "$venv/bin/python" ]; then
  mkdir -p "$build_dir"
  "$python" -m venv "$venv" || skip "$python -m venv failed"
fi
pip=("$venv/bin/python" -m pip --disable-pip-version-check)
# Build tools installed in the environment and used without isolation: their
# paths stay the same between runs, so the build folder stays incremental.
if ! "${pip[@]}" install -q "scikit-build-core>=0.10" "nanobind>=2.0" pytest numpy h5py matplotlib tqdm healpy; then
  skip "pip could not install the build and test tools from PyPI (no network?)"
fi
echo "test-python: tools ready ($((SECONDS - start)) s)"

if command -v ccache >/dev/null 2>&1; then
  export CMAKE_C_COMPILER_LAUNCHER=ccache CMAKE_CXX_COMPILER_LAUNCHER=ccache
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR=1
fi
export CMAKE_BUILD_PARALLEL_LEVEL="${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}"
if ! command -v nvcc >/dev/null 2>&1 && [ -x /usr/local/cuda/bin/nvcc ]; then
  export PATH="/usr/local/cuda/bin:$PATH"  # as scripts/bootstrap.sh: the same configuration as build/
fi
log="$build_dir/pip-install.log"
build_start=$SECONDS
if ! "${pip[@]}" install --no-build-isolation -v . >"$log" 2>&1; then
  tail -n 60 "$log"
  echo "test-python: FAILED: pip install . (the whole log: $log)"
  exit 1
fi
echo "test-python: pip install . took $((SECONDS - build_start)) s (log: $log)"

# From outside the source tree, so that the installed package is the one imported.
cd "$root/tests/python"
export MPLBACKEND=Agg
status=0
"$root/$venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir "$root/tests/python" "$@" . || status=$?
echo "test-python: $((SECONDS - start)) s in all"
exit $status
