#!/usr/bin/env bash
# The whole GPU-machine job in one call (device tool), from the repository root:
#   bash bench/gpu/run.sh [quick|full|verify|bench]
# verify: build, the whole test suite (long hard cases included), the
# four-backend parity at full size and the native-math drift; no benchmark.
# bench: only the build and the benchmark section (issue 7, docs/performance.md):
# arnoldweb_bench on every GPU at N up to 8.4e6 x 2000 steps with the naive
# CUDA baseline, GPU memory of a 1e9 map run, ncu FP64-pipe metrics of our
# kernel and the naive kernel, the Figure-3 scene end to end (1e8 x 5000
# steps), every CPU device with the naive OpenMP baseline, the cost of
# effects. $OUT keeps at most 8 files: summary.txt, bench.csv,
# bench_throughput.png, ncu.csv and results.tgz (every log and file).
# Builds everything there, runs the whole test suite on every device (cpu,
# PoCL, NVIDIA OpenCL, CUDA), the four-backend parity check (portable math at
# full size: 10^5 trajectories x 10^4 steps; native-math drift), a short
# throughput benchmark per device, and prints one table last.
# recheck: build, the GPU-relevant suites (parity, order and expressions on
# CUDA and NVIDIA OpenCL, models, indicators, outputs, reliability, checkpoints),
# the quick parity check and the small-N rate (bench/gpu/small_n.sh); no benchmark.
# accuracy: build the program, then bench/gpu/accuracy_fig3.sh on the first CUDA device: the
# cheapest method and step for Figure 3 at max|dE| <= 1e-8 and what integrator.step = "auto"
# chooses, each timed on the whole 1e8 (issue 16 target 5, issue 18; docs/accuracy.md).
# float: build the program, then bench/gpu/float_map.sh on the first CUDA device: Figure 3 in double
# and in float, timed, and the maps compared by the chi-square test (issue 16 target 6).
# wheel: no build: the binary wheel built on the Debian machine
# (bench/gpu/prepare-wheel.sh) installed into a fresh venv, timed, and a scene
# from Python on CUDA, NVIDIA OpenCL and cpu next to the wheel's CLI
# (bench/gpu/wheel.sh; issue 28).
# fgl: build the program, then bench/gpu/fgl_rate.sh on the first CUDA device: the fgl rates that
# size issue 26's frequency map and D(eps) scan (docs/frequencies.md).
# science: build the program and the tests, the GPU suites of issues 25 and 26 (parity, open runs,
# frequencies on CUDA and NVIDIA OpenCL), then bench/gpu/science.sh on the first CUDA device: the
# cost of observe.frequencies, the FGL frequency map beside its FLI map, the D(eps) scan, a sliced
# Figure-4 run killed with kill -9 and resumed (docs/frequencies.md, docs/gallery.md, docs/cluster.md).
# multi: build the program, then bench/gpu/multi_gpu.sh: Figure 3 panel (a) on one GPU and on every
# CUDA device driven by one process (--device cuda:0,cuda:1, then --device all), timed as whole
# processes, with the ratio and the digests (issue 25 item 4; docs/cluster.md). Run it on nvidia-h200-x2.
# rates: build the program, then bench/gpu/rates.sh on the first CUDA device: Figure 3 panel (a)
# (1e8 x 5000 steps, Yoshida-6A, double; trajectory-steps/s) and Figure 4's schedule at N = 32,768,
# the GPU rows of issue 29, each kernel variant of AW_RATES_VARIANTS (name=NVRTC options, ';'
# between; default: the default kernel only) in turn, AW_RATES_REPEAT rounds (default 2), each
# Figure-3 run's map digest and at the end whether they are all the first variant's.
# build: only the program (build-gpu/arnoldweb) and the device list; bench/gpu/campaign.sh builds with it.
# parity: build the program and the tests, the GPU parity suites (AW_PARITY_TESTS, a ctest regex;
# default: parity, open runs, frequency runs and order on CUDA and NVIDIA OpenCL), then the
# explorer's click-to-map time of a zoom of AW_ZOOM (default 10^6) trajectories on the first CUDA
# device, over HTTP without a browser (bench/explorer/viewer.py --no-browser; docs/viewer.md).
# Needs .device-deps/ (see docs/gpu.md): Debian packages the image lacks and
# ../shared/gpu/device-setup.sh. Results go to $OUT (default ./gpu-out).
set -uo pipefail
mode=${1:-full}
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT"
exec > >(tee "$OUT/summary.txt") 2>&1  # the whole log comes back as summary.txt
t0=$(date +%s)
stamp() { echo "[$(( $(date +%s) - t0 )) s] $*"; }
if [ "$mode" = wheel ]; then  # needs nothing of device-setup: the wheel carries its libraries
  OUT="$OUT" bash bench/gpu/wheel.sh .device-deps/wheels
  exit $?
