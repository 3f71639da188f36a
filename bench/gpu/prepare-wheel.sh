#!/usr/bin/env bash
# Here (the Debian machine), before `bash bench/gpu/run.sh wheel` on the GPU
# machine: builds the stable-ABI wheel cp312-abi3 that the GPU machine's Python
# 3.12 takes (scripts/build-wheel.sh with pyenv's 3.12 or $PYTHON312) and
# downloads a numpy wheel for 3.12 (the GPU machine reaches no package index),
# into .device-deps/wheels/ (carried by the device tool: carry [".device-deps"]).
set -euo pipefail
cd "$(dirname "$0")/../.."
dest=.device-deps/wheels
mkdir -p "$dest"
py312=""
for p in ${PYTHON312:-} "$HOME"/.pyenv/versions/3.12*/bin/python python3.12; do
  if "$p" -c 'import sys; assert sys.version_info[:2] == (3, 12)' 2>/dev/null; then py312=$p; break; fi
done
[ -n "$py312" ] || { echo "prepare-wheel: no Python 3.12 (set PYTHON312)" >&2; exit 2; }
rm -f "$dest"/arnoldweb-*.whl
WHEEL_DIR="$PWD/$dest" PYTHONS="$py312" scripts/build-wheel.sh | sed -n '/^build-wheel: arnoldweb-/p'
ls "$dest"/arnoldweb-*-cp312-abi3-*.whl >/dev/null || { echo "prepare-wheel: no cp312-abi3 wheel was built" >&2; exit 1; }
python3 -m pip download -q --only-binary=:all: --python-version 3.12 --platform manylinux_2_28_x86_64 \
  --platform manylinux2014_x86_64 --platform manylinux_2_17_x86_64 -d "$dest" numpy
ls -la "$dest"
