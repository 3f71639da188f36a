#!/usr/bin/env bash
# Issue 25 (long trajectories) and issue 26 (frequencies, diffusion) on one GPU, in one call:
#   bash bench/gpu/science.sh ARNOLDWEB DEVICE OUTDIR
# 1. the cost of observe.frequencies: the default scene (the paper's method, scenes/default_paper.toml
#    where it exists) as a map, then with frequencies of 2 x 512 samples every 0.04 T; the FGL
#    frequency map (scenes/fgl_frequency_map.toml, 1024^2, FLI + frequencies) against its FLI alone;
#    its pictures (frequency_map.png, diffusion_index.png, fli.png) are kept for docs/gallery.md;
# 2. the D(eps) scan of scenes/fgl_diffusion.toml, shortened to AW_DSCAN_T (default 1e5 T) per eps,
#    for the values of AW_DSCAN_EPS on a grid of AW_DSCAN_RES^2 (default 362^2) trajectories, each
#    sample the mean of the actions over its interval; each run's summary.json, diffusion.csv and diffusion.png kept
#    (bench/gpu/d_eps_fit.py fits D(eps) from them; with AW_DSCAN_CENTRES, the square at other places
#    along the resonance, and bench/gpu/d_eps_places.py fits the law to the mean over the places);
# 3. a sliced long run (scenes/fig4_diffusion.toml at N = 32,768 to AW_FIG4_T, run.slice), once in
#    one piece and once killed with kill -9 and resumed (twice), with both runs' digests.
# Prints one line per run: case, wall seconds of the process, the run's own seconds.
set -uo pipefail
AW=$1 DEV=$2 OUTDIR=$3
mkdir -p "$OUTDIR"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

run() {  # NAME OUT SCENE ARGS...: runs, prints the times, keeps summary.json under $OUTDIR/NAME
  local name=$1 out=$2
  shift 2
  local t0 t1 rc
  t0=$(date +%s.%N)
  "$AW" run "$@" --quiet --device "$DEV" --out "$out" --force >"$tmp/$name.log" 2>&1
  rc=$?
  t1=$(date +%s.%N)
  if [ $rc -ne 0 ]; then echo "$name: failed (exit $rc)"; tail -5 "$tmp/$name.log"; return 1; fi
  mkdir -p "$OUTDIR/$name"
  cp "$out/summary.json" "$OUTDIR/$name/"
  python3 - "$out/summary.json" "$name" "$t0" "$t1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:28s} process {float(sys.argv[4]) - float(sys.argv[3]):8.2f} s  run {s['wall_seconds']:8.2f} s"
      f"  {s['trajectory_steps_per_second']:.3e} traj-steps/s  trajectories {s['trajectories']}"
      + (f"  frequencies {s['digests']['frequencies']}" if s.get('digests', {}).get('frequencies') else ""))
PY
}

parts=" ${AW_SCIENCE_PARTS:-1 2 3} "
part() { [[ "$parts" == *" $1 "* ]]; }

if part 1; then
echo "== 1. the cost of observe.frequencies on $DEV"
scene=scenes/default_paper.toml
[ -f "$scene" ] || scene=scenes/default.toml
freq=(--set "observe.frequencies={ samples = 512, every = 0.04 }")
# warm the kernel caches first, so that no timed run compiles
run warm_map "$tmp/w1" "$scene" --set ensemble.trajectories=65536 --set output.images=false >/dev/null
run warm_freq "$tmp/w2" "$scene" --set ensemble.trajectories=65536 --set output.images=false "${freq[@]}" >/dev/null
# the same with launches of AW_FREQ_CHUNK trajectories (default 262144: four waves of an H200),
# whose series buffer is a fifth of the default's (a quarter of the GPU's memory)
chunk=(--set "ensemble.chunk=${AW_FREQ_CHUNK:-262144}")
for rep in 1 2; do
  run "default_map_$rep" "$tmp/d1" "$scene" --set output.images=false
  run "default_map_freq_$rep" "$tmp/d2" "$scene" --set output.images=false "${freq[@]}"
  run "default_map_freq_chunk_$rep" "$tmp/d3" "$scene" --set output.images=false "${freq[@]}" "${chunk[@]}"
