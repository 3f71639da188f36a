#!/usr/bin/env bash
# Small N, long time (issue 16 target 7, issue 15 part 7): the per-trajectory
# step rate of Figure 4's schedule (E = 15, Yoshida-6, frames on) at the
# paper's 3.2e4 trajectories against larger N, on each device given, and the
# projected time of the paper's full length (3.2e4 trajectories to 1e7 T).
#   bash bench/gpu/small_n.sh ARNOLDWEB DURATION_T DEVICE...   (DURATION_T: a multiple of 10 T)
# Prints one line per (device, N): seconds, trajectory-steps/s, steps/s per trajectory.
# AW_SMALL_N_SIZES (default "32768 131072 1048576"): the N measured.
set -uo pipefail
aw=$1 duration=$2
shift 2
for dev in "$@"; do
  for n in ${AW_SMALL_N_SIZES:-32768 131072 1048576}; do
    out=$(mktemp -d)/run
    if "$aw" run scenes/fig4_diffusion.toml --quiet --device "$dev" --out "$out" \
         --set ensemble.trajectories=$n --set run.duration="$duration" \
         --set "observe.frames.times=[0, $duration]" --set output.images=false >/dev/null 2>"$out.err"; then
      python3 - "$out/summary.json" "$dev" "$n" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[3]); r = s["trajectory_steps_per_second"]
paper = 32768 * 1e7 / 0.01  # trajectory-steps of the paper's Figure 4 length at h = 0.01 T
line = f"  {sys.argv[2]:9s} N = {n:8d}: {s['wall_seconds']:7.2f} s, {r:.3e} traj-steps/s, {r / n:.3e} steps/s per trajectory"
if n == 32768: line += f"; the paper's length (3.2e4 x 1e7 T) would take {paper / r / 3600:.1f} h"
print(line)
PY
    else
      echo "  $dev N = $n: failed"; tail -3 "$out.err"
    fi
    rm -rf "$(dirname "$out")"
  done
done
