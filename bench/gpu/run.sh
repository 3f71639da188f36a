#!/usr/bin/env bash
# The whole GPU-machine job in one call (device tool), from the repository root:
#   bash bench/gpu/run.sh [quick|full]
# Builds everything there, runs the whole test suite on every device (cpu,
# PoCL, NVIDIA OpenCL, CUDA), the four-backend parity check (portable math at
# full size: 10^5 trajectories x 10^4 steps; native-math drift), a short
# throughput benchmark per device, and prints one table last.
# Needs .device-deps/ (see docs/gpu.md): Debian packages the image lacks and
# ../shared/gpu/device-setup.sh. Results go to $OUT (default ./gpu-out).
set -uo pipefail
mode=${1:-full}
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT"
t0=$(date +%s)
stamp() { echo "[$(( $(date +%s) - t0 )) s] $*"; }

source .device-deps/device-setup.sh .device-deps >"$OUT/setup.txt" 2>&1
cat "$OUT/setup.txt"
export PKG_CONFIG_PATH=/opt/device-deps/usr/lib/x86_64-linux-gnu/pkgconfig:${PKG_CONFIG_PATH:-}
export PATH=/usr/local/cuda/bin:$PATH

stamp "configure"
if ! cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release \
     -DCUDAToolkit_ROOT=/usr/local/cuda -DCMAKE_CUDA_ARCHITECTURES=90 >"$OUT/build.txt" 2>&1; then
  tail -40 "$OUT/build.txt"; exit 1
fi
stamp "build"
if ! cmake --build build-gpu -j"$(nproc)" >>"$OUT/build.txt" 2>&1; then
  grep -E "error|Error" -A4 "$OUT/build.txt" | head -60; exit 1
fi
build-gpu/arnoldweb devices | tee "$OUT/devices.txt"

stamp "tests"
ctest --test-dir build-gpu --output-on-failure -j4 --timeout 900 >"$OUT/ctest.txt" 2>&1
ctest_rc=$?
grep -E "Test +#|tests passed|tests failed" "$OUT/ctest.txt"

stamp "parity (portable, full size)"
if [ "$mode" = quick ]; then n=20000; s=2000; else n=100000; s=10000; fi
build-gpu/arnoldweb_parity --trajectories $n --steps $s --csv "$OUT/parity.csv" >"$OUT/parity.md" 2>&1
parity_rc=$?
cat "$OUT/parity.md"
stamp "native-math drift"
build-gpu/arnoldweb_parity --trajectories 20000 --steps $s --native >"$OUT/parity_native.md" 2>&1
grep native "$OUT/parity_native.md"

stamp "throughput (default scene, E = 15, yoshida6a)"
echo "device,precision,trajectories,seconds,trajectory_steps_per_s" >"$OUT/throughput.csv"
for id in $(build-gpu/arnoldweb devices --json | python3 -c 'import json,sys; print(" ".join(d["id"] for d in json.load(sys.stdin)))'); do
  for prec in double float; do
    case $id in cuda*|opencl*) n=20000000 ;; *) n=1000000 ;; esac
    if build-gpu/arnoldweb devices --json | python3 -c "import json,sys; d=[d for d in json.load(sys.stdin) if d['id']=='$id'][0]; sys.exit(0 if d['cpu'] else 1)"; then n=1000000; fi
    rm -rf "/tmp/aw-tp"
    build-gpu/arnoldweb run scenes/default.toml --quiet --device "$id" --out /tmp/aw-tp \
      --set ensemble.trajectories=$n --set integrator.precision=$prec --set output.images=false >/dev/null 2>"$OUT/run_err.txt"
    python3 - "$id" "$prec" "$n" >>"$OUT/throughput.csv" <<'PY'
import json, sys
s = json.load(open('/tmp/aw-tp/summary.json'))
print(f"{sys.argv[1]},{sys.argv[2]},{sys.argv[3]},{s['wall_seconds']:.3f},{s['trajectory_steps_per_second']:.4g}")
PY
  done
done
column -t -s, "$OUT/throughput.csv"

stamp "summary"
echo "ctest rc=$ctest_rc  parity rc=$parity_rc"
grep -E "tests passed|tests failed" "$OUT/ctest.txt"
tail -1 "$OUT/parity.md"
