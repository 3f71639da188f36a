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
# AW_RATES_CLOCKS=1 samples the GPU's SM clock, power and throttle reasons (nvidia-smi, every 100
# ms) through the rounds and prints each Figure-3 run's median clock beside its rate: the FP64 limit
# is 132 SMs x 64 lanes x the clock the card holds under this load, not its boost clock.
# AW_RATES_NCU=1 profiles each variant's first aw_ensemble launch of Figure 3 (a) at 2^20
# trajectories with ncu: FP64 pipe busy, issue active, warps active, registers, the main stalls.
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
  echo "$name $t0 start" >>"$OUT/windows.txt"
  "$AW" run "$OUT/fig3a.toml" --quiet --device "$DEV" --out "$OUT/$name" --set output.images=false \
    --set ensemble.trajectories="$n" >"$OUT/$name.log" 2>&1
  rc=$?; t1=$(date +%s.%N)
  echo "$name $t1 end" >>"$OUT/windows.txt"
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
rm -f "$OUT/windows.txt" "$OUT/clocks.csv"
sampler=""
if [ -n "${AW_RATES_CLOCKS:-}" ] && command -v nvidia-smi >/dev/null; then
  nvidia-smi --query-gpu=timestamp,clocks.sm,clocks.max.sm,power.draw,temperature.gpu,clocks_throttle_reasons.active \
    --format=csv,noheader,nounits -lms 100 >"$OUT/clocks.csv" 2>/dev/null &
  sampler=$!
fi
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
if [ -n "$sampler" ]; then
  kill "$sampler" 2>/dev/null; wait "$sampler" 2>/dev/null
  python3 - "$OUT/clocks.csv" "$OUT/windows.txt" <<'PY'
import datetime, statistics, sys
samples = []
for line in open(sys.argv[1]):
    f = [x.strip() for x in line.split(",")]
    try:
        t = datetime.datetime.strptime(f[0], "%Y/%m/%d %H:%M:%S.%f").replace(tzinfo=datetime.timezone.utc).timestamp()
        samples.append((t, float(f[1]), float(f[2]), float(f[3]), float(f[4]), f[5]))
    except (ValueError, IndexError):
        continue
runs, start = [], {}
for line in open(sys.argv[2]):
    name, t, kind = line.split()
    if kind == "start":
        start[name] = float(t)
    elif name in start and name.startswith("fig3a-"):
        runs.append((name, start[name], float(t)))
print("== SM clock during each Figure-3 run (nvidia-smi every 100 ms; its clock is local time: matched by offset)")
# nvidia-smi prints local time; the windows are epoch seconds: align the two by their ends
if samples and runs:
    off = round((samples[-1][0] - runs[-1][2]) / 1800) * 1800
    for name, a, b in runs:
        w = [s for s in samples if a + 3 <= s[0] - off <= b]
        if not w:
            print(f"  {name:22s} no samples"); continue
        print(f"  {name:22s} SM clock median {statistics.median(s[1] for s in w):.0f} MHz (min {min(s[1] for s in w):.0f}, "
              f"max clock {w[0][2]:.0f}), power median {statistics.median(s[3] for s in w):.0f} W, "
              f"temperature max {max(s[4] for s in w):.0f} C, throttle reasons {sorted({s[5] for s in w})}, {len(w)} samples")
PY
fi
if [ -n "${AW_RATES_NCU:-}" ] && command -v ncu >/dev/null; then
  echo "== ncu: each variant's first aw_ensemble launch of Figure 3 (a), 2^20 trajectories"
  # metric=label, one list for ncu's --metrics and the printed line
  columns="sm__pipe_fp64_cycles_active.avg.pct_of_peak_sustained_active=FP64 pipe busy %;\
sm__inst_executed_pipe_fp64.avg.pct_of_peak_sustained_active=FP64 inst %;\
smsp__issue_active.avg.pct_of_peak_sustained_active=issue active %;\
sm__warps_active.avg.pct_of_peak_sustained_active=warps active %;\
launch__registers_per_thread=registers;\
smsp__average_warps_issue_stalled_wait_per_issue_active.ratio=stall wait;\
smsp__average_warps_issue_stalled_math_pipe_throttle_per_issue_active.ratio=stall math pipe;\
smsp__average_warps_issue_stalled_short_scoreboard_per_issue_active.ratio=stall short scoreboard;\
smsp__average_warps_issue_stalled_not_selected_per_issue_active.ratio=not selected;\
sm__cycles_elapsed.avg.per_second=SM cycles/s"
  metrics=$(tr ';' '\n' <<<"$columns" | cut -d= -f1 | paste -sd,)
  for v in "${variants[@]}"; do
    name=${v%%=*}
    ARNOLDWEB_NVRTC_OPTIONS="${v#*=}" timeout 120 ncu --clock-control none -k regex:aw_ensemble --launch-count 1 --csv --page raw \
      --metrics "$metrics" "$AW" run "$OUT/fig3a.toml" --quiet --device "$DEV" --out "$OUT/ncu-$name" \
      --set output.images=false --set ensemble.trajectories=1048576 >"$OUT/ncu-$name.csv" 2>"$OUT/ncu-$name.err"
    python3 - "$OUT/ncu-$name.csv" "$name" "$columns" <<'PY'
import csv, sys
rows = [r for r in csv.reader(open(sys.argv[1])) if r]
head = next((i for i, r in enumerate(rows) if "Kernel Name" in r), None)
if head is None or len(rows) < head + 3:
    print(f"  {sys.argv[2]:22s} no ncu rows"); sys.exit(0)
h, d = rows[head], rows[head + 2]
short = dict(c.split("=", 1) for c in sys.argv[3].split(";"))
print(f"  {sys.argv[2]:22s} " + ", ".join(f"{short[k]} {d[h.index(k)]}" for k in short if k in h))
PY
    rm -rf "${OUT:?}/ncu-$name"
  done
fi
# every Figure-3 map digest against the first variant's (same bits per trajectory: same map)
python3 - "$OUT/fig3a-lines.txt" <<'PY'
import re, sys
runs = [(l.split()[0], m.group(1)) for l in open(sys.argv[1]) if (m := re.search(r"map (\S+),", l))]
if runs:
    first = runs[0][1]
    odd = sorted({name for name, d in runs if d != first})
    print("== map digests: " + ("all the same as " + runs[0][0] + "'s" if not odd else "DIFFER from " + runs[0][0] + "'s: " + ", ".join(odd)))
PY
