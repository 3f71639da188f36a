#!/usr/bin/env bash
# Throughput of the paper's model written as an expression (model.kind =
# "expression") beside the built-in seibert2011, on one device, in one bench
# run: scenes/default.toml with fewer trajectories, the two models alternating,
# REPEATS runs each; prints trajectory-steps/s of every run (summary.json) and
# the median of each model. The wall time includes the kernel build; PoCL
# keeps built programs in its own disk cache, so the first run of each model
# pays it (warm-up run, not counted).
#   bench/expression/throughput.sh [BIN] [DEVICE] [TRAJECTORIES] [REPEATS]
#   (defaults: build/arnoldweb opencl:0 100000 3)
set -euo pipefail
bin=${1:-build/arnoldweb}
dev=${2:-opencl:0}
n=${3:-100000}
repeats=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
common=(--quiet --device "$dev" --set "ensemble.trajectories=$n" --set output.images=false)
builtin=(--set 'model.kind="seibert2011"')
expression=(--set 'model.kind="expression"' --set 'model.potential="cos(x)*cos(y)*(1 + cos(2*z))"')
rate() {  # name, run index, extra args...
  local name=$1 i=$2
  shift 2
  "$bin" run scenes/default.toml "${common[@]}" "$@" --out "$work/$name-$i" >/dev/null
  python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["trajectory_steps_per_second"])' \
    "$work/$name-$i/summary.json"
}
echo "device $dev, $n trajectories of scenes/default.toml, $(date -u +%F)"
rate builtin warm "${builtin[@]}" >/dev/null
rate expression warm "${expression[@]}" >/dev/null
b=() e=()
for i in $(seq 1 "$repeats"); do
  b+=("$(rate builtin "$i" "${builtin[@]}")")
  e+=("$(rate expression "$i" "${expression[@]}")")
  echo "run $i: seibert2011 ${b[-1]}  expression ${e[-1]}"
done
python3 - "${#b[@]}" "${b[@]}" "${e[@]}" <<'PY'
import statistics, sys
k = int(sys.argv[1]); v = [float(x) for x in sys.argv[2:]]
b, e = statistics.median(v[:k]), statistics.median(v[k:])
print(f"median trajectory-steps/s: seibert2011 {b:.4g}, expression {e:.4g}, ratio {e / b:.3f}")
PY
