#!/usr/bin/env bash
# The rates that size issue 26's FGL scenes (docs/frequencies.md, "Cost"):
# trajectory-steps per second of the fgl model (saba3, h = 0.02 T, double) on
# one device, for the frequency-map grid with and without the FLI tangent
# vector, and for the diffusion ensembles at 2^14 and 2^17 trajectories (few
# trajectories, long time: the per-trajectory step rate is what limits the
# D(eps) scan). Everything here runs with today's keys; the frequency analysis
# itself is not wired yet.
#   bash bench/gpu/fgl_rate.sh ARNOLDWEB DEVICE
# A smoke test at a CPU size: AW_FGL_RES=32 AW_FGL_T=4 AW_FGL_SIDES="8" AW_FGL_DIFF_T=20 bash ...
# Prints: case, trajectories, steps per trajectory, seconds, traj-steps/s, steps/s per trajectory.
set -uo pipefail
aw=$1 dev=$2
printf "%-22s %10s %12s %9s %12s %14s\n" case trajectories steps seconds traj-steps/s steps/s/traj
run() {  # name, then arguments of arnoldweb run
  local name=$1
  shift
  local out
  out=$(mktemp -d)/run
  if "$aw" run "$@" --quiet --device "$dev" --out "$out" --set output.images=false >/dev/null 2>"$out.err"; then
    python3 - "$out/summary.json" "$name" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
r, n = s["trajectory_steps_per_second"], s["trajectories"]
steps = r * s["wall_seconds"] / n
print(f"{sys.argv[2]:22s} {n:10d} {steps:12.0f} {s['wall_seconds']:9.2f} {r:12.4g} {r / n:14.4g}")
PY
  else
    echo "$name: failed"; tail -3 "$out.err"
  fi
  rm -rf "$(dirname "$out")"
}
res=${AW_FGL_RES:-1024} t=${AW_FGL_T:-160} diff_t=${AW_FGL_DIFF_T:-2000}
grid=(--set model.epsilon=0.01 --set "ensemble.grid.resolution=[$res,$res]" --set run.average=$t --set run.duration=$t)
# the frequency-map grid of scenes/fgl_frequency_map.toml: 1024^2 x 160 T, plain, then with FLI
run fma_grid_plain scenes/fli_fgl.toml "${grid[@]}" --set observe.fli=false --set observe.final_states=true
run fma_grid_fli scenes/fli_fgl.toml "${grid[@]}"
# the diffusion ensembles of scenes/fgl_diffusion.toml: a square of actions on I1 = I2, 2000 T
for side in ${AW_FGL_SIDES:-128 362}; do
  run "diffusion_${side}x${side}" scenes/fli_fgl.toml --set model.epsilon=0.01 \
    --set "ensemble.grid.resolution=[$side,$side]" --set "ensemble.grid.range1=[0.3,0.300001]" \
    --set "ensemble.grid.range2=[0.3,0.300001]" --set run.average=$diff_t --set run.duration=$diff_t \
    --set observe.fli=false --set observe.final_states=true
done