done
# AW_FREQ_VARIANTS="name=NVRTC options;...": the frequency run again under each kernel variant
# (ARNOLDWEB_NVRTC_OPTIONS), after a warm-up that fills its kernel cache; its frequencies.h5 digest
# on its line (variants that only reorder loads must give the same bits)
if [ -n "${AW_FREQ_VARIANTS:-}" ]; then
  IFS=';' read -r -a variants <<<"$AW_FREQ_VARIANTS"
  for v in "${variants[@]}"; do
    ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" run "warm_${v%%=*}" "$tmp/w3" "$scene" --set ensemble.trajectories=65536 \
      --set output.images=false "${freq[@]}" >/dev/null
  done
  for rep in 1 2; do
    for v in "${variants[@]}"; do
      ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" run "freq_${v%%=*}_$rep" "$tmp/v" "$scene" --set output.images=false "${freq[@]}"
    done
  done
fi
# the same frequency run on NVIDIA's OpenCL (its launches keep the series below 2^31 bytes:
# lib/src/plan/estimates.cpp), when the machine has it
CLDEV=$("$AW" devices --json | python3 -c "import json,sys; print(next((d['id'] for d in json.load(sys.stdin) if d['id'].startswith('opencl') and not d['cpu']), ''))")
if [ -n "$CLDEV" ]; then
  DEV0=$DEV DEV=$CLDEV
  run warm_opencl "$tmp/w6" "$scene" --set ensemble.trajectories=65536 --set output.images=false "${freq[@]}" >/dev/null
  run warm_opencl_map "$tmp/w7" "$scene" --set ensemble.trajectories=65536 --set output.images=false >/dev/null
  run opencl_map "$tmp/o1" "$scene" --set output.images=false
  run opencl_map_freq "$tmp/o2" "$scene" --set output.images=false "${freq[@]}"
  DEV=$DEV0
fi
# AW_FREQ_NCU=1: ncu of one launch of 65,536 of the frequency run (time and DRAM bytes per kernel)
if [ -n "${AW_FREQ_NCU:-}" ] && command -v ncu >/dev/null; then
  ncu --kernel-name regex:aw_ --launch-count 3 --metrics gpu__time_duration.sum,dram__bytes_read.sum,dram__bytes_write.sum,dram__throughput.avg.pct_of_peak_sustained_elapsed \
    "$AW" run "$scene" --quiet --device "$DEV" --out "$tmp/n1" --force --set output.images=false \
    --set ensemble.trajectories=65536 --set ensemble.chunk=65536 "${freq[@]}" 2>&1 | grep -E "^  aw_|duration|bytes|throughput"
fi
# the FGL kernels compiled first too (timed cold, each FGL run counted its NVRTC compile: 0.85 s
# for a 0.32 s FLI map on the H200)
run warm_fgl_fli "$tmp/w4" scenes/fgl_frequency_map.toml --set observe.frequencies=false --set output.images=false \
  --set "ensemble.grid.resolution=[128, 128]" >/dev/null
run warm_fgl_freq "$tmp/w5" scenes/fgl_frequency_map.toml --set output.images=false \
  --set "ensemble.grid.resolution=[128, 128]" >/dev/null
run fgl_fli_only "$tmp/f1" scenes/fgl_frequency_map.toml --set observe.frequencies=false --set output.images=false
run fgl_fli_freq "$tmp/f2" scenes/fgl_frequency_map.toml
mkdir -p "$OUTDIR/gallery"
for f in frequency_map.png diffusion_index.png fli.png; do
  [ -f "$tmp/f2/$f" ] && cp "$tmp/f2/$f" "$OUTDIR/gallery/fgl_0.01_$f"
done
ls "$tmp/f2" >"$OUTDIR/gallery/fgl_files.txt"
fi