fi

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
targets=""
[ "$mode" = bench ] && targets="--target arnoldweb-cli arnoldweb_bench"
[ "$mode" = accuracy ] || [ "$mode" = float ] || [ "$mode" = fgl ] || [ "$mode" = multi ] || [ "$mode" = rates ] ||
  [ "$mode" = build ] &&
  targets="--target arnoldweb-cli"
{ [ "$mode" = science ] || [ "$mode" = parity ]; } && targets="--target arnoldweb-cli arnoldweb_tests"
if ! cmake --build build-gpu -j"$(nproc)" $targets >>"$OUT/build.txt" 2>&1; then
  grep -E "error|Error" -A4 "$OUT/build.txt" | head -60; exit 1
fi
build-gpu/arnoldweb devices | tee "$OUT/devices.txt"
if [ "$mode" = build ]; then stamp "built"; exit 0; fi
first_cuda() {  # the id of the first CUDA device
  build-gpu/arnoldweb devices --json | python3 -c "import json,sys; print(next(d['id'] for d in json.load(sys.stdin) if d['id'].startswith('cuda')))"
}

ctest_rc=-; parity_rc=-
gpu_suites() {  # TIMEOUT REGEX: the ctest suites REGEX of build-gpu, the log in $OUT/ctest.txt, its rc
  (cd build-gpu && ctest --output-on-failure --timeout "$1" -R "$2") >"$OUT/ctest.txt" 2>&1
  local rc=$?
  grep -E "tests passed|Passed|Failed|\*\*\*" "$OUT/ctest.txt"
  return $rc
}
if [ "$mode" = accuracy ]; then
  stamp "accuracy for less: Figure 3 at max|dE| <= ${AW_ACC_TARGETS:-1e-8}"
  CUDA0=$(first_cuda)
  nproc; grep -m1 "model name" /proc/cpuinfo
  timeout 560 bash bench/gpu/accuracy_fig3.sh build-gpu/arnoldweb "$CUDA0" "$OUT/accuracy" "${AW_ACC_TARGETS:-1e-8}" ${AW_ACC_METHODS:-}
  stamp "done"
  (cd "$OUT" && tar czf /tmp/results.tgz --exclude=results.tgz . && mv /tmp/results.tgz results.tgz && rm -rf accuracy)
  exit 0
fi
if [ "$mode" = float ]; then
  stamp "float where it is enough: Figure 3 in double and float, maps compared"
  CUDA0=$(first_cuda)
  timeout 500 bash bench/gpu/float_map.sh build-gpu/arnoldweb "$CUDA0" /tmp/aw-float "${AW_FLOAT_N:-100000000}"
  stamp "done"
  exit 0
fi
if [ "$mode" = fgl ]; then
  stamp "fgl rates (issue 26 sizing)"
  CUDA0=$(first_cuda)
  timeout 560 bash bench/gpu/fgl_rate.sh build-gpu/arnoldweb "$CUDA0" | tee "$OUT/fgl_rate.txt"
  stamp "done"
  exit 0
fi
if [ "$mode" = science ]; then
  CUDA0=$(first_cuda)
  nproc; grep -m1 "model name" /proc/cpuinfo; nvidia-smi --query-gpu=name,driver_version --format=csv,noheader
  stamp "issue 25 and 26 measurements (bench/gpu/science.sh) on $CUDA0"
  timeout "${AW_SCIENCE_TIMEOUT:-330}" bash bench/gpu/science.sh build-gpu/arnoldweb "$CUDA0" "$OUT/science"
  (cd "$OUT" && tar czf science.tgz science && rm -rf science)
  if [ -f bench/gpu/rates.sh ] && [ -n "${AW_SCIENCE_RATES:-}" ]; then
    stamp "issue 29's GPU rows (bench/gpu/rates.sh, one round)"
    timeout 120 bash bench/gpu/rates.sh build-gpu/arnoldweb "$CUDA0" /tmp/aw-rates 1 | tee "$OUT/rates.txt"
  fi
  stamp "GPU suites of issues 25 and 26 (open runs, frequencies) and the parity suites"
  gpu_suites 200 "${AW_SCIENCE_TESTS:-^(parity\.cuda|parity\.opencl|open-runs\.cuda|open-runs\.opencl|frequency-runs\.cuda|frequency-runs\.opencl|order\.cuda|trajectories\.cuda)$}"
  stamp "done"
  exit 0
