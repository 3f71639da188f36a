#!/usr/bin/env bash
# A long run as a chain of batch jobs of bounded wall-clock time (issue 41; docs/cluster.md,
# "Campaigns"). A campaign is a folder (bench/gpu/campaigns/NAME/, or any path holding a
# campaign.conf) with the run's scene and --set values, a ledger of the jobs so far and the
# checkpoint the last job left. From the repository root:
#
#   bash bench/gpu/campaign.sh job CAMPAIGN...        one job: the campaigns in turn, each resumed from
#                                                     its checkpoint, until done or the wall-clock budget;
#                                                     what it brings back goes to $OUT
#   bash bench/gpu/campaign.sh accept FILES_AT        (here) checks what a job brought back (digests, the
#                                                     ledger's chain) and moves it into the campaign folders
#   bash bench/gpu/campaign.sh status CAMPAIGN...     the ledger, the checkpoint waiting and its digest
#   bash bench/gpu/campaign.sh verify CAMPAIGN        the shortened check: the campaign's scene with its
#                                                     verify_set values (1/100 of the length) in one piece,
#                                                     in slices, and in slices through jobs stopped by
#                                                     SIGTERM and resumed in new processes: the digests
#                                                     must be equal; verify.txt in $OUT
#
# campaign.conf, one "key = value" a line (# comments; values are not given to a shell):
#   scene = scenes/fig4_diffusion.toml     the scene file, from the repository root
#   set = run.slice=10240                  a --set value (repeatable; the last of a key wins)
#   verify_set = run.duration=100000       --set values added in `verify` only (repeatable)
#   device = cuda:0                        the device (AW_DEVICE overrides)
#   prepare = python3 SCRIPT ARGS...       a command run before each job's run (it makes inputs in {work})
#   inputs = {work}/states.h5              files whose sha256 the first job records and later jobs must match
#   collect = python3 SCRIPT ARGS...       a command run once the run is done (it writes into {result})
#   keep = summary.json frames/*           the outputs brought back when done (globs; default: all)
# In values, {work} is the campaign's work folder on the job's machine, {run} the run's output
# directory, {result} the folder of what comes back, {campaign} the campaign folder.
#
# A job (one device call, or one batch job) builds the program if .device-deps/ is there (the
# GPU machine: bench/gpu/run.sh build), unpacks the campaign's checkpoint and refuses (exit 2)
# when its sha256 is not the one the ledger's last entry recorded, runs `arnoldweb run SCENE
# --resume` (which itself refuses a checkpoint of another scene or other values), and sends
# SIGTERM AW_JOB_SECONDS - AW_JOB_RESERVE seconds after the job began (default 540 - 45; 0: at once; not
# before the run's first progress line, so that its handler is in place and a slice is done): the
# run stops after its current slice and writes its checkpoint; AW_JOB_GRACE (30) seconds after
# that it is killed and the last periodic checkpoint (run.checkpoint_every) is taken. $OUT then
# holds at most 8 files, 15 MiB each: job.log, job.tgz (each campaign's ledger entry, run log
# and, when done, its kept outputs) and checkpoint.awck.gz (split into .00, .01, ... above 15 MiB).
# While a run goes on, each new periodic checkpoint (looked for every AW_JOB_POLL = 2 s) is also
# packed with a provisional entry into $OUT/cut/: a job killed without warning (the device tool at
# its limit kills everything at once) brings that back, and `accept` takes it; a job that ends as
# planned removes cut/.
# Environment: AW (the program; default: built here, else build/arnoldweb), AW_DEVICE,
# AW_CAMPAIGN_WORK (work folders, default /tmp/aw-campaign: the same on every job of a campaign).
set -uo pipefail

PART_BYTES=$((15 * 1024 * 1024))  # under the device tool's 16 MiB a file
WORKROOT=${AW_CAMPAIGN_WORK:-/tmp/aw-campaign}
T0=${EPOCHREALTIME/./}  # microseconds; the clock is read without a process (the job's loop polls it)

