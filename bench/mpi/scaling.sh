#!/usr/bin/env bash
# Scaling of one run over K MPI ranks (issue 15, part 6; docs/cluster.md): runs
# a scene with 1 rank and with K ranks (one device each: the node-local rank
# picks the node's device of that index among the devices of the kind asked
# for), prints the wall times, the speed-up and whether the digests agree.
#   bench/mpi/scaling.sh [BIN] [K] [DEVICE] [SCENE] [--set ...]
#   e.g. bench/mpi/scaling.sh build/arnoldweb 2 cuda:0 scenes/fig3_e15.toml
# A mixed run gives a device list: DEVICE=cuda:0,cuda:1,cpu (rank r takes entry r).
set -euo pipefail
bin=${1:-build/arnoldweb}; k=${2:-2}; device=${3:-auto}; scene=${4:-scenes/fig3_e15.toml}
shift $(( $# < 4 ? $# : 4 )) || true
extra=("$@")
command -v mpirun >/dev/null || { echo "mpirun not found (openmpi-bin)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
launcher=(mpirun --oversubscribe -n)
[ "$(id -u)" = 0 ] && launcher=(mpirun --allow-run-as-root --oversubscribe -n)
run() {  # ranks out device
  local t0 t1
  t0=$(date +%s%N)
  "${launcher[@]}" "$1" "$bin" run "$scene" --quiet --device "$3" --out "$work/$2" --set output.images=false \
    "${extra[@]}"
  t1=$(date +%s%N)
  echo $(( (t1 - t0) / 1000000 ))  # milliseconds
}
single_device=${device%%,*}
t1=$(run 1 one "$single_device")
tk=$(run "$k" many "$device")
python3 - "$work/one/summary.json" "$work/many/summary.json" "$t1" "$tk" "$k" "$device" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
t1, tk, k = float(sys.argv[3]) / 1e3, float(sys.argv[4]) / 1e3, int(sys.argv[5])
same = a["digests"] == b["digests"]
print(f"1 rank   {t1:8.2f} s   compute {a['wall_seconds']:.2f} s   {a['device']['name']}")
print(f"{k} ranks  {tk:8.2f} s   compute {b['wall_seconds']:.2f} s   devices {sys.argv[6]}")
print(f"speed-up {t1 / tk:.2f} (wall), {a['wall_seconds'] / b['wall_seconds']:.2f} (compute)   "
      f"digests {'identical' if same else 'DIFFER'}")
sys.exit(0 if same else 1)
PY