fi
if [ "$mode" = parity ]; then
  CUDA0=$(first_cuda)
  stamp "GPU parity suites"
  gpu_suites 300 "${AW_PARITY_TESTS:-^(parity\.cuda|parity\.opencl|open-runs\.cuda|frequency-runs\.cuda|frequency-runs\.opencl|order\.cuda|trajectories\.cuda|trajectories\.opencl)$}"
  ctest_rc=$?
  stamp "explorer: a zoom of ${AW_ZOOM:-1000000} trajectories on $CUDA0, request to map bytes"
  timeout 200 python3 bench/explorer/viewer.py --cli build-gpu/arnoldweb --no-browser --device "$CUDA0" \
    --zoom "${AW_ZOOM:-1000000}" --work /tmp/aw-viewer-bench 2>&1 | tail -3 | tee "$OUT/explorer.txt"
  stamp "done (ctest rc=$ctest_rc)"
  exit "$ctest_rc"
fi
if [ "$mode" = rates ]; then
  stamp "issue 29's GPU rows: Figure 3 (a) and Figure 4's schedule at N = 32,768 (variants: ${AW_RATES_VARIANTS:-default=})"
  CUDA0=$(first_cuda)
  nproc; grep -m1 "model name" /proc/cpuinfo; nvidia-smi --query-gpu=name,driver_version,clocks.max.sm --format=csv,noheader
  timeout 560 bash bench/gpu/rates.sh build-gpu/arnoldweb "$CUDA0" /tmp/aw-rates "${AW_RATES_REPEAT:-2}" | tee "$OUT/rates.txt"
  stamp "done"
  exit 0
fi
if [ "$mode" = multi ]; then
  stamp "every GPU in one process: Figure 3 (a), one GPU against ${AW_MULTI_DEVICES:-every CUDA device}"
  nproc; grep -m1 "model name" /proc/cpuinfo
  timeout 300 bash bench/gpu/multi_gpu.sh build-gpu/arnoldweb /tmp/aw-multi "${AW_MULTI_DEVICES:-}" "${AW_MULTI_N:-}"
  echo "multi rc=$?"
  stamp "done"
  exit 0
fi
if [ "$mode" != bench ]; then
stamp "tests"
export ARNOLDWEB_LONG_TESTS=1   # the long hard cases run here, not in CI
ctest_sel=(-E "^python$")
[ "$mode" = recheck ] && ctest_sel=(-R "^(parity\.cuda|parity\.opencl|order\.cuda|expression\.opencl|nvrtc|models|indicators|output|reliability|checkpoint|scale)$")
ctest --test-dir build-gpu --output-on-failure -j4 --timeout 900 "${ctest_sel[@]}" >"$OUT/ctest.txt" 2>&1  # python: PyPI is out of reach there
ctest_rc=$?
grep -E "Test +#|tests passed|tests failed" "$OUT/ctest.txt"

stamp "parity (portable, full size)"
if [ "$mode" = quick ] || [ "$mode" = recheck ]; then n=20000; s=2000; else n=100000; s=10000; fi
build-gpu/arnoldweb_parity --trajectories $n --steps $s --csv "$OUT/parity.csv" >"$OUT/parity.md" 2>&1
parity_rc=$?
cat "$OUT/parity.md"
stamp "native-math drift"
build-gpu/arnoldweb_parity --trajectories 20000 --steps $s --native >"$OUT/parity_native.md" 2>&1
grep native "$OUT/parity_native.md"

if [ "$mode" != verify ] && [ "$mode" != recheck ]; then
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
cat "$OUT/throughput.csv"
fi

