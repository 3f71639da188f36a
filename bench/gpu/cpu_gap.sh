#!/usr/bin/env bash
# Issue 42 item 3: where a 2-core Intel Xeon loses the factor of two against the 2-core AMD EPYC
# (docs/performance.md, "The CPU backend on Intel and AMD"). Runs the default scene on the host CPU
# of whatever machine runs it (the GPU machines' hosts are Xeons), confined with taskset to two
# logical CPUs chosen from the topology:
#   siblings  two hyperthreads of one physical core (what a cloud "2-vCPU" machine often is)
#   cores     two hyperthreads-free CPUs of two different physical cores
#   one       a single logical CPU (one thread)
# each with the 8-lane AVX-512 kernels (x86-64-v4) and the cores pair also with the 4-lane AVX2
# kernels (x86-64-v3: the 512-bit execution and its frequency licence against 256-bit), on the
# library's own backend (`--device cpu`) and PoCL (the default device where there is no GPU).
# Whole-process seconds, with the max|dE| and the map digest (every configuration must give the
# same bits). Usage: bash bench/gpu/cpu_gap.sh AW [SCENE [--set K=V ...]] (AW: the program).
set -uo pipefail
AW=${1:?usage: cpu_gap.sh AW [SCENE]}
SCENE=${2:-scenes/default.toml}
shift $(( $# < 2 ? $# : 2 )); EXTRA=("$@")  # further arguments: --set values for every run
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

lscpu | grep -E "Model name|Thread\(s\) per core|Core\(s\) per socket|Socket\(s\)|^CPU\(s\)|MHz|L2|Flags" |
  sed 's/\(Flags:.\{0,40\}\).*\(avx512f\).*/\1 ... \2 .../'
topo=/sys/devices/system/cpu
first_sib=$(cut -d, -f1 <"$topo/cpu0/topology/thread_siblings_list" | cut -d- -f1)
sib_list=$(cat "$topo/cpu0/topology/thread_siblings_list")
# a sibling of cpu0 other than cpu0 (lists look like "0,8" or "0-1")
sib=$(echo "$sib_list" | tr ',' '\n' | while IFS=- read -r a b; do
  for ((c = a; c <= ${b:-$a}; c++)); do [ "$c" != 0 ] && echo "$c"; done; done | head -1)
# a CPU on another physical core: the first whose core_id or package differs from cpu0's
core0=$(cat "$topo/cpu0/topology/core_id"); pkg0=$(cat "$topo/cpu0/topology/physical_package_id")
other=""
for d in "$topo"/cpu[0-9]*; do
  c=${d##*cpu}
  [ -r "$d/topology/core_id" ] || continue
  if [ "$(cat "$d/topology/core_id")" != "$core0" ] && [ "$(cat "$d/topology/physical_package_id")" = "$pkg0" ]; then
    other=$c; break
  fi
done
echo "cpu0's siblings: $sib_list (first $first_sib); another core: cpu${other:-none}"

run() {  # label, cpus, isa, device
  local label=$1 cpus=$2 isa=$3 dev=$4 t0 t1 out=$tmp/$1
  t0=${EPOCHREALTIME/./}
  if ! ARNOLDWEB_CPU_ISA=$isa taskset -c "$cpus" "$AW" run "$SCENE" --device "$dev" -q -f -o "$out" "${EXTRA[@]}" \
       >"$tmp/$label.log" 2>&1; then
    echo "| $label | $cpus | $isa | $dev | failed: $(tail -1 "$tmp/$label.log") | | |"; return
  fi
  t1=${EPOCHREALTIME/./}
  python3 - "$out/summary.json" "$label" "$cpus" "$isa" "$dev" "$t0" "$t1" <<'EOF'
import json, sys
s = json.load(open(sys.argv[1]))
label, cpus, isa, dev, t0, t1 = sys.argv[2:8]
de = s["energy_error"]["max"]
mp = s["digests"]["map"]
print(f"| {label} | {cpus} | {isa} | {dev} | {(int(t1) - int(t0)) / 1e6:.1f} | {de} | {mp} |")
EOF
}

echo "| case | CPUs | kernels | device | whole process s | max abs dE | map digest |"
echo "|---|---|---|---|---|---|---|"
[ -n "$other" ] && run cores "0,$other" x86-64-v4 cpu
[ -n "$sib" ] && run siblings "0,$sib" x86-64-v4 cpu
run one 0 x86-64-v4 cpu
[ -n "$other" ] && run cores-avx2 "0,$other" x86-64-v3 cpu
[ -n "$other" ] && run cores-pocl "0,$other" x86-64-v4 opencl:0
[ -n "$sib" ] && run siblings-pocl "0,$sib" x86-64-v4 opencl:0
exit 0
