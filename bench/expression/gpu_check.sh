#!/usr/bin/env bash
# On the GPU machine (device tool, carry .device-deps, docs/gpu.md): build, the
# expression-model test suites, and the final-state digests of one expression
# scene on every device (PoCL, NVIDIA OpenCL, CUDA: the same bits expected)
# beside the built-in model's. Output in $OUT.
#   bash bench/expression/gpu_check.sh
set -uo pipefail
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT"
source .device-deps/device-setup.sh .device-deps >"$OUT/setup.txt" 2>&1
export PKG_CONFIG_PATH=/opt/device-deps/usr/lib/x86_64-linux-gnu/pkgconfig:${PKG_CONFIG_PATH:-}
export PATH=/usr/local/cuda/bin:$PATH
b=${BUILD:-/tmp/build-expr}
cmake -S . -B "$b" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUDAToolkit_ROOT=/usr/local/cuda \
  -DCMAKE_CUDA_ARCHITECTURES=90 >"$OUT/build.txt" 2>&1 || { tail -40 "$OUT/build.txt"; exit 1; }
cmake --build "$b" -j"$(nproc)" --target arnoldweb-cli arnoldweb_tests >>"$OUT/build.txt" 2>&1 ||
  { grep -E "error" -A4 "$OUT/build.txt" | head -60; exit 1; }
"$b/arnoldweb" devices
(cd "$b/tests" && ./arnoldweb_tests -ts=expression,expression-opencl,nvrtc,scene,models 2>&1 |
  grep -v "warnings generated" | tail -25)
set_common=(--quiet --set ensemble.trajectories=20000 --set run.average=5 --set run.duration=10
            --set observe.final_states=true --set observe.initial_states=true --set output.images=false)
paper=(--set 'model.kind="expression"' --set 'model.potential="cos(x)*cos(y)*(1 + cos(2*z))"')
mixed=(--set 'model.kind="expression"' --set 'model.potential="eps*exp(cos(x - y))*sqrt(2 + sin(z)) + cos(x)^3*cos(2*y + z)^2/(3 + cos(z))"' --set 'model.parameters={ eps = 0.5 }')
for dev in $("$b/arnoldweb" devices | awk 'NR > 1 && $1 ~ /^(opencl|cuda):/ {print $1}'); do
  for m in builtin paper mixed; do
    case $m in builtin) extra=();; paper) extra=("${paper[@]}");; mixed) extra=("${mixed[@]}");; esac
    "$b/arnoldweb" run scenes/default.toml --device "$dev" "${set_common[@]}" "${extra[@]}" --out "/tmp/x-$m-${dev/:/_}" &&
    python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); d=s["digests"]; print(sys.argv[2], sys.argv[3], "init", d["initial_states"][:16], "final", d["final_states"][:16], "map", d["map"][:16], "max|dE|", s["energy_error"].get("max"), "rate", s["trajectory_steps_per_second"])' "/tmp/x-$m-${dev/:/_}/summary.json" "$m" "$dev"
  done
done
