#!/usr/bin/env bash
# Digests of every ready scene (scaled down) and of the effects, on the given
# devices: the proof that a refactoring changed no bits. Prints one line per
# scene and device: map, initial-states and final-states digests, max |dE|.
#   bench/digests/digests.sh [BIN] [DEVICES...]   (default: build/arnoldweb cpu opencl:0)
set -euo pipefail
bin=${1:-build/arnoldweb}; shift || true
devices=("$@"); [ ${#devices[@]} -gt 0 ] || devices=(cpu opencl:0)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
small=(--set ensemble.trajectories=3000 --set observe.initial_states=true --set observe.final_states=true
       --set output.images=false)
cases=(
  "default|scenes/default.toml|--set run.average=5 --set run.duration=10"
  "fig2|scenes/fig2_e400.toml|--set run.average=2 --set run.duration=2 --set observe.energy_error.every=1"
  "fig3|scenes/fig3_e15.toml|--set run.average=2 --set run.duration=2 --set observe.energy_error.every=1"
  "fig4|scenes/fig4_diffusion.toml|--set run.duration=40 --set observe.frames.times=[0,10,20,40]"
  "float|scenes/default.toml|--set integrator.precision=float --set run.average=5 --set run.duration=5"
  "box-pefrl|scenes/default.toml|--set ensemble.initial=box --set integrator.method=pefrl --set run.average=4 --set run.duration=4 --set observe.energy_error.every=2 --set observe.max_energy_error=1e-5"
  "cap-zoom-confine|scenes/default.toml|--set ensemble.initial=cap --set observe.zoom.width=20 --set observe.confine.width=30 --set run.average=2 --set run.duration=4 --set observe.energy_error.every=1"
)
for dev in "${devices[@]}"; do
  for c in "${cases[@]}"; do
    IFS='|' read -r name scene extra <<<"$c"
    out="$work/$name-${dev/:/_}"
    # shellcheck disable=SC2086
    "$bin" run "$scene" --quiet --device "$dev" --out "$out" "${small[@]}" $extra
    python3 - "$out/summary.json" "$name" "$dev" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
d = s["digests"]
print(f'{sys.argv[2]:18} {sys.argv[3]:9} map {d["map"]} init {d["initial_states"][:12]} final {d["final_states"][:12]} '
      f'max|dE| {s["energy_error"].get("max", "-")!r} binned {s["binned"]}')
PY
  done
done
