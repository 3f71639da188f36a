#!/usr/bin/env bash
# What an expression model's cpu kernel costs to compile at run time (issue 25,
# item 5; docs/models.md): the paper's potential as model.kind = "expression"
# on --device cpu, a tiny run (1000 trajectories x 5 T) with an empty disk
# cache (the kernel is compiled), then again (read from the disk cache), for
# double and float. The difference of the two process times is the compile.
#   bench/expression/cpu_compile.sh [BIN] [REPEATS]   (defaults: build/arnoldweb 3)
set -euo pipefail
bin=${1:-build/arnoldweb}
repeats=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(scenes/default.toml --quiet --device cpu --set 'model.kind="expression"'
      --set 'model.potential="cos(x)*cos(y)*(1 + cos(2*z))"' --set ensemble.trajectories=1000
      --set run.average=5 --set run.duration=5 --set output.images=false)
seconds() {  # cache-dir out extra...: the process's wall seconds, then the kernel's origin
  local cache=$1 out=$2 t0 t1
  shift 2
  t0=$(date +%s.%N)
  ARNOLDWEB_CACHE_DIR=$cache "$bin" run "${args[@]}" "$@" --out "$out" >/dev/null
  t1=$(date +%s.%N)
  python3 -c 'import json,sys; k=json.load(open(sys.argv[1]))["kernel"]; print(f"{float(sys.argv[3])-float(sys.argv[2]):.2f}", k[k.rfind(";")+2:-1])' \
    "$out/summary.json" "$t0" "$t1"
}
echo "compiler: $(c++ --version | head -1); $(date -u +%F); load average $(cut -d' ' -f1-3 /proc/loadavg)"
for precision in double float; do
  for i in $(seq 1 "$repeats"); do
    cache="$work/cache-$precision-$i"
    cold=$(seconds "$cache" "$work/cold-$precision-$i" --set "integrator.precision=\"$precision\"")
    warm=$(seconds "$cache" "$work/warm-$precision-$i" --set "integrator.precision=\"$precision\"")
    echo "$precision run $i: cold ${cold% *} s (${cold#* }), warm ${warm% *} s (${warm#* }), compile $(python3 -c "print(f'{${cold% *} - ${warm% *}:.2f}')") s"
  done
done
