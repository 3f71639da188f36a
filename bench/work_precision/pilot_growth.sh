#!/bin/sh
# How much larger is max|dE| over a full ensemble than over the accuracy
# pilot (the first 512 trajectories, 5 T)? The answer sets the default safety
# factor of `arnoldweb accuracy` and integrator.step = "auto" (docs/accuracy.md).
# Usage: bench/work_precision/pilot_growth.sh [BUILD_DIR] [N_FULL]
set -e
build=${1:-build}
nfull=${2:-16384}
aw="$build/arnoldweb"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf "%-6s %-13s %-8s %-24s %-24s %s\n" E method step "pilot 512 x 5 T" "full $nfull x 50 T" ratio
for case in "15 yoshida6a 0.01" "15 kahan-li-s15 0.01" "15 srkn11b 0.01" "400 yoshida6a 0.002" "400 srkn11b 0.002"; do
  set -- $case
  common="--device cpu -q -f --set model.energy=$1 --set integrator.method=$2 --set integrator.step=$3
          --set observe.velocity_map=false --set observe.energy_error.every=1"
  $aw run scenes/default.toml $common --set ensemble.trajectories=512 --set run.average=5 \
      --set run.duration=5 -o "$out/p" >/dev/null
  $aw run scenes/default.toml $common --set ensemble.trajectories=$nfull --set run.average=50 \
      --set run.duration=50 -o "$out/f" >/dev/null
  /usr/bin/python3 - "$out/p/summary.json" "$out/f/summary.json" "$1" "$2" "$3" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["energy_error"]["max"]
f = json.load(open(sys.argv[2]))["energy_error"]["max"]
print(f"{sys.argv[3]:<6} {sys.argv[4]:<13} {sys.argv[5]:<8} {p:<24.3e} {f:<24.3e} {f / p:.2f}")
PY
done
