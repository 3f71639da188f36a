#!/usr/bin/env bash
# Float where it is enough (issue 16 target 6): Figure 3 panel (a) (scenes/fig3_e15.toml: E = 15,
# 1e8 trajectories x 50 T at 0.01 T, nside 256) in double and in float, each timed as a process,
# and the maps compared by the two-sample chi-square test (`arnoldweb compare`, docs/outputs.md).
#
#   bash bench/gpu/float_map.sh ARNOLDWEB DEVICE OUTDIR [TRAJECTORIES]
#
# Runs: double seed 1, double seed 2, float seed 2, float seed 3. Comparisons:
#   double 1 - double 2  the null: two independent ensembles of the same precision
#   double 1 - float 2   the question: independent ensembles, double against float
#   double 1 - float 3   the same with another float ensemble
#   double 2 - float 2   the same initial states in both precisions (correlated: chi2/dof < 1)
# One line per run (precision, seed, wall seconds of the process and of the run, rate) and the
# output of each comparison go to stdout; every summary.json and map stay in OUTDIR.
set -uo pipefail
AW=$1; DEV=$2; OUT=$3; N=${4:-100000000}
mkdir -p "$OUT"
sed '/^\[\[panel\]\]/,$d' scenes/fig3_e15.toml >"$OUT/fig3a.toml"

run() {  # NAME PRECISION SEED
  local name=$1 prec=$2 seed=$3
  rm -rf "${OUT:?}/$name"
  local t0; t0=$(date +%s.%N)
  if "$AW" run "$OUT/fig3a.toml" --quiet --device "$DEV" --out "$OUT/$name" --set output.images=false \
       --set ensemble.trajectories="$N" --set integrator.precision="\"$prec\"" --set ensemble.seed="$seed" \
       >"$OUT/$name.log" 2>&1; then
    python3 - "$OUT/$name/summary.json" "$t0" "$(date +%s.%N)" "$name" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f'{sys.argv[4]:9s} process {float(sys.argv[3]) - float(sys.argv[2]):7.2f} s, run {s["wall_seconds"]:7.2f} s, '
      f'{s["trajectory_steps_per_second"]:.3e} traj-steps/s, binned {s["binned"]}, max|dE| {s["energy_error"]["max"]:.2e}')
PY
  else
    echo "$name: failed"; tail -3 "$OUT/$name.log"
  fi
}

echo "== Figure 3 (a), $N trajectories, $DEV: double and float"
run double1 double 1
run double2 double 2
run float2 float 2
run float3 float 3
for pair in "double1 double2" "double1 float2" "double1 float3" "double2 float2"; do
  set -- $pair
  echo "== compare $1 $2"
  "$AW" compare "$OUT/$1" "$OUT/$2"
  echo "exit $?"
done