if part 2; then
echo "== 2. the D(eps) scan (scenes/fgl_diffusion.toml, ${AW_DSCAN_T:=100000} T per eps)"
T=$AW_DSCAN_T
every=$(python3 -c "print($T / 100)")
fit=$(python3 -c "print($T / 10)")
res=${AW_DSCAN_RES:-362}   # the grid: res x res trajectories
# AW_DSCAN_CENTRES: other places along the resonance I1 = I2 (the square of side 1e-6 about
# (c, c); runs named dscan_<eps>@<c>); default: the scene's (0.3, 0.3) only
for eps in ${AW_DSCAN_EPS:-0.006 0.008 0.010 0.012 0.015 0.020}; do
  for c in ${AW_DSCAN_CENTRES:-scene}; do
    name="dscan_$eps"
    where=()
    if [ "$c" != scene ]; then
      name="dscan_$eps@$c"
      r=$(python3 -c "print(f'[{$c - 5e-7!r}, {$c + 5e-7!r}]')")
      where=(--set "ensemble.grid.range1=$r" --set "ensemble.grid.range2=$r")
    fi
    o="$tmp/ds_$eps"
    run "$name" "$o" scenes/fgl_diffusion.toml --set model.epsilon="$eps" --set run.duration="$T" \
      --set run.average="$T" --set observe.diffusion.every="$every" --set observe.diffusion.fit_from="$fit" \
      --set observe.diffusion.average="$every" --set "ensemble.grid.resolution=[$res, $res]" "${where[@]}" \
      --set observe.energy_error.every="$every" --set observe.final_states=false &&
      for f in diffusion.csv diffusion.png; do [ -f "$o/$f" ] && cp "$o/$f" "$OUTDIR/$name/"; done
    rm -rf "$o"
  done
done
fi

if part 3; then
echo "== 3. a sliced long run, in one piece and killed with kill -9 and resumed (${AW_FIG4_T:=20480} T)"
sl=(scenes/fig4_diffusion.toml --set ensemble.trajectories=32768 --set run.duration="$AW_FIG4_T"
    --set "observe.frames.times=[0.0, 10.0, 160.0, 2560.0, $AW_FIG4_T]" --set run.slice=1280
    --set run.checkpoint_every=1 --set output.images=false --set observe.final_states=true)
run fig4_plain "$tmp/p" "${sl[@]}"
plain_s=$(python3 -c "import json; print(json.load(open('$OUTDIR/fig4_plain/summary.json'))['wall_seconds'])")
o="$tmp/k"
rm -rf "$o"
t0=$(date +%s.%N)
kills=0
"$AW" run "${sl[@]}" --quiet --device "$DEV" --out "$o" >"$tmp/k.log" 2>&1 &
pid=$!
for frac in 0.5 0.4; do  # killed at half of the run's time, and again 0.4 of it after the resume
  sleep "$(python3 -c "print($plain_s * $frac)")"
  if kill -0 $pid 2>/dev/null; then kill -9 $pid; wait $pid 2>/dev/null; kills=$((kills + 1)); fi
  if [ ! -f "$o/summary.json" ]; then
    "$AW" resume "$o" --quiet --device "$DEV" >>"$tmp/k.log" 2>&1 &
    pid=$!
  fi
done
wait $pid
t1=$(date +%s.%N)
echo "fig4 killed $kills times, resumed: process $(python3 -c "print(round($t1 - $t0, 2))") s in all"
mkdir -p "$OUTDIR/fig4_killed"
cp "$o/summary.json" "$OUTDIR/fig4_killed/" 2>/dev/null || { echo "fig4 killed: no summary"; tail -5 "$tmp/k.log"; }
python3 - "$OUTDIR/fig4_plain/summary.json" "$OUTDIR/fig4_killed/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
da, db = a.get("digests", {}), b.get("digests", {})
print("digests of the plain run:  ", json.dumps(da, sort_keys=True))
print("digests of the killed run: ", json.dumps(db, sort_keys=True))
print("fig4 sliced, killed and resumed: digests", "IDENTICAL" if da == db and da else "DIFFER")
PY
fi
