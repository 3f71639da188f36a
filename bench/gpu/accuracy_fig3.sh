#!/usr/bin/env bash
# Accuracy for less on the GPU (issue 16 target 5, issue 18 part 5): the cheapest method and step
# for the Figure-3 ensemble (scenes/fig3_e15.toml panel a: E = 15, 1e8 trajectories x 50 T,
# nside 256) at max|dE| <= TARGET, and what integrator.step = "auto" chooses, each timed end to end.
#
#   bash bench/gpu/accuracy_fig3.sh ARNOLDWEB DEVICE OUTDIR [TARGETS] [METHODS]
#
# 1. ladder: every method at steps T/n (n from 50 up, ratio ~1.25) on 1e7 of the trajectories
#    (the first 1e7 of the same ensemble: seed and indices as in the full run) until max|dE| <=
#    TARGET/2 (the full ensemble's maximum lies above the tenth's), one row per run in ladder.csv;
# 2. full: the three cheapest (by the ladder's time) at their step on the whole 1e8, timed;
# 3. auto: the whole 1e8 with integrator.step = "auto", integrator.tolerance = TARGET (the pilot
#    runs on the cpu backend of the host, inside make_plan) and the method left to the pilot;
#    its pilot time is in summary.json (auto_step.pilot_seconds); every run is also timed as a
#    process (device open, kernel compile or cache, pilot, run, outputs).
# Every run writes its summary.json; a table goes to stdout.
set -uo pipefail
AW=$1; DEV=$2; OUT=$3
TARGETS=${4:-1e-8}
METHODS=${5:-yoshida6a:200,srkn11b,aba864,aba1064,sbab3c:400,sbab4c:400,saba4c:400,chin4a:640}  # name[:first T/n]
LADDER_N=${LADDER_N:-10000000}  # the ladder's ensemble (environment; a tenth of Figure 3)
FULL_N=${FULL_N:-100000000}     # the whole Figure 3
mkdir -p "$OUT"
W=/tmp/aw-acc
rm -rf "$W"; mkdir -p "$W"
# panel (a) alone, and the same without integrator.method (so that the pilot chooses it)
sed '/^\[\[panel\]\]/,$d' scenes/fig3_e15.toml >"$W/fig3a.toml"
sed '/^method = /d' "$W/fig3a.toml" >"$W/fig3a_open.toml"
SCENE=$W/fig3a.toml
common=(--quiet --device "$DEV" --set output.images=false)

# run NAME TRAJECTORIES SETS... -> prints "max_dE run_wall_s rate method auto_step pilot_s process_wall_s"
run() {
  local name=$1 n=$2; shift 2
  rm -rf "$W/$name"
  local t0; t0=$(date +%s.%N)
  if "$AW" run "$SCENE" "${common[@]}" --out "$W/$name" --set ensemble.trajectories="$n" "$@" \
       >"$W/$name.log" 2>&1; then
    python3 - "$W/$name/summary.json" "$t0" "$(date +%s.%N)" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
a = s.get("auto_step") or {}
print(f'{s["energy_error"]["max"]:.3e} {s["wall_seconds"]:.3f} {s["trajectory_steps_per_second"]:.3e} '
      f'{s["method"]["name"]} {a.get("step", 0)} {a.get("pilot_seconds", 0):.3f} '
      f'{float(sys.argv[3]) - float(sys.argv[2]):.3f}')
PY
  else
    echo "fail"; tail -3 "$W/$name.log" >&2
  fi
}

for target in ${TARGETS//,/ }; do
  echo "== target max|dE| <= $target: ladder on $LADDER_N trajectories x 50 T, $DEV"
  echo "method,steps_per_T,trajectories,max_dE,wall_s,traj_steps_per_s" >"$OUT/ladder_$target.csv"
  : >"$W/best_$target.txt"
  for spec in ${METHODS//,/ }; do
    m=${spec%%:*}; first=64; [ "$spec" != "$m" ] && first=${spec#*:}
    for n in 50 64 80 100 128 160 200 256 320 400 512 640 800 1024 1280 1600; do
      [ "$n" -lt "$first" ] && continue
      r=$(run "l_${m}_$n" "$LADDER_N" --set integrator.method="\"$m\"" --set integrator.step="$(python3 -c "print(1/$n)")")
      [ "$r" = fail ] && { echo "  $m T/$n: failed"; break; }
      set -- $r
      echo "$m,$n,$LADDER_N,$1,$2,$3" >>"$OUT/ladder_$target.csv"
      printf "  %-9s T/%-4d max|dE| %s  %6.2f s  %s traj-steps/s\n" "$m" "$n" "$1" "$2" "$3"
      if python3 -c "import sys; sys.exit(0 if $1 <= $target / 2 else 1)"; then
        echo "$2 $m $n" >>"$W/best_$target.txt"; break
      fi
    done
  done
  echo "== the three cheapest on $FULL_N trajectories (scene as written otherwise)"
  echo "method,steps_per_T,trajectories,max_dE,wall_s,traj_steps_per_s" >"$OUT/full_$target.csv"
  sort -g "$W/best_$target.txt" | head -3 | while read -r _ m n; do
    r=$(run "f_${m}_$n" "$FULL_N" --set integrator.method="\"$m\"" --set integrator.step="$(python3 -c "print(1/$n)")")
    [ "$r" = fail ] && { echo "  $m T/$n: failed"; continue; }
    set -- $r
    echo "$m,$n,$FULL_N,$1,$2,$3" >>"$OUT/full_$target.csv"
    printf "  %-9s T/%-4d max|dE| %s  run %6.2f s, process %6.2f s (meets: %s)\n" "$m" "$n" "$1" "$2" "$7" \
      "$(python3 -c "print('yes' if $1 <= $target else 'NO')")"
  done
  echo "== integrator.step = \"auto\", tolerance $target, method chosen by the pilot, $FULL_N trajectories"
  SCENE=$W/fig3a_open.toml
  r=$(run "auto_$target" "$FULL_N" --set integrator.step='"auto"' --set integrator.tolerance="$target")
  SCENE=$W/fig3a.toml
  if [ "$r" != fail ]; then
    set -- $r
    echo "auto:$4,$5,$FULL_N,$1,$2,$3,pilot_s=$6,process_s=$7" >>"$OUT/full_$target.csv"
    printf "  auto: %s at h = %s T, max|dE| %s, run %6.2f s, pilot %s s, process %6.2f s\n" "$4" "$5" "$1" "$2" "$6" "$7"
  fi
done
cp "$W"/*.log "$OUT/" 2>/dev/null
true