fi
if [ "$mode" = recheck ]; then
  stamp "small N, long time: Figure 4's schedule at 3.2e4, 1.3e5 and 1e6 trajectories, 1000 T"
  GPU_IDS=$(build-gpu/arnoldweb devices --json | python3 -c "import json,sys; print(' '.join(d['id'] for d in json.load(sys.stdin) if not d['cpu']))")
  timeout 240 bash bench/gpu/small_n.sh build-gpu/arnoldweb 1000 $GPU_IDS
  timeout 120 bash bench/gpu/small_n.sh build-gpu/arnoldweb 20 cpu
fi
if [ "$mode" != verify ] && [ "$mode" != recheck ]; then

# ---------------------------------------------------------------- benchmark (issue 7)
# Every step has its own time limit so that the whole call stays well inside
# the device tool's 10 minutes; results of finished steps are kept.
BW=/tmp/aw-bench
DEADLINE=${AW_BENCH_DEADLINE:-540}  # seconds since the start of the script
left() {  # timeout for the next step: at most $1, never past the deadline
  local l=$(( DEADLINE - ($(date +%s) - t0) )); [ "$l" -gt "$1" ] && l=$1; [ "$l" -lt 5 ] && l=5; echo "$l"; }
rm -rf "$BW"; mkdir -p "$BW"
B=build-gpu/arnoldweb_bench
ids_where() {  # ids of devices with cpu == $1
  build-gpu/arnoldweb devices --json | python3 -c "import json,sys; print(','.join(d['id'] for d in json.load(sys.stdin) if d['cpu'] == ($1 == 1)))"
}
GPUS=$(ids_where 0); CPUS=$(ids_where 1)
CUDA0=$(echo "$GPUS" | tr , '\n' | grep '^cuda' | head -1)
echo "GPU devices: $GPUS   CPU devices: $CPUS"
if [ -n "$GPUS" ]; then
  stamp "bench: GPUs, N up to 8.4e6 x 2000 steps, naive CUDA baseline, memory of a 1e9 map run"
  timeout $(left 160) $B --devices "$GPUS" --preset gpu --sizes 65536,262144,1048576,4194304,8388608 --repeat 3 --memory 1e9 --no-plot --out "$BW/gpu" 2>&1 | tee "$BW/gpu.log" | grep -vE "^\|---|^\| device"
fi
if [ -n "$CUDA0" ]; then
  stamp "occupancy sweep: AW_CUDA_MIN_BLOCKS (launch bounds) 4, 6, 8 on $CUDA0 (N = 4194304, 2000 steps)"
  for mb in 4 6 8; do
    ARNOLDWEB_NVRTC_OPTIONS="-DAW_CUDA_MIN_BLOCKS=$mb" timeout $(left 40) $B --devices "$CUDA0" --sizes 4194304 \
      --steps 2000 --precision double,float --variants default --no-baselines --repeat 3 --no-plot \
      --out "$BW/minblocks$mb" 2>&1 | grep -E "^\| cuda" | sort -u | sed "s/^/min_blocks=$mb /"
  done
fi
OCL0=$(echo "$GPUS" | tr , '\n' | grep '^opencl' | head -1)
if [ -n "$OCL0" ]; then
  stamp "trajectories per work-item (ARNOLDWEB_OPENCL_LANES) 1, 2, 4 on $OCL0 (N = 4194304, 2000 steps)"
  for ln in 1 2 4; do
    ARNOLDWEB_OPENCL_LANES=$ln timeout $(left 40) $B --devices "$OCL0" --sizes 4194304 --steps 2000 \
      --precision double,float --variants default --no-baselines --repeat 3 --no-plot \
      --out "$BW/lanes$ln" 2>&1 | grep -E "^\| opencl" | sort -u | sed "s/^/lanes=$ln /"
  done
