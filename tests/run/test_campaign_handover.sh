#!/usr/bin/env bash
# The campaign runner's hand-over on the CPU (bench/gpu/campaign.sh; docs/cluster.md, "Campaigns"):
#   tests/run/test_campaign_handover.sh ARNOLDWEB SOURCE_DIR
# 1. `verify`: a small sliced scene in one piece, in slices, and in slices through jobs of a
#    third of its time, each a new process stopped by SIGTERM, its checkpoint packed, accepted and
#    handed over: the same digests, and more than one job.
# 2. Refusals, nothing changed by any of them: a job refuses a checkpoint whose sha256 is not the
#    ledger's (a byte changed; the ledger's digest changed); `accept` refuses a checkpoint damaged
#    on the way back and a job accepted twice; a campaign whose values changed after a stop is
#    refused by arnoldweb itself (another scene), recorded as a failed job.
# 3. The campaign of part 2, continued to its end, gives the digests of the run in one piece.
# Exit 77 (skipped) without python3 (the runner reads summary.json with it), unless
# ARNOLDWEB_REQUIRE_CHECKS=1.
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

# a sliced scene of about a second here: its length doubled until the run in one piece takes 1 s
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
d=50
for _ in 1 2 3 4 5; do
  t0=$(date +%s.%N)
  "$AW" run "$T/scene.toml" --quiet --device cpu --set run.duration=$d --out "$T/calibrate" --force >/dev/null || fail "the plain run"
  t=$(awk -v a="$t0" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
  awk -v t="$t" 'BEGIN { exit !(t >= 1) }' && break
  d=$((d * 2))
done
per=$(awk -v t="$t" 'BEGIN { print t / 3 }')
echo "scene: $d T, $t s in one piece; jobs of $per s"
mkdir -p "$T/camp"
printf 'scene = %s\nset = run.duration=%s\nverify_set = run.duration=%s\ndevice = cpu\n' "$T/scene.toml" $d $d >"$T/camp/campaign.conf"

# ---- 1. verify
OUT=$T/verify AW_VERIFY_JOB_SECONDS=$per bash $C verify "$T/camp" >"$T/verify.log" 2>&1 || { cat "$T/verify.log"; fail "verify"; }
cat "$T/verify.log"
jobs=$(sed -n 's/^verify: IDENTICAL (\([0-9]*\) jobs)$/\1/p' "$T/verify.log")
[ -n "$jobs" ] || fail "verify did not say IDENTICAL"
[ "$jobs" -ge 2 ] || fail "verify's run went through $jobs job: no hand-over was tested"
plain=$(sed -n 's/^in one piece: *//p' "$T/verify.log")

# ---- 2. refusals
job() {  # N [BUDGET]: one job into $T/out-N
  rm -rf "$T/out-$1"
  OUT=$T/out-$1 AW_JOB_SECONDS=${2:-$per} AW_JOB_RESERVE=0 bash $C job "$T/camp" >"$T/job-$1.log" 2>&1
}
snapshot() { (cd "$T/camp" && find . -type f | sort | xargs sha256sum); }
job 1 || { cat "$T/job-1.log"; fail "job 1"; }
bash $C accept "$T/out-1" || fail "accept of job 1"
[ -f "$T/camp/checkpoint.awck.gz" ] || fail "no checkpoint after job 1 (it finished within $per s?)"
before=$(snapshot)

cp "$T/camp/checkpoint.awck.gz" "$T/good.gz"
size=$(stat -c %s "$T/good.gz")
printf '\x5a' | dd of="$T/camp/checkpoint.awck.gz" bs=1 seek=$((size / 2)) conv=notrunc status=none
job 2; rc=$?
[ $rc -eq 2 ] || fail "a changed checkpoint: exit $rc, not 2"
grep -q "REFUSED" "$T/job-2.log" || fail "a changed checkpoint: no REFUSED in the job's log"
[ "$(ls "$T/out-2")" = job.log ] || fail "a refused job left files: $(ls "$T/out-2")"
cp "$T/good.gz" "$T/camp/checkpoint.awck.gz"

cp "$T/camp/ledger.tsv" "$T/ledger.good"
awk -F'\t' -v OFS='\t' '!/^#/ { $5 = "0" substr($5, 2) } { print }' "$T/ledger.good" >"$T/camp/ledger.tsv"
job 2; rc=$?
[ $rc -eq 2 ] || fail "a ledger that names another digest: exit $rc, not 2"
cp "$T/ledger.good" "$T/camp/ledger.tsv"
[ "$(snapshot)" = "$before" ] || fail "a refused job changed the campaign folder"

job 2 || { cat "$T/job-2.log"; fail "job 2"; }
cp -r "$T/out-2" "$T/damaged"
size=$(stat -c %s "$T/damaged/checkpoint.awck.gz")
printf '\x5a' | dd of="$T/damaged/checkpoint.awck.gz" bs=1 seek=$((size / 3)) conv=notrunc status=none
if bash $C accept "$T/damaged" >"$T/accept.log" 2>&1; then fail "accept took a checkpoint damaged on the way"; fi
grep -q "damaged on the way" "$T/accept.log" || { cat "$T/accept.log"; fail "accept: no reason given"; }
[ "$(snapshot)" = "$before" ] || fail "a refused accept changed the campaign folder"
bash $C accept "$T/out-2" || fail "accept of job 2"
if bash $C accept "$T/out-2" >"$T/accept.log" 2>&1; then fail "accept took job 2 twice"; fi
grep -q "the ledger's next is job 3" "$T/accept.log" || { cat "$T/accept.log"; fail "accept twice: no reason given"; }

cp "$T/camp/campaign.conf" "$T/conf.good"
echo "set = run.average=5.0" >>"$T/camp/campaign.conf"
job 3; rc=$?
[ $rc -ne 0 ] || fail "a campaign whose values changed after a stop was continued"
bash $C accept "$T/out-3" || fail "accept of the failed job 3"
[ "$(tail -1 "$T/camp/ledger.tsv" | cut -f7)" = failed ] || fail "job 3 is not recorded as failed"
grep -q "another scene" "$T/camp/jobs/003.log" || { cat "$T/camp/jobs/003.log"; fail "job 3: not refused as another scene"; }
cp "$T/conf.good" "$T/camp/campaign.conf"

# ---- 3. to the end, through the hand-overs above
n=4
until [ "$(tail -1 "$T/camp/ledger.tsv" | cut -f7)" = done ] || [ $n -gt 30 ]; do
  job $n 600 || { cat "$T/job-$n.log"; fail "job $n"; }
  bash $C accept "$T/out-$n" >/dev/null || fail "accept of job $n"
  n=$((n + 1))
done
bash $C status "$T/camp"
final=$(tail -1 "$T/camp/ledger.tsv" | cut -f11)
[ "$final" = "$plain" ] || fail "the campaign's digests ($final) are not the run's in one piece ($plain)"
[ ! -e "$T/camp/checkpoint.awck.gz" ] || fail "the checkpoint was not consumed at the end"
echo "campaign hand-over: verify through $jobs jobs, refusals, and the refused campaign continued to the run's digests"
