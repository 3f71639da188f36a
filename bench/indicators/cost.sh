#!/usr/bin/env bash
# The cost of the chaos indicators (docs/indicators.md): the same grid of
# initial conditions (HEALPix directions at a fixed position, E = 15,
# Yoshida-6, h = 0.01 T) run as a plain velocity map, with FLI, and with every
# indicator, on each device given; prints the wall time of each and the ratio
# to the plain run (the issue's target: FLI at most 2x).
#   bench/indicators/cost.sh [BIN] [NSIDE] [DURATION_T] [DEVICES...]
#   defaults: build/arnoldweb 64 (49152 trajectories) 10 (1000 steps) cpu opencl:0
# On a GPU: bench/indicators/cost.sh build/arnoldweb 512 100 cuda:0
# (512: 3.1e6 trajectories; a 1024 x 1024 plane grid: see docs/indicators.md).
set -euo pipefail
bin=${1:-build/arnoldweb}; nside=${2:-64}; duration=${3:-10}; shift 3 || true
devices=("$@"); [ ${#devices[@]} -gt 0 ] || devices=(cpu opencl:0)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--set ensemble.initial=grid --set ensemble.grid.kind=healpix --set "ensemble.grid.nside=$nside"
        --set "ensemble.grid.position=[0.3,0.7,1.1]" --set "run.average=$duration" --set "run.duration=$duration"
        --set observe.energy_error=false --set output.images=false --set model.energy=15
        --set observe.fli=false --set observe.megno=false --set observe.lyapunov=false)
variants=(
  "velocity_map|"
  "fli|--set observe.fli=true"
  "fli+megno+lyapunov|--set observe.fli=true --set observe.megno=true --set observe.lyapunov=true"
  "fli_no_map|--set observe.fli=true --set observe.velocity_map=false"
)
echo "# $(date -u +%F) $(lscpu | sed -n 's/^Model name: *//p' | head -1), $(nproc) cores; nside $nside, duration $duration T"
echo "# each variant runs twice (the first fills the kernel caches); the second is timed: wall_seconds of the"
echo "# run (summary.json) and the process's CPU time (user + system, all threads; robust on a busy machine)"
for dev in "${devices[@]}"; do
  base_wall=""; base_cpu=""
  for v in "${variants[@]}"; do
    IFS='|' read -r name extra <<<"$v"
    for pass in warm timed; do
      out="$work/$name-${dev/:/_}-$pass"
      # shellcheck disable=SC2086
      cpu=$(python3 - "$bin" run scenes/fli_e15.toml --quiet --device "$dev" --out "$out" "${common[@]}" $extra <<'PY'
import resource, subprocess, sys
subprocess.run(sys.argv[1:], check=True, stderr=subprocess.DEVNULL)
r = resource.getrusage(resource.RUSAGE_CHILDREN)
print(r.ru_utime + r.ru_stime)
PY
)
    done
    wall=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_seconds"])' "$out/summary.json")
    [ -n "$base_wall" ] || { base_wall=$wall; base_cpu=$cpu; }
    python3 -c 'import sys; n,d,w,c,bw,bc=sys.argv[1:]; w,c,bw,bc=map(float,(w,c,bw,bc)); print(f"{d:10} {n:20} wall {w:8.3f} s x{w/bw:.2f}   cpu {c:8.3f} s x{c/bc:.2f}")' \
      "$name" "$dev" "$wall" "$cpu" "$base_wall" "$base_cpu"
  done
done