fi
if [ -n "$CUDA0" ] && command -v ncu >/dev/null; then
  stamp "ncu: FP64 pipe of aw_ensemble and the naive kernel (N = 2^20, 200 steps, double)"
  NCU_METRICS=sm__inst_executed_pipe_fp64.avg.pct_of_peak_sustained_active,sm__inst_executed_pipe_fp64.sum,sm__sass_thread_inst_executed_op_dfma_pred_on.sum,sm__sass_thread_inst_executed_op_dadd_pred_on.sum,sm__sass_thread_inst_executed_op_dmul_pred_on.sum,smsp__inst_executed.sum,sm__warps_active.avg.pct_of_peak_sustained_active,launch__registers_per_thread,launch__grid_size,launch__block_size,gpu__time_duration.sum
  # the command to read the achieved fraction of FP64 peak (also printed for reuse)
  NCU="ncu --clock-control none -k regex:aw_ensemble|aw_naive --metrics $NCU_METRICS --csv --page raw"
  echo "$NCU $B --devices $CUDA0 --sizes 1048576 --steps 200 --precision double --variants default --repeat 1"
  timeout $(left 90) $NCU $B --devices "$CUDA0" --sizes 1048576 --steps 200 --precision double --variants default \
    --repeat 1 --no-plot --out "$BW/ncu-run" >"$BW/ncu.csv" 2>"$BW/ncu.err"
  echo "ncu rc=$? ($(grep -c aw_ "$BW/ncu.csv") kernel rows)"; tail -3 "$BW/ncu.err"
  timeout $(left 45) ncu --clock-control none -k regex:aw_ensemble --metrics sm__pipe_fp64_cycles_active.avg.pct_of_peak_sustained_active,smsp__issue_active.avg.pct_of_peak_sustained_active,smsp__average_warps_issue_stalled_wait_per_issue_active.ratio,smsp__average_warps_issue_stalled_math_pipe_throttle_per_issue_active.ratio --csv --page raw \
    $B --devices "$CUDA0" --sizes 1048576 --steps 200 --precision double --variants default --repeat 1 --no-baselines \
    --no-plot --out "$BW/ncu-run2" >"$BW/ncu2.csv" 2>>"$BW/ncu.err" || echo "ncu (extra metrics) failed"
fi
if [ -n "$CUDA0" ]; then
  stamp "Figure 3 end to end: E = 15, 1e8 trajectories, 50 T at 0.01 T (5000 steps)"
  if [ -f scenes/fig3_e15.toml ]; then FIG3="--scene scenes/fig3_e15.toml"; else
    FIG3="--scene scenes/default.toml --scene-set ensemble.trajectories=100000000 --scene-set integrator.step=0.01 --scene-set run.average=50 --scene-set run.duration=50"; fi
  timeout $(left 80) $B --devices "$CUDA0" --no-figure --no-baselines $FIG3 --out "$BW/fig3" 2>&1 | tee "$BW/fig3.log" | grep scene
fi
if [ -n "$CPUS" ]; then
  stamp "bench: CPU devices (cpu backend, PoCL) with the naive OpenMP baseline"
  timeout $(left 100) $B --devices "$CPUS" --preset gpu --repeat 2 --no-plot --out "$BW/cpu" 2>&1 | tee "$BW/cpu.log" | grep -vE "^\|---|^\| device"
fi
stamp "bench: cost of effects (every device)"
EFF_DEVS=$(echo "$GPUS,cpu" | sed 's/^,//')
timeout $(left 130) $B --devices "$EFF_DEVS" --no-figure --effects --preset gpu --effects-size 2097152 --repeat 1 --no-plot --out "$BW/effects" \
  >"$BW/effects.log" 2>&1; echo "effects rc=$?"
sed -n '/Cost of effects/,$p' "$BW/effects.log" | grep -vE "^\|---"

