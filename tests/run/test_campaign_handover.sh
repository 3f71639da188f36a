#!/usr/bin/env bash
# The campaign runner's hand-over on the CPU (bench/gpu/campaign.sh; docs/cluster.md, "Campaigns"):
#   tests/run/test_campaign_handover.sh ARNOLDWEB SOURCE_DIR
# 1. `verify`: a small sliced scene in one piece, in slices, and in slices through jobs, each a new
#    process stopped by SIGTERM, its checkpoint packed, accepted and handed over: the same digests,
#    through more than one job.
# 2. Refusals, none changing the campaign folder: a job naming a folder that is no campaign;
#    `accept` refuses a checkpoint damaged on the way back and a job accepted twice; a job refuses
#    a checkpoint whose sha256 is not the ledger's (a byte changed; the ledger's digest changed); a
#    campaign whose values changed after a stop is refused by arnoldweb itself (another scene) and
#    recorded as a failed job.
# 3. A job killed without warning (SIGKILL to its process group, as the device tool at its limit):
#    its cut/ is accepted, and the campaign continued gives the digests of the run in one piece.
# 4. The campaign of part 2, continued to its end, gives the digests of the run in one piece.
# Jobs have a budget of 0 s: SIGTERM at the run's first progress line, so that each stops after a
# slice or so, whatever the machine's speed or load. Exit 77 (skipped) without python3 (the runner
# reads summary.json with it), unless ARNOLDWEB_REQUIRE_CHECKS=1.
set -uo pipefail
AW=$(realpath "$1"); SRC=$2
cd "$SRC" || exit 1
if ! command -v python3 >/dev/null; then
  echo "python3 not found: the campaign runner needs it"
  [ "${ARNOLDWEB_REQUIRE_CHECKS:-0}" = 1 ] && exit 1
  exit 77
fi
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
export AW AW_CAMPAIGN_WORK=$T/work
fail() { echo "FAIL: $*"; exit 1; }
C=bench/gpu/campaign.sh
flip() {  # FILE OFFSET: one byte inverted
  local b; b=$(od -An -tu1 -j "$2" -N1 "$1" | tr -d ' ')
  printf "\\x$(printf %02x $((b ^ 255)))" | dd of="$1" bs=1 seek="$2" conv=notrunc status=none
}
job() {  # N [BUDGET]: one job into $T/out-N
  rm -rf "$T/out-$1"
  OUT=$T/out-$1 AW_JOB_SECONDS=${2:-0} AW_JOB_RESERVE=0 bash $C job "$T/camp" >"$T/job-$1.log" 2>&1
}
snapshot() { (cd "$T/camp" && find . -type f | sort | xargs sha256sum); }

# a sliced scene: 10 slices of 5 T, about a second here
cat >"$T/scene.toml" <<'EOF'
[model]
energy = 15.0
[ensemble]
trajectories = 2048
chunk = 1024
[integrator]
step = 0.02
[run]
average = 1.0
duration = 50.0
slice = 5.0
checkpoint_every = 0.5
[observe]
velocity_map = { nside = 8 }
energy_error = { every = 0.5 }
final_states = true
[output]
images = false
EOF
mkdir -p "$T/camp"
printf 'scene = %s\nset = run.duration=50\nverify_set = run.duration=50\ndevice = cpu\n' "$T/scene.toml" >"$T/camp/campaign.conf"

# ---- 1. verify
OUT=$T/verify AW_VERIFY_JOB_SECONDS=0 bash $C verify "$T/camp" >"$T/verify.log" 2>&1 || { cat "$T/verify.log"; fail "verify"; }
cat "$T/verify.log"
jobs=$(sed -n 's/^verify: IDENTICAL (\([0-9]*\) jobs)$/\1/p' "$T/verify.log")
[ -n "$jobs" ] || fail "verify did not say IDENTICAL"
[ "$jobs" -ge 2 ] || fail "verify's run went through $jobs job: no hand-over was tested"
plain=$(sed -n 's/^in one piece: *//p' "$T/verify.log")

# ---- 2. refusals
OUT=$T/nowhere bash $C job "$T/camp" "$T/no-such-campaign" >"$T/nowhere.log" 2>&1; rc=$?
[ $rc -eq 2 ] && [ ! -e "$T/nowhere" ] || fail "a job naming a folder without campaign.conf: exit $rc, or files written"
job 1 || { cat "$T/job-1.log"; fail "job 1"; }
[ -f "$T/out-1/checkpoint.awck.gz" ] || { cat "$T/job-1.log"; fail "no checkpoint from job 1"; }
before=$(snapshot)
cp -r "$T/out-1" "$T/damaged"
chmod -R u+w "$T/damaged"
flip "$T/damaged/checkpoint.awck.gz" $(( $(stat -c %s "$T/damaged/checkpoint.awck.gz") / 3 ))
if bash $C accept "$T/damaged" >"$T/accept.log" 2>&1; then fail "accept took a checkpoint damaged on the way"; fi
grep -q "damaged on the way" "$T/accept.log" || { cat "$T/accept.log"; fail "accept: no reason given"; }
[ "$(snapshot)" = "$before" ] || fail "a refused accept changed the campaign folder"
bash $C accept "$T/out-1" || fail "accept of job 1"
if bash $C accept "$T/out-1" >"$T/accept.log" 2>&1; then fail "accept took job 1 twice"; fi
grep -q "the ledger's next is job 2" "$T/accept.log" || { cat "$T/accept.log"; fail "accept twice: no reason given"; }
before=$(snapshot)

