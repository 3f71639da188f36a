#!/usr/bin/env bash
# Every GPU of a node in one process (issue 25, item 4; docs/cluster.md): Figure 3 panel (a)
# (scenes/fig3_e15.toml without its panels: E = 15, 1e8 trajectories x 50 T at 0.01 T, nside 256)
# timed as a whole process on one GPU and on a list of GPUs driven by one process (a thread per
# device, no MPI), then with `--device all`. Prints each run's process and compute seconds, the
# ratio of the one-GPU time to the list's (goal >= 1.9 with two GPUs, as a whole process) and the
# map and state digests, which must be identical. Beside each run, where its start-up went
# (summary.json's "startup", issue 42 item 4): the drivers' inventory by backend, each device's
# open (context), kernels (and where they came from), buffers and first launch, and what the
# process spent outside the run (process - wall_seconds: inventory, open, planning, writing, exit).
#
#   bash bench/gpu/multi_gpu.sh ARNOLDWEB OUTDIR [DEVICES] [TRAJECTORIES]
#
# DEVICES: the list (default: every CUDA device, e.g. cuda:0,cuda:1); the one-GPU run uses its
# first entry. A warm-up of 2^20 trajectories (or TRAJECTORIES, if fewer) on the list first fills
# the kernel caches, so that no timed run compiles. Exit 0 when every digest agrees, 1 otherwise.
set -uo pipefail
AW=$1; OUT=$2
DEVS=${3:-$("$AW" devices --json | python3 -c "import json,sys; print(','.join(d['id'] for d in json.load(sys.stdin) if d['id'].startswith('cuda')))")}
N=${4:-100000000}
ONE=${DEVS%%,*}
[ -n "$ONE" ] || { echo "multi_gpu: no CUDA device"; exit 77; }
mkdir -p "$OUT"
sed '/^\[\[panel\]\]/,$d' scenes/fig3_e15.toml >"$OUT/fig3a.toml"

run() {  # NAME DEVICE TRAJECTORIES: one line, the process time in $OUT/NAME.seconds
  local name=$1 dev=$2 n=$3
  rm -rf "${OUT:?}/$name"
  local t0 t1; t0=$(date +%s.%N)
  "$AW" run "$OUT/fig3a.toml" --quiet --device "$dev" --out "$OUT/$name" --set output.images=false \
    --set ensemble.trajectories="$n" >"$OUT/$name.log" 2>&1
  local rc=$?
  t1=$(date +%s.%N)
  if [ $rc -ne 0 ]; then echo "$name ($dev): failed, exit $rc"; tail -5 "$OUT/$name.log"; return 1; fi
  python3 - "$OUT/$name/summary.json" "$t0" "$t1" "$name" "$dev" "$OUT/$name.seconds" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
process = float(sys.argv[3]) - float(sys.argv[2])
open(sys.argv[6], "w").write(f"{process}\n")
print(f'{sys.argv[4]:6s} {sys.argv[5]:24s} process {process:7.2f} s, run {s["wall_seconds"]:7.2f} s, '
      f'{s["trajectory_steps_per_second"]:.3e} traj-steps/s, binned {s["binned"]}, device {s["device"]["name"]}')
st = s.get("startup", {})
inv = ", ".join(f"{k} {v:.3f} s" for k, v in st.get("inventory_seconds", {}).items())
print(f'       start-up: outside the run {process - s["wall_seconds"]:.3f} s; devices asked: {inv or "none"}')
for d in st.get("devices", []):
    print(f'         {d["device"]:10s} open {d["open_seconds"]:.3f} s, kernel {d["kernel_seconds"]:.3f} s '
          f'({d["kernel_from"]}), buffers {d["buffers_seconds"]:.3f} s, first launch {d["first_launch_seconds"]:.3f} s')
PY
}

nvidia-smi --query-gpu=index,name,driver_version --format=csv,noheader 2>/dev/null
WARM=$(( N < 1048576 ? N : 1048576 ))
echo "== warm-up (kernel caches): $WARM trajectories on $DEVS"
run warmup "$DEVS" "$WARM" || exit 1
echo "== Figure 3 (a), $N trajectories: one GPU, then $DEVS in one process, then --device all"
run one "$ONE" "$N" || exit 1
run list "$DEVS" "$N" || exit 1
run all all "$N" || exit 1
python3 - "$OUT" <<'PY'
import json, sys
out = sys.argv[1]
s = {k: json.load(open(f"{out}/{k}/summary.json")) for k in ("one", "list", "all")}
t = {k: float(open(f"{out}/{k}.seconds").read()) for k in s}
print(f"ratio one GPU / list: {t['one'] / t['list']:.3f} as a whole process, "
      f"{s['one']['wall_seconds'] / s['list']['wall_seconds']:.3f} in compute; outside the run: one GPU "
      f"{t['one'] - s['one']['wall_seconds']:.3f} s, list {t['list'] - s['list']['wall_seconds']:.3f} s")
for k in s:
    print(f"digests {k:4s}: map {s[k]['digests'].get('map')}  final {s[k]['digests'].get('final_states')}  "
          f"kernel {s[k].get('kernel', '')[-60:]}")
same = all(s[k]["digests"] == s["one"]["digests"] and s[k]["binned"] == s["one"]["binned"] for k in s)
print("digests identical" if same else "DIGESTS DIFFER")
sys.exit(0 if same else 1)
PY