if [ -n "$CUDA0" ]; then
  stamp "models: throughput of each model on $CUDA0 (4.2e6 trajectories x 2000 steps, double; docs/models.md)"
  OCL_GPU=$(echo "$GPUS" | tr , '\n' | grep '^opencl' | head -1)
  for spec in "seibert2011|" "fgl|--set model.kind=fgl --set model.epsilon=0.01 --set model.energy=1 --set integrator.step=0.002" \
              "fourier|--set model.kind=fourier --set model.harmonics=[[1,1,0,0.5,0],[1,-1,0,0.5,0],[1,1,2,0.25,0],[1,1,-2,0.25,0],[1,-1,2,0.25,0],[1,-1,-2,0.25,0]]" \
              "expression|--set model.kind=expression --set model.potential=cos(x)*cos(y)*(1+cos(2*z))"; do
    IFS='|' read -r name extra <<<"$spec"
    for dev in $CUDA0 $OCL_GPU; do
      rm -rf /tmp/aw-model
      # shellcheck disable=SC2086
      timeout $(left 40) build-gpu/arnoldweb run scenes/default.toml --quiet --device "$dev" --out /tmp/aw-model \
        --set ensemble.trajectories=4194304 --set run.average=20 --set run.duration=20 --set output.images=false $extra \
        >/dev/null 2>"$BW/model_err.txt" &&
        python3 -c "import json; s=json.load(open('/tmp/aw-model/summary.json')); print(f'  model {\"$name\":11s} $dev: {s[\"trajectory_steps_per_second\"]:.3e} traj-steps/s, {s[\"wall_seconds\"]:.2f} s')" ||
        { echo "  model $name $dev: failed"; tail -3 "$BW/model_err.txt"; }
    done
  done
  if [ -x bench/indicators/cost.sh ] || [ -f bench/indicators/cost.sh ]; then
    stamp "indicators: cost of FLI against the velocity map (HEALPix nside 512 = 3.1e6 trajectories, 100 T)"
    timeout $(left 90) bash bench/indicators/cost.sh build-gpu/arnoldweb 512 100 "$CUDA0" $OCL_GPU 2>&1 | tee "$BW/indicators.log"
    stamp "indicators: a 1024 x 1024 FLI map at 10^4 steps on $CUDA0 (fgl, eps = 0.01, plane grid of actions)"
    rm -rf /tmp/aw-fli
    timeout $(left 60) build-gpu/arnoldweb run scenes/fli_e15.toml --quiet --device "$CUDA0" --out /tmp/aw-fli \
      --set model.kind=fgl --set model.epsilon=0.01 --set model.energy=1 --set ensemble.initial=grid \
      --set ensemble.grid.kind=plane --set "ensemble.grid.resolution=[1024,1024]" --set "ensemble.grid.range1=[-0.5,1.5]" \
      --set "ensemble.grid.range2=[-0.5,1.5]" --set "ensemble.grid.axes=[0,1]" --set ensemble.grid.fixed=0 \
      --set observe.fli=true --set observe.velocity_map=false --set integrator.step=0.01 --set run.average=100 \
      --set run.duration=100 --set output.images=false >/dev/null 2>"$BW/fli_err.txt" &&
      python3 -c "import json; s=json.load(open('/tmp/aw-fli/summary.json')); print(f'  FLI 1024x1024 x {s.get(\"steps\", \"?\")} steps on $CUDA0: {s[\"wall_seconds\"]:.2f} s run, {s[\"trajectory_steps_per_second\"]:.3e} traj-steps/s')" ||
      { echo "  FLI 1024x1024: failed"; tail -5 "$BW/fli_err.txt"; }
  fi
fi
stamp "bench: combine, plot, targets"
python3 - "$BW" "$OUT" <<'PY'
import csv, glob, io, json, os, sys
bw, out = sys.argv[1], sys.argv[2]
rows, header = [], None
for f in sorted(glob.glob(bw + "/*/bench.csv")):
    if "ncu-run" in f: continue
    r = list(csv.reader(open(f)))
    header = header or r[0]
    rows += r[1:]
if header:
    with open(out + "/bench.csv", "w", newline="") as f:
        w = csv.writer(f); w.writerow(header); w.writerows(rows)
D = [dict(zip(header, r)) for r in rows] if header else []
def rate(**k):
    best = None
    for d in D:
        if all(d.get(a) == str(v) for a, v in k.items()) and float(d["rate"] or 0) > 0:
            if best is None or int(d["trajectories"]) > int(best["trajectories"]): best = d
    return best
print("\nTargets (double, Yoshida-6, E = 15):")
for d in D:
    if d["kind"] == "library" and d["precision"] == "double" and d["variant"] == "default" and float(d["ratio"] or 0) > 0:
        pass
big = {}
for d in D:
    if d["kind"] == "library" and d["variant"] == "default" and d["rate"]:
        k = (d["device"], d["precision"])
        if k not in big or int(d["trajectories"]) > int(big[k]["trajectories"]): big[k] = d
for (dev, prec), d in sorted(big.items()):
    print(f"  {dev:10s} {d['name'][:30]:30s} {prec:6s} N={int(d['trajectories']):>9d} steps={d['steps']:>5s} "
          f"{float(d['rate']):.3e} traj-steps/s  x{float(d['ratio'] or 0):.2f} {d['baseline']}")
cu = big.get(("cuda:0", "double"))
for (dev, prec), d in big.items():
    if prec == "double" and dev.startswith("opencl") and d["cpu"] == "0" and cu:
        print(f"  NVIDIA OpenCL / CUDA (double): {float(d['rate']) / float(cu['rate']):.3f}")
