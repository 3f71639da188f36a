#!/usr/bin/env bash
# The two GPU rows of issue 29 from one call (docs/performance.md, "Performance, round three"):
#   1. Figure 3 panel (a): scenes/fig3_e15.toml without its panels (E = 15, 1e8 trajectories x 50 T
#      at 0.01 T = 5000 steps, Yoshida-6A, double, nside 256), timed as a whole process; the
#      trajectory-steps/s of its run (baseline 2.356e10 on an H200, goal >= 3.0e10);
#   2. Figure 4's schedule at the paper's N = 32,768 (bench/gpu/small_n.sh, DURATION_T T; baseline
#      6.15e9 at 1000 T, goal >= 1.2e10).
# Each kernel variant of AW_RATES_VARIANTS runs both, in turn, REPEAT times (A B A B ...), so that
# a variant and the default are compared inside one call on one machine:
#   AW_RATES_VARIANTS="default=;two=-DAW_SOMETHING=1"   name=NVRTC options (ARNOLDWEB_NVRTC_OPTIONS)
# A warm-up run of each variant (2^20 trajectories of Figure 3, 10 T of Figure 4's schedule) fills
# its kernel caches first, so that no timed run compiles. The map digest of each Figure-3 run is
# printed, and at the end whether every variant's digest is the first variant's: variants that only
# change the schedule of the work (the kernel levers of docs/performance.md) must give the same.
#
#   bash bench/gpu/rates.sh ARNOLDWEB DEVICE OUTDIR [REPEAT] [DURATION_T]
set -uo pipefail
AW=$1; DEV=$2; OUT=$3; REPEAT=${4:-2}; DURATION=${5:-1000}
N=${AW_RATES_N:-100000000}
mkdir -p "$OUT"
rm -f "$OUT/fig3a-lines.txt"
sed '/^\[\[panel\]\]/,$d' scenes/fig3_e15.toml >"$OUT/fig3a.toml"
IFS=';' read -r -a variants <<<"${AW_RATES_VARIANTS:-default=}"

fig3a() {  # NAME TRAJECTORIES: one line (process, run, rate, max|dE|, digest)
  local name=$1 n=$2
  rm -rf "${OUT:?}/$name"
  local t0 t1 rc; t0=$(date +%s.%N)
  "$AW" run "$OUT/fig3a.toml" --quiet --device "$DEV" --out "$OUT/$name" --set output.images=false \
    --set ensemble.trajectories="$n" >"$OUT/$name.log" 2>&1
  rc=$?; t1=$(date +%s.%N)
  if [ $rc -ne 0 ]; then echo "  $name: failed, exit $rc"; tail -5 "$OUT/$name.log"; return 1; fi
  python3 - "$OUT/$name/summary.json" "$t0" "$t1" "$name" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f'  {sys.argv[4]:22s} process {float(sys.argv[3]) - float(sys.argv[2]):7.2f} s, run {s["wall_seconds"]:7.2f} s, '
      f'{s["trajectory_steps_per_second"]:.4e} traj-steps/s, max|dE| {s["energy_error"]["max"]:.2e}, '
      f'map {s["digests"]["map"]}, {s["device"]["name"]}')
PY
  rm -rf "${OUT:?}/$name"
}

for v in "${variants[@]}"; do
  name=${v%%=*}
  ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" fig3a "warmup-$name" 1048576 >/dev/null
  ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" AW_SMALL_N_SIZES=32768 bash bench/gpu/small_n.sh "$AW" 10 "$DEV" >/dev/null
done
for r in $(seq 1 "$REPEAT"); do
  for v in "${variants[@]}"; do
    name=${v%%=*}
    echo "== round $r, variant $name (NVRTC options: '${v#*=}')"
    echo " Figure 3 (a), $N trajectories x 5000 steps, $DEV:"
    ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" fig3a "fig3a-$name-$r" "$N" | tee -a "$OUT/fig3a-lines.txt"
    echo " Figure 4's schedule, $DURATION T, $DEV:"
    ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" AW_SMALL_N_SIZES=32768 bash bench/gpu/small_n.sh "$AW" "$DURATION" "$DEV"
  done
done
# every Figure-3 map digest against the first variant's (same bits per trajectory: same map)
python3 - "$OUT/fig3a-lines.txt" <<'PY'
import re, sys
runs = [(l.split()[0], m.group(1)) for l in open(sys.argv[1]) if (m := re.search(r"map (\S+),", l))]
if runs:
    first = runs[0][1]
    odd = sorted({name for name, d in runs if d != first})
    print("== map digests: " + ("all the same as " + runs[0][0] + "'s" if not odd else "DIFFER from " + runs[0][0] + "'s: " + ", ".join(odd)))
PY