die() { echo "campaign: $*" >&2; exit 2; }
us() { echo $(( ${EPOCHREALTIME/./} - T0 )); }                           # microseconds of this job
us_of() { awk -v s="$1" 'BEGIN { printf "%d", s * 1e6 }'; }               # seconds (decimals) in us
sec() { awk -v u="$1" 'BEGIN { printf "%.1f", u / 1e6 }'; }               # us in seconds, 0.1
now() { sec "$(us)"; }
sha_of() { sha256sum | cut -c1-64; }

# ------------------------------------------------------------------ the campaign folder
campaign_dir() {  # NAME or PATH -> the folder holding campaign.conf
  local c=${1%/}
  [ ! -f "$c/campaign.conf" ] && [ -f "bench/gpu/campaigns/$c/campaign.conf" ] && c=bench/gpu/campaigns/$c
  [ -f "$c/campaign.conf" ] || die "$1: no campaign.conf there (a campaign is a folder with campaign.conf; bench/gpu/campaigns/)"
  echo "$c"
}

# read_conf DIR: SCENE, SETS, VERIFY_SETS, DEVICE, PREPARE, INPUTS, COLLECT, KEEP
read_conf() {
  SCENE="" DEVICE=auto PREPARE="" INPUTS="" COLLECT="" KEEP="*"
  SETS=() VERIFY_SETS=()
  local line key value n=0
  while IFS= read -r line || [ -n "$line" ]; do
    n=$((n + 1))
    [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
    [[ $line == *=* ]] || die "$1/campaign.conf, line $n: not \"key = value\": $line"
    key=$(echo "${line%%=*}" | tr -d '[:space:]')
    value=$(echo "${line#*=}" | sed 's/^[[:space:]]*//; s/[[:space:]]*$//')
    case $key in
      scene) SCENE=$value ;;
      set) SETS+=("$value") ;;
      verify_set) VERIFY_SETS+=("$value") ;;
      device) DEVICE=$value ;;
      prepare) PREPARE=$value ;;
      inputs) INPUTS=$value ;;
      collect) COLLECT=$value ;;
      keep) KEEP=$value ;;
      *) die "$1/campaign.conf, line $n: unknown key '$key' (scene, set, verify_set, device, prepare, inputs, collect, keep)" ;;
    esac
  done <"$1/campaign.conf"
  [ -n "$SCENE" ] || die "$1/campaign.conf: no scene = ..."
  [ -f "$SCENE" ] || die "$1/campaign.conf: scene $SCENE: no such file (paths are from the repository root)"
  DEVICE=${AW_DEVICE:-$DEVICE}
}