for d in D:
    if d["kind"] == "scene":
        print(f"  Figure 3 on {d['device']}: {float(d['seconds'] or 0):.2f} s end to end, {float(d['rate'] or 0):.3e} traj-steps/s; {d['note']}")
for f in glob.glob(bw + "/*/bench.json"):
    for m in json.load(open(f)).get("memory", []):
        print(f"  memory {m['device']} N={m['trajectories']:.0e}: computed {m['computed_bytes']/2**20:.1f} MiB, measured {m['measured_bytes']/2**20:.1f} MiB")
eff = [d for d in D if d["kind"] == "effects"]
for d in eff:
    if d["variant"] == "default" and d["math"] == "native":
        p = [e for e in eff if e["device"] == d["device"] and e["precision"] == d["precision"] and e["variant"] == "default" and e["math"] == "portable"]
        if p and float(d["rate"] or 0) > 0:
            print(f"  portable / native {d['device']:10s} {d['precision']:6s}: {float(p[0]['rate']) / float(d['rate']):.3f}")
# ncu
try:
    lines = open(bw + "/ncu.csv").read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith('"ID"'))
    nr = list(csv.reader(io.StringIO("\n".join(lines[start:]))))
    hdr, data = nr[0], [r for r in nr[2:] if len(r) == len(nr[0])]
    num = lambda s: float(s.replace(",", "")) if s.replace(",", "").replace(".", "", 1).isdigit() else 0.0
    best = {}
    for r in data:
        d = dict(zip(hdr, r))
        name = "aw_ensemble" if "aw_ensemble" in d["Kernel Name"] else "naive"
        g = num(d.get("launch__grid_size", "0"))
        if name not in best or g > best[name][0]: best[name] = (g, d)
    with open(out + "/ncu.csv", "w") as f:
        f.write("\n".join(lines[start:]) + "\n")
    for name, (g, d) in best.items():
        ts = 1048576 * 200.0
        fp64 = num(d["sm__inst_executed_pipe_fp64.sum"]) * 32 / ts
        ops = sum(num(d[f"sm__sass_thread_inst_executed_op_{o}_pred_on.sum"]) for o in ("dfma", "dadd", "dmul")) / ts
        print(f"  ncu {name:11s}: FP64 pipe {d['sm__inst_executed_pipe_fp64.avg.pct_of_peak_sustained_active']}% of peak (active), "
              f"{fp64:.0f} FP64-pipe thread-instr/step, {ops:.0f} DFMA+DADD+DMUL/step, regs {d['launch__registers_per_thread']}, "
              f"occupancy {d['sm__warps_active.avg.pct_of_peak_sustained_active']}%, {d['gpu__time_duration.sum']} ns")
except Exception as e:
    print("  ncu: no metrics (" + str(e) + ")")
PY
GPUNAME="$(nvidia-smi --query-gpu=name,driver_version --format=csv,noheader 2>/dev/null | head -1)"
[ -f "$OUT/bench.csv" ] && { python3 bench/throughput/plot_bench.py "$OUT/bench.csv" "$OUT/bench_throughput.png" "$GPUNAME" ||
  /usr/bin/python3 bench/throughput/plot_bench.py "$OUT/bench.csv" "$OUT/bench_throughput.png" "$GPUNAME"; } || true
cp "$BW"/*.log "$BW"/ncu*.csv "$BW"/ncu.err "$OUT/" 2>/dev/null
for d in "$BW"/*/; do n=$(basename "$d"); for f in "$d"*.csv "$d"*.json; do [ -f "$f" ] && cp "$f" "$OUT/${n}_$(basename "$f")"; done; done
fi  # not verify

stamp "summary"
echo "ctest rc=$ctest_rc  parity rc=$parity_rc"
if [ "$mode" != bench ]; then
  grep -E "tests passed|tests failed" "$OUT/ctest.txt"
  tail -1 "$OUT/parity.md"
fi
# At most 8 files come back from $OUT: keep the main ones, pack the rest.
(cd "$OUT" && tar czf /tmp/results.tgz --exclude=results.tgz . && mv /tmp/results.tgz results.tgz &&
  for f in *; do case $f in results.tgz|summary.txt|bench.csv|bench_throughput.png|ncu.csv|setup.txt) ;; *) rm -rf "$f" ;; esac; done)
ls "$OUT"
