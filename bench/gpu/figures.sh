#!/usr/bin/env bash
# The paper's Figures 2-4 at the paper's N on the GPU machine (device tool):
#   [FIGS="fig3_e15 ..."] bash bench/gpu/figures.sh [device]   (default: all three, cuda:0)
# Builds if build-gpu/ is missing (as bench/gpu/run.sh does), runs every
# figure scene with timing, and packs each output directory (summary.json,
# map.h5, panels; no pictures: the image has no cairo) into $OUT/figN.tgz.
# Draw the pictures afterwards: `arnoldweb render out/fig3` (docs/gallery.md).
set -uo pipefail
device=${1:-cuda:0}
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT"
t0=$(date +%s)
stamp() { echo "[$(( $(date +%s) - t0 )) s] $*"; }
if [ ! -x build-gpu/arnoldweb ]; then
  source .device-deps/device-setup.sh .device-deps >/dev/null 2>&1
  export PKG_CONFIG_PATH=/opt/device-deps/usr/lib/x86_64-linux-gnu/pkgconfig:${PKG_CONFIG_PATH:-}
  export PATH=/usr/local/cuda/bin:$PATH
  stamp "configure and build"
  cmake -S . -B build-gpu -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUDAToolkit_ROOT=/usr/local/cuda \
    -DARNOLDWEB_TESTS=OFF -DARNOLDWEB_BENCH=OFF >/dev/null || exit 1
  cmake --build build-gpu -j"$(nproc)" --target arnoldweb-cli >/dev/null || exit 1
fi
build-gpu/arnoldweb devices
mkdir -p figs
echo "figure,device,trajectories,wall_seconds,trajectory_steps_per_second,energy_error_max,binned,map_digest" > "$OUT/figures.csv"
for fig in ${FIGS:-fig3_e15 fig2_e400 fig4_diffusion}; do
  stamp "$fig on $device"
  start=$SECONDS
  build-gpu/arnoldweb run "scenes/$fig.toml" --device "$device" --out "figs/$fig" --force --quiet || echo "$fig FAILED"
  echo "$fig: $((SECONDS - start)) s end to end"
  for s in "figs/$fig/summary.json" figs/"$fig"/panel-*/summary.json; do
    [ -f "$s" ] && python3 - "$s" "$fig" >> "$OUT/figures.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
name = sys.argv[2] + ("/" + sys.argv[1].split("/")[-2] if "panel-" in sys.argv[1] else "")
print(f"{name},{s['device']['name']},{s['trajectories']},{s['wall_seconds']:.2f},"
      f"{s['trajectory_steps_per_second']:.4g},{s['energy_error'].get('max', 0):.3g},{s['binned']},{s['digests']['map']}")
PY
  done
  tar czf "$OUT/$fig.tgz" -C figs "$fig"
  ls -la "$OUT/$fig.tgz"
done
stamp "done"
cat "$OUT/figures.csv"