fill() {  # TEXT: the placeholders replaced
  local s=$1
  s=${s//\{work\}/$WORK}; s=${s//\{run\}/$WORK/run}; s=${s//\{result\}/$WORK/result}; s=${s//\{campaign\}/$CDIR}
  echo "$s"
}

LEDGER_HEADER=$'# job\tdate\tdevice\tfrom\tto\texit\tstate\tseconds\tprogress\tinputs\tnote'
ledger_entries() { awk '!/^#/ && NF { n++ } END { print n + 0 }' "$1/ledger.tsv" 2>/dev/null || echo 0; }
ledger_field() {  # DIR COLUMN: that column of the last entry ("" without entries)
  [ -f "$1/ledger.tsv" ] || return 0
  grep -v '^#' "$1/ledger.tsv" | grep . | tail -1 | cut -f"$2"
}
first_inputs() { [ -f "$1/ledger.tsv" ] && grep -v '^#' "$1/ledger.tsv" | grep . | head -1 | cut -f10; }

checkpoint_parts() {  # DIR: the checkpoint's files, in order (checkpoint.awck.gz or .gz.00, .01, ...)
  local d=$1
  if [ -f "$d/checkpoint.awck.gz" ]; then echo "$d/checkpoint.awck.gz"; else
    ls "$d"/checkpoint.awck.gz.[0-9][0-9] 2>/dev/null; fi
}
checkpoint_sha() {  # DIR: sha256 of the raw checkpoint its parts hold ("" if none, "damaged")
  local parts h
  mapfile -t parts < <(checkpoint_parts "$1")
  [ ${#parts[@]} -gt 0 ] || return 0
  if h=$(cat "${parts[@]}" | gzip -dc 2>/dev/null | sha_of); then echo "$h"; else echo damaged; fi
}

pack() {  # FILE: left as it is up to 15 MiB, else split into FILE.00, FILE.01, ...
  local f=$1
  [ "$(stat -c %s "$f")" -le $PART_BYTES ] && return 0
  split -b $PART_BYTES -d -a 2 "$f" "$f." && rm -f "$f"
}
unpack() {  # DIR NAME: NAME or NAME.00, NAME.01, ... in DIR joined, to stdout
  if [ -f "$1/$2" ]; then cat "$1/$2"; else cat "$1/$2".[0-9][0-9] 2>/dev/null; fi
}

# ------------------------------------------------------------------ job
build_program() {
  [ -n "${AW:-}" ] && return 0
  if [ -f .device-deps/device-setup.sh ]; then
    echo "[$(now) s] build (bench/gpu/run.sh build)"
    # shellcheck disable=SC1091
    source .device-deps/device-setup.sh .device-deps >"$WORKROOT/setup.txt" 2>&1
    if ! OUT="$WORKROOT/build" bash bench/gpu/run.sh build >"$WORKROOT/build.txt" 2>&1; then
      tail -30 "$WORKROOT/build.txt"; die "the build failed"
    fi
    grep -E "^\[|^(cuda|opencl|cpu)" "$WORKROOT/build.txt" | tail -8
    AW=build-gpu/arnoldweb
  else
    AW=build/arnoldweb
  fi
  [ -x "$AW" ] || die "$AW: no program (set AW, or build it)"
}

machine_name() {
  nvidia-smi --query-gpu=name --format=csv,noheader 2>/dev/null | head -1 | tr -d '\t' | grep . ||
    grep -m1 "model name" /proc/cpuinfo | sed 's/.*: //' | tr -d '\t'
}

summary_done() {  # SUMMARY.JSON: exit 0 when the run completed (every trajectory, not interrupted)
  python3 - "$1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
sys.exit(0 if s.get("completed") == s.get("trajectories") and not s.get("interrupted") else 1)
PY
}
digests_of() {  # SUMMARY.JSON: the non-empty digests, one "name=value" a line
  python3 -c "import json,sys; d=json.load(open(sys.argv[1]))['digests']; print(' '.join(f'{k}={v}' for k,v in sorted(d.items()) if v and k != 'algorithm'))" "$1"
}

entry_line() {  # N FROM TO EXIT STATE SECONDS PROGRESS INPUTS NOTE: one ledger entry
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$(date -u +%Y-%m-%dT%H:%M:%SZ)" \
    "$(machine_name) $DEVICE" "$2" "$3" "$4" "$5" "$6" "$7" "$8" "$9"
}
last_progress() { local p; p=$(grep -o 'progress: *[0-9]*%' "$WORK/run.log" | tail -1 | grep -o '[0-9]*%'); echo "${p:--}"; }

# save_cut CHECKPOINT STAGE N FROM INPUTS STARTED: while the run goes on, its newest periodic
# checkpoint and a provisional ledger entry (with the entries of the campaigns this job finished
# before it) into $OUT/cut/, replaced whole at each new checkpoint. A job killed without warning
# (a device call or batch job past its limit: no SIGTERM, everything killed at once) still brings
# back a checkpoint that `accept` takes; a job that ends as planned removes cut/.
save_cut() {
  local ck=$1 stage=$2 n=$3 from=$4 inputs=$5 started=$6 tmp="$OUT/cut.tmp" to note
  rm -rf "$tmp"; mkdir -p "$tmp"
  # the checkpoint is renamed into place whole (atomic_file): a copy is one checkpoint
  cp "$ck" "$tmp/checkpoint.awck" 2>/dev/null || { rm -rf "$tmp"; return 0; }
  to=$(sha_of <"$tmp/checkpoint.awck")
  if [ "$to" = "$from" ]; then rm -rf "$tmp"; return 0; fi
  gzip -n -6 -c "$tmp/checkpoint.awck" >"$tmp/checkpoint.awck.gz"
  note="cut off: the job was killed without warning; its last periodic checkpoint, $(stat -c %s "$tmp/checkpoint.awck") bytes, $(stat -c %s "$tmp/checkpoint.awck.gz") gzipped"
  rm -f "$tmp/checkpoint.awck"
  pack "$tmp/checkpoint.awck.gz"
  entry_line "$n" "$from" "$to" 137 stopped "$(sec $(( $(us) - started )))" "$(last_progress)" "$inputs" "$note" >"$stage/entry.tsv"
  cp "$WORK/run.log" "$stage/run.log"
  tar czf "$tmp/job.tgz" -C "$STAGE" . && pack "$tmp/job.tgz" || { rm -rf "$tmp"; return 0; }
  rm -rf "$OUT/cut"; mv "$tmp" "$OUT/cut"
  echo "[$(now) s] $CDIR: periodic checkpoint at $(last_progress) kept in \$OUT/cut (taken if the job is cut off)"
}

# run_one KEY: one campaign's part of the job. Sets STATE (done, stopped, failed, refused).
run_one() {
  CDIR=$1
  read_conf "$CDIR"
  local n from to rc state progress inputs="-" note="" started seconds
  n=$(( $(ledger_entries "$CDIR") + 1 ))
  if [ "$(ledger_field "$CDIR" 7)" = "done" ]; then echo "campaign $CDIR: done (ledger entry $((n - 1))); nothing to do"; STATE=skipped; return 0; fi
  WORK="$WORKROOT/$(echo "$CDIR" | tr '/' '_' | sed 's/^_*//')"
  rm -rf "$WORK"; mkdir -p "$WORK/result"
  from=$(ledger_field "$CDIR" 5); [ -n "$from" ] || from=-

  # the inputs this job makes, and the checkpoint handed over: both must be the ledger's
  if [ -n "$PREPARE" ]; then
    local argv; read -r -a argv <<<"$(fill "$PREPARE")"
    echo "[$(now) s] $CDIR: prepare: ${argv[*]}"
    "${argv[@]}" >"$WORK/prepare.log" 2>&1 || { cat "$WORK/prepare.log"; STATE=failed; echo "campaign $CDIR: prepare failed"; return 1; }
  fi
  if [ -n "$INPUTS" ]; then
    local files; read -r -a files <<<"$(fill "$INPUTS")"
    inputs=$(cat "${files[@]}" | sha_of) || { STATE=failed; return 1; }
    local pinned; pinned=$(first_inputs "$CDIR")
    if [ -n "$pinned" ] && [ "$pinned" != "-" ] && [ "$pinned" != "$inputs" ]; then
      echo "campaign $CDIR: REFUSED: the inputs made now (sha256 $inputs) are not those of job 1 ($pinned)" >&2
      STATE=refused; return 2
    fi
  fi
  local cmd=(run "$SCENE")
  for s in "${SETS[@]}"; do cmd+=(--set "$(fill "$s")"); done
  cmd+=(--out "$WORK/run" --device "$DEVICE")
  if [ "$from" != - ]; then
    local got; got=$(checkpoint_sha "$CDIR")
    if [ "$got" != "$from" ]; then
      echo "campaign $CDIR: REFUSED: the checkpoint in $CDIR has sha256 ${got:-(none)}, the ledger's last entry (job $((n - 1))) recorded $from; not continuing from it" >&2
      STATE=refused; return 2
    fi
    # a staging directory of a process that cannot be running (pid 0): arnoldweb adopts it
    mkdir -p "$WORK/run.partial-0"
    local parts; mapfile -t parts < <(checkpoint_parts "$CDIR")
    cat "${parts[@]}" | gzip -dc >"$WORK/run.partial-0/checkpoint.awck"
    echo "arnoldweb staging directory (campaign.sh: the checkpoint of job $((n - 1)))" >"$WORK/run.partial-0/.arnoldweb-staging"
    cmd+=(--resume)
    echo "[$(now) s] $CDIR: job $n resumes from the checkpoint of job $((n - 1)) (sha256 $from: as the ledger says)"
  else
    echo "[$(now) s] $CDIR: job $n starts the run"
  fi

  local stage="$STAGE/$((++CAMPAIGNS_TOUCHED))"  # from here on the job records an entry
  mkdir -p "$stage"
  echo "$CDIR" >"$stage/campaign"
  started=$(us)
  local cut_stamp="" cut_next=0 ck
  ck=$(ls -t "$WORK"/run.partial-*/checkpoint.awck 2>/dev/null | head -1)
  [ -n "$ck" ] && cut_stamp=$(stat -c '%i %.9Y' "$ck")  # the adopted one: nothing new
  "$AW" "${cmd[@]}" >"$WORK/run.log" 2>&1 &
  local pid=$! termed="" killed="" going=""
  while kill -0 "$pid" 2>/dev/null; do
    # SIGTERM once the budget is spent and the run has reported progress (its signal handler is
    # in place and a slice is done: every job moves the campaign on), or GRACE s later regardless
    [ -z "$going" ] && grep -q '^progress:' "$WORK/run.log" && going=1
    if [ -z "$termed" ] && [ "$(us)" -ge "$TERM_AT" ] && { [ -n "$going" ] || [ "$(us)" -ge $((TERM_AT + GRACE)) ]; }; then
      echo "[$(now) s] $CDIR: the job's budget is spent: SIGTERM (stop after the current slice, keep it)"
      kill -TERM "$pid" 2>/dev/null; termed=$(us)
    elif [ -n "$termed" ] && [ -z "$killed" ] && [ "$(us)" -ge $((termed + GRACE)) ]; then
      echo "[$(now) s] $CDIR: still running $(sec "$GRACE") s after SIGTERM: SIGKILL (the last periodic checkpoint stays)"
      kill -KILL "$pid" 2>/dev/null; killed=1
    fi
    if [ -z "$termed" ] && [ "$(us)" -ge "$cut_next" ]; then
      cut_next=$(( $(us) + POLL ))
      ck=$(ls -t "$WORK"/run.partial-*/checkpoint.awck 2>/dev/null | head -1)
      if [ -n "$ck" ] && [ "$(stat -c '%i %.9Y' "$ck" 2>/dev/null)" != "$cut_stamp" ]; then
        cut_stamp=$(stat -c '%i %.9Y' "$ck" 2>/dev/null)
        save_cut "$ck" "$stage" "$n" "$from" "$inputs" "$started"
      fi
    fi
    sleep 0.05
  done
  wait "$pid"; rc=$?
  seconds=$(sec $(( $(us) - started )))
  progress=$(last_progress)
  tail -4 "$WORK/run.log" | sed "s|^|  $CDIR: |"

  to=-
  if [ -f "$WORK/run/summary.json" ] && summary_done "$WORK/run/summary.json"; then
    state="done"; progress=100%
    note=$(digests_of "$WORK/run/summary.json")
    if [ -n "$COLLECT" ]; then
      local argv; read -r -a argv <<<"$(fill "$COLLECT")"
      echo "[$(now) s] $CDIR: collect: ${argv[*]}"
      "${argv[@]}" >"$WORK/collect.log" 2>&1 || { cat "$WORK/collect.log"; note="$note collect-failed"; }
      cat "$WORK/collect.log" >>"$WORK/run.log"
    fi
    (cd "$WORK/run" && for f in $KEEP; do [ -e "$f" ] && cp -r --parents "$f" "$WORK/result/"; done)
    cp -r "$WORK/result" "$stage/result"
    rm -rf "$CDIR/result"; cp -r "$WORK/result" "$CDIR/result"  # for the campaigns after it in this job
  else
    # the newest checkpoint beside the run (the one it adopted and rewrote; or, after SIGKILL,
    # the last periodic one)
    local ck; ck=$(ls -t "$WORK"/run.partial-*/checkpoint.awck 2>/dev/null | head -1)
    [ -n "$ck" ] && to=$(sha_of <"$ck")
    if [ -n "$ck" ] && [ "$to" != "$from" ]; then
      state=stopped
      gzip -n -6 -c "$ck" >"$OUT/checkpoint.awck.gz"
      note="checkpoint $(stat -c %s "$ck") bytes, $(stat -c %s "$OUT/checkpoint.awck.gz") gzipped"
      pack "$OUT/checkpoint.awck.gz"
    else
      to=$from; state=failed
      note="exit $rc without a new checkpoint (the run's log says why): the state stays that of job $((n - 1))"
    fi
  fi
  entry_line "$n" "$from" "$to" "$rc" "$state" "$seconds" "$progress" "$inputs" "$note" >"$stage/entry.tsv"
  cp "$WORK/run.log" "$stage/run.log"
  echo "[$(now) s] $CDIR: job $n: $state (exit $rc, $seconds s, progress $progress) $note"
  STATE=$state
  [ "$state" != failed ]
}

cmd_job() {
  [ $# -gt 0 ] || die "job: name at least one campaign"
  local dirs=() c
  for c in "$@"; do dirs+=("$(campaign_dir "$c")") || exit 2; done
  OUT=${OUT:-$PWD/campaign-out}
  mkdir -p "$OUT" "$WORKROOT"
  ! ls "$OUT"/job.log "$OUT"/job.tgz* "$OUT"/checkpoint.awck.gz* >/dev/null 2>&1 ||
    die "$OUT holds another job's files (job.log, job.tgz, checkpoint.awck.gz): one job a folder"
  exec > >(tee "$OUT/job.log") 2>&1
  local budget=${AW_JOB_SECONDS:-540} reserve=${AW_JOB_RESERVE:-45}
  GRACE=$(us_of "${AW_JOB_GRACE:-30}") POLL=$(us_of "${AW_JOB_POLL:-2}")
  TERM_AT=$(us_of "$(awk -v b="$budget" -v r="$reserve" 'BEGIN { print (b > r ? b - r : 0) }')")
  local start_until=$((TERM_AT - (TERM_AT > 60000000 ? 30000000 : 0)))  # a campaign after the first needs 30 s
  echo "campaign job: ${dirs[*]}; SIGTERM at $(sec "$TERM_AT") s of the job (AW_JOB_SECONDS=$budget, AW_JOB_RESERVE=$reserve)"
  build_program
  STAGE=$(mktemp -d); CAMPAIGNS_TOUCHED=0; STATE=""
  trap 'rm -rf "$STAGE"' EXIT
  local rc=0
  for c in "${dirs[@]}"; do
    if [ "$CAMPAIGNS_TOUCHED" -gt 0 ] && [ "$(us)" -ge "$start_until" ]; then
      echo "[$(now) s] too little time left to start $c: for the next job"; break
    fi
    run_one "$c"; rc=$?
    [ "$STATE" = "done" ] || [ "$STATE" = skipped ] || break
  done
  if [ "$CAMPAIGNS_TOUCHED" -gt 0 ]; then
    tar czf "$OUT/job.tgz" -C "$STAGE" . && pack "$OUT/job.tgz"
  fi
  rm -rf "$OUT/cut" "$OUT/cut.tmp"  # the job ended as planned: job.tgz says what it did
  local files; files=$(ls "$OUT" | wc -l)
  [ "$files" -le 8 ] || echo "WARNING: $files files in $OUT: the device tool brings back 8"
  echo "[$(now) s] job over: $(ls "$OUT" | tr '\n' ' ')"
  [ "$STATE" = refused ] && exit 2
  exit "$rc"
}

# ------------------------------------------------------------------ accept
cmd_accept() {
  local from=${1:?accept: name the folder of what came back (files_at of the device tool)}
  [ -d "$from" ] || die "$from: no such folder"
  STAGE=$(mktemp -d)
  trap 'rm -rf "$STAGE"' EXIT
  local stage=$STAGE
  if ! ls "$from"/job.tgz* >/dev/null 2>&1 && ls "$from"/cut/job.tgz* >/dev/null 2>&1; then
    echo "accept: $from holds no job.tgz but cut/: the job was cut off; taking what it kept at its last periodic checkpoint"
    from=$from/cut
  fi
  if ! ls "$from"/job.tgz* >/dev/null 2>&1; then echo "accept: no job.tgz in $from: the job touched no campaign (see $from/job.log)"; return 1; fi
  unpack "$from" job.tgz | tar xzf - -C "$stage" || die "$from/job.tgz: damaged"
  local e dir n last entry job efrom eto state newck=""
  # every check first; nothing is moved unless all pass
  for e in "$stage"/*/; do
    dir=$(cat "$e/campaign"); entry=$(cat "$e/entry.tsv")
    [ -f "$dir/campaign.conf" ] || die "$dir: the job's campaign is not here"
    job=$(cut -f1 <<<"$entry"); efrom=$(cut -f4 <<<"$entry"); eto=$(cut -f5 <<<"$entry"); state=$(cut -f7 <<<"$entry")
    n=$(( $(ledger_entries "$dir") + 1 ))
    last=$(ledger_field "$dir" 5); [ -n "$last" ] || last=-
    [ "$job" = "$n" ] || die "$dir: the job's entry is job $job, the ledger's next is job $n (accepted already, or another job came first)"
    [ "$efrom" = "$last" ] || die "$dir: the job started from checkpoint $efrom, the ledger's last is $last: not this campaign's chain"
    if [ "$state" = stopped ] && [ "$eto" != "$efrom" ]; then
      local got; got=$(unpack "$from" checkpoint.awck.gz | gzip -dc 2>/dev/null | sha_of)
      [ "$got" = "$eto" ] || die "$dir: the checkpoint that came back has sha256 ${got:-(none)}, the job recorded $eto: damaged on the way; not accepted"
      newck=$dir
    fi
  done
  for e in "$stage"/*/; do
    dir=$(cat "$e/campaign"); entry=$(cat "$e/entry.tsv")
    job=$(cut -f1 <<<"$entry"); state=$(cut -f7 <<<"$entry")
    [ -f "$dir/ledger.tsv" ] || echo "$LEDGER_HEADER" >"$dir/ledger.tsv"
    mkdir -p "$dir/jobs"
    cp "$e/run.log" "$dir/jobs/$(printf %03d "$job").log"
    if [ "$dir" = "$newck" ]; then
      rm -f "$dir"/checkpoint.awck.gz "$dir"/checkpoint.awck.gz.[0-9][0-9]
      cp "$from"/checkpoint.awck.gz* "$dir/"
      chmod u+w "$dir"/checkpoint.awck.gz*
    fi
    if [ "$state" = "done" ]; then
      rm -f "$dir"/checkpoint.awck.gz "$dir"/checkpoint.awck.gz.[0-9][0-9]  # consumed
      rm -rf "$dir/result"; cp -r "$e/result" "$dir/result"; chmod -R u+w "$dir/result"
    fi
    echo "$entry" >>"$dir/ledger.tsv"
    echo "accepted $dir: job $job, $state ($(cut -f8 <<<"$entry") s, progress $(cut -f9 <<<"$entry")) $(cut -f11 <<<"$entry")"
  done
  [ -z "$newck" ] || [ "$(checkpoint_sha "$newck")" = "$(ledger_field "$newck" 5)" ] || die "$newck: the checkpoint moved in does not match its entry"
  echo "commit: git add <campaign>/ledger.tsv <campaign>/jobs <campaign>/result (and the checkpoint at a session's end: docs/cluster.md)"
}

# ------------------------------------------------------------------ status
cmd_status() {
  local c dir
  for c in "$@"; do
    dir=$(campaign_dir "$c") || exit 2
    echo "== $dir: $(ledger_entries "$dir") job(s)"
    [ -f "$dir/ledger.tsv" ] && awk -F'\t' '{ printf "  %-5s %-21s %-5s %-8s %-8s %-9s %-13.12s %s\n", $1, $2, $6, $7, $8, $9, $5, $11 }' "$dir/ledger.tsv"
    local want got; want=$(ledger_field "$dir" 5)
    if [ "$(ledger_field "$dir" 7)" = "done" ]; then echo "done: $(ledger_field "$dir" 11)"
    elif [ -n "$want" ] && [ "$want" != - ]; then
      got=$(checkpoint_sha "$dir")
      if [ "$got" = "$want" ]; then echo "checkpoint waiting: sha256 $got, as the ledger says: the next job resumes it"
      else echo "checkpoint: sha256 ${got:-(none)} is NOT the ledger's $want: a job would refuse it"; fi
    else echo "not started"; fi
  done
}

# ------------------------------------------------------------------ verify
cmd_verify() {
  local dir; dir=$(campaign_dir "${1:?verify: name the campaign}") || exit 2
  read_conf "$dir"
  [ ${#VERIFY_SETS[@]} -gt 0 ] || die "$dir/campaign.conf: no verify_set lines (the shortened run: e.g. run.duration at 1/100)"
  OUT=${OUT:-$PWD/campaign-out}
  mkdir -p "$OUT" "$WORKROOT"
  local W="$WORKROOT/verify"
  rm -rf "$W"; mkdir -p "$W"
  exec > >(tee "$OUT/verify.txt") 2>&1
  build_program
  export AW
  local sets=() s
  for s in "${SETS[@]}" "${VERIFY_SETS[@]}"; do sets+=(--set "$s"); done
  echo "verify $dir: $SCENE ${sets[*]} on $DEVICE"
  local t0 tsliced
  "$AW" run "$SCENE" "${sets[@]}" --set run.slice=0 --set run.checkpoint_every=off --quiet --device "$DEVICE" --out "$W/plain" ||
    die "the run in one piece failed"
  t0=$(us)
  "$AW" run "$SCENE" "${sets[@]}" --set run.checkpoint_every=off --quiet --device "$DEVICE" --out "$W/sliced" ||
    die "the sliced run failed"
  tsliced=$(sec $(( $(us) - t0 )))
  # the same through jobs: a copy of the campaign with the shortened values, each job a new
  # process given a third of the sliced run's time, its checkpoint packed, accepted, handed over
  local camp="$W/campaign"; mkdir -p "$camp"
  { echo "scene = $SCENE"; for s in "${SETS[@]}" "${VERIFY_SETS[@]}"; do echo "set = $s"; done; echo "device = $DEVICE"; } >"$camp/campaign.conf"
  local per=${AW_VERIFY_JOB_SECONDS:-$(awk -v t="$tsliced" 'BEGIN { v = t / 3; print (v < 1 ? 1 : v) }')}
  local jobs=0
  while [ "$(ledger_field "$camp" 7)" != "done" ] && [ $jobs -lt 40 ]; do
    jobs=$((jobs + 1))
    OUT="$W/out-$jobs" AW_CAMPAIGN_WORK="$W/work" AW_JOB_SECONDS=$per AW_JOB_RESERVE=0 \
      bash "$0" job "$camp" >"$W/job-$jobs.txt" 2>&1
    local jrc=$?
    [ $jrc -eq 0 ] || { cat "$W/job-$jobs.txt"; die "job $jobs failed (exit $jrc)"; }
    bash "$0" accept "$W/out-$jobs" >>"$W/job-$jobs.txt" 2>&1 || { cat "$W/job-$jobs.txt"; die "accept of job $jobs failed"; }
  done
  [ "$(ledger_field "$camp" 7)" = "done" ] || die "the run through jobs did not finish in $jobs jobs"
  local a b c
  a=$(digests_of "$W/plain/summary.json"); b=$(digests_of "$W/sliced/summary.json"); c=$(digests_of "$camp/result/summary.json")
  echo "in one piece:                       $a"
  echo "in slices, one process:             $b"
  echo "in slices through $jobs jobs ($per s each): $c"
  cut -f1,6,7,8,9 "$camp/ledger.tsv" | sed 's/^/  /'
  if [ -n "$a" ] && [ "$a" = "$b" ] && [ "$a" = "$c" ]; then echo "verify: IDENTICAL ($jobs jobs)"; else echo "verify: DIFFER"; exit 1; fi
}

case ${1:-} in
  job) shift; cmd_job "$@" ;;
  accept) shift; cmd_accept "$@" ;;
  status) shift; cmd_status "$@" ;;
  verify) shift; cmd_verify "$@" ;;
  *) sed -n '2,20p' "$0"; exit 2 ;;
esac