cp "$T/camp/checkpoint.awck.gz" "$T/good.gz"
flip "$T/camp/checkpoint.awck.gz" $(( $(stat -c %s "$T/good.gz") / 2 ))
job 2; rc=$?
[ $rc -eq 2 ] || fail "a changed checkpoint: exit $rc, not 2"
grep -q "REFUSED" "$T/job-2.log" || fail "a changed checkpoint: no REFUSED in the job's log"
[ "$(ls "$T/out-2")" = job.log ] || fail "a refused job left files: $(ls "$T/out-2")"
cp "$T/good.gz" "$T/camp/checkpoint.awck.gz"

cp "$T/camp/ledger.tsv" "$T/ledger.good"
awk -F'\t' -v OFS='\t' '!/^#/ { $5 = (substr($5, 1, 1) == "0" ? "1" : "0") substr($5, 2) } { print }' \
  "$T/ledger.good" >"$T/camp/ledger.tsv"
job 2; rc=$?
[ $rc -eq 2 ] || fail "a ledger that names another digest: exit $rc, not 2"
cp "$T/ledger.good" "$T/camp/ledger.tsv"
[ "$(snapshot)" = "$before" ] || fail "a refused job changed the campaign folder"

cp "$T/camp/campaign.conf" "$T/conf.good"
echo "set = run.average=5.0" >>"$T/camp/campaign.conf"
job 2; rc=$?
[ $rc -ne 0 ] || fail "a campaign whose values changed after a stop was continued"
bash $C accept "$T/out-2" || fail "accept of the failed job 2"
[ "$(tail -1 "$T/camp/ledger.tsv" | cut -f7)" = failed ] || fail "job 2 is not recorded as failed"
grep -q "another scene" "$T/camp/jobs/002.log" || { cat "$T/camp/jobs/002.log"; fail "job 2: not refused as another scene"; }
cp "$T/conf.good" "$T/camp/campaign.conf"

# ---- 3. a job killed without warning, as the device tool kills a call at its limit (everything at
# once, no SIGTERM): what it kept in cut/ at its last periodic checkpoint is accepted and continued
# to the digests of the same run in one piece
mkdir -p "$T/camp2"
printf 'scene = %s\nset = run.duration=2000\nset = run.slice=50\ndevice = cpu\n' "$T/scene.toml" >"$T/camp2/campaign.conf"
# 2000 T: about 3 s on 2 cores, 6 periodic checkpoints (every 0.5 s)
"$AW" run "$T/scene.toml" --set run.duration=2000 --set run.slice=50 --device cpu --out "$T/plain2" >"$T/plain2.log" 2>&1 ||
  { cat "$T/plain2.log"; fail "the 2000 T run in one piece"; }
plain2=$(python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['digests']; print(' '.join(f'{k}={v}' for k,v in sorted(d.items()) if v and k != 'algorithm'))" "$T/plain2/summary.json")
OUT=$T/out-cut AW_JOB_SECONDS=600 AW_JOB_POLL=0.1 setsid bash $C job "$T/camp2" >"$T/job-cut.log" 2>&1 &
jpid=$!
for _ in $(seq 600); do [ -f "$T/out-cut/cut/job.tgz" ] && break; sleep 0.05; done
kill -KILL -- -"$jpid" 2>/dev/null; wait "$jpid" 2>/dev/null
[ -f "$T/out-cut/cut/job.tgz" ] || { cat "$T/job-cut.log"; fail "no cut/ kept while the run went on"; }
[ ! -e "$T/out-cut/job.tgz" ] || fail "the run ended before the kill: nothing was cut off (a longer run is needed here)"
bash $C accept "$T/out-cut" >"$T/accept-cut.log" 2>&1 || { cat "$T/accept-cut.log"; fail "accept of the job cut off"; }
grep -q "the job was cut off" "$T/accept-cut.log" || { cat "$T/accept-cut.log"; fail "accept did not say the job was cut off"; }
[ "$(tail -1 "$T/camp2/ledger.tsv" | cut -f7)" = stopped ] || fail "the job cut off is not recorded as stopped"
[ -f "$T/camp2/checkpoint.awck.gz" ] || fail "no checkpoint handed over from the job cut off"
m=1
until [ "$(tail -1 "$T/camp2/ledger.tsv" | cut -f7)" = done ] || [ $m -gt 5 ]; do
  rm -rf "$T/out-c$m"
  OUT=$T/out-c$m AW_JOB_SECONDS=600 bash $C job "$T/camp2" >"$T/job-c$m.log" 2>&1 || { cat "$T/job-c$m.log"; fail "job c$m"; }
  [ ! -e "$T/out-c$m/cut" ] || fail "a job that ended as planned left cut/"
  bash $C accept "$T/out-c$m" >/dev/null || fail "accept of job c$m"
  m=$((m + 1))
done
[ "$(tail -1 "$T/camp2/ledger.tsv" | cut -f11)" = "$plain2" ] || fail "cut off and continued: digests $(tail -1 "$T/camp2/ledger.tsv" | cut -f11), in one piece $plain2"

# ---- 4. to the end, through the hand-overs above
n=3
until [ "$(tail -1 "$T/camp/ledger.tsv" | cut -f7)" = done ] || [ $n -gt 30 ]; do
  job $n 600 || { cat "$T/job-$n.log"; fail "job $n"; }
  bash $C accept "$T/out-$n" >/dev/null || fail "accept of job $n"
  n=$((n + 1))
done
bash $C status "$T/camp"
final=$(tail -1 "$T/camp/ledger.tsv" | cut -f11)
[ "$final" = "$plain" ] || fail "the campaign's digests ($final) are not the run's in one piece ($plain)"
[ ! -e "$T/camp/checkpoint.awck.gz" ] || fail "the checkpoint was not consumed at the end"
echo "campaign hand-over: verify through $jobs jobs, refusals, a job cut off and continued, and the refused campaign continued to the run's digests"
