#!/usr/bin/env bash
# Digests of every ready scene (scaled down), of every model of the table and
# of the effects, on the given devices: the proof that a refactoring changed no
# bits. The models come from the binary (`models --json`): each built-in gets a
# case "model-<name>" at its defaults on the paper's scene, so a new model is in
# by itself; each line prints every digest summary.json holds (the map and one
# per output of the output table), so a new output is too.
# The cases on the default scene's physics use scenes/default_paper.toml (Yoshida-6 at
# 0.02 T, the default scene until 2026-11-26); "sbab3c" is scenes/default.toml itself.
# Prints one line per case and device: the digests (the map's whole, the others'
# first 12 hex digits), max |dE|, binned count. The freq-*
# cases: the FGL frequency map and the default scene's chaotic orbits, whose
# largest terms the band's grid finds.
#   bench/digests/digests.sh [BIN] [DEVICES...]   (default: build/arnoldweb cpu opencl:0)
# Expression models need a device that compiles at run time (OpenCL, CUDA, or a
# cpu backend with a host compiler); a case a device refuses prints "refused".
set -euo pipefail
bin=${1:-build/arnoldweb}; shift || true
devices=("$@"); [ ${#devices[@]} -gt 0 ] || devices=(cpu opencl:0)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
small=(--set observe.initial_states=true --set observe.final_states=true --set output.images=false)
n3000=";--set;ensemble.trajectories=3000"
# each case: name|scene|extra arguments separated by ';'
cases=(
  "default|scenes/default_paper.toml|;--set;run.average=5;--set;run.duration=10$n3000"
  "fig2|scenes/fig2_e400.toml|;--set;run.average=2;--set;run.duration=2;--set;observe.energy_error.every=1$n3000"
  "fig3|scenes/fig3_e15.toml|;--set;run.average=2;--set;run.duration=2;--set;observe.energy_error.every=1$n3000"
  "fig4|scenes/fig4_diffusion.toml|;--set;run.duration=40;--set;observe.frames.times=[0,10,20,40]$n3000"
  "float|scenes/default_paper.toml|;--set;integrator.precision=float;--set;run.average=5;--set;run.duration=5$n3000"
  "box-pefrl|scenes/default_paper.toml|;--set;ensemble.initial=box;--set;integrator.method=pefrl;--set;run.average=4;--set;run.duration=4;--set;observe.energy_error.every=2;--set;observe.max_energy_error=1e-5$n3000"
  "cap-zoom-confine|scenes/default_paper.toml|;--set;ensemble.initial=cap;--set;observe.zoom.width=20;--set;observe.confine.width=30;--set;run.average=2;--set;run.duration=4;--set;observe.energy_error.every=1$n3000"
  "fgl|scenes/fgl_eps0.01.toml|;--set;run.average=20;--set;run.duration=20$n3000"
  "expression|scenes/default_paper.toml|;--set;model.kind=expression;--set;model.potential=\"cos(x)*cos(y)*(1 + cos(2*z))\";--set;run.average=5;--set;run.duration=5$n3000"
  "gradient|scenes/default_paper.toml|;--set;integrator.method=saba4c;--set;run.average=5;--set;run.duration=5$n3000"
  "sbab3c|scenes/default.toml|;--set;run.average=5;--set;run.duration=10$n3000"
  "orbits|scenes/default.toml|;--set;run.average=5;--set;run.duration=10;--set;observe.trajectories={ ids = [0, 5, 2999], every = 5.0 }$n3000"
  "chin4a-fourier|scenes/default_paper.toml|;--set;model.kind=fourier;--set;integrator.method=chin4a;--set;run.average=5;--set;run.duration=5$n3000"
  "sbab3c-expression|scenes/default.toml|;--set;model.kind=expression;--set;model.potential=\"cos(x)*cos(y)*(1 + cos(2*z))\";--set;run.average=5;--set;run.duration=5$n3000"
  "fli-grid|scenes/fli_e15.toml|;--set;ensemble.grid.nside=8;--set;run.duration=20;--set;run.average=20"
  "fli-fgl|scenes/fli_fgl.toml|;--set;ensemble.grid.resolution=[24,24];--set;run.duration=100;--set;run.average=100"
  "freq-fgl|scenes/fgl_frequency_map.toml|;--set;ensemble.grid.resolution=[48,48]"
  "freq-default|scenes/default_paper.toml|;--set;run.average=10.24;--set;run.duration=10.24;--set;observe.energy_error.every=1.28;--set;observe.frequencies={ samples = 128, every = 0.04 }$n3000"
)
# every model of the table whose potential is not written in the scene (that kind: the expression cases)
while read -r model; do
  cases+=("model-$model|scenes/default_paper.toml|;--set;model.kind=$model;--set;integrator.allow_unsafe_step=true;--set;run.average=5;--set;run.duration=5$n3000")
done < <("$bin" models --json | python3 -c '
import json, sys
for m in json.load(sys.stdin):
    if "model.potential" not in m["keys"]:
        print(m["name"])')
for dev in "${devices[@]}"; do
  for c in "${cases[@]}"; do
    IFS='|' read -r name scene extra <<<"$c"
    out="$work/$name-${dev/:/_}"
    IFS=';' read -r -a more <<<"${extra#;}"
    if ! "$bin" run "$scene" --quiet --device "$dev" --out "$out" "${small[@]}" "${more[@]}" >"$work/log" 2>&1; then
      printf '%-18s %-9s refused: %s\n' "$name" "$dev" "$(head -c 150 "$work/log" | tr '\n' ' ')"
      continue
    fi
    python3 - "$out/summary.json" "$name" "$dev" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
digests = " ".join(f"{k} {v if k == 'map' else v[:12]}" for k, v in s["digests"].items() if k != "algorithm")
print(f'{sys.argv[2]:18} {sys.argv[3]:9} {digests} '
      f'max|dE| {s["energy_error"].get("max", "-")!r} binned {s["binned"]}')
PY
  done
done
