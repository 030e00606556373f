#!/usr/bin/env bash
# make test-slurm: proves that a 2-shard Slurm job array plus `silva merge` writes the same
# dataset, byte for byte (run*.json and the card's CARD.md and card.json aside, they quote run.json's
# timings), as one single-process `silva generate`.
# Sets up a throw-away single-node Slurm cluster on this machine (Debian bookworm; root,
# or sudo when not root): installs munge + slurmctld + slurmd + slurm-client when missing,
# starts munged if none answers, starts slurmctld and slurmd with a private slurm.conf
# (no systemd, no cgroups), and stops every daemon it started on every exit path.
# Builds nothing: expects the silva binary at ${SILVA:-build/silva} (`make test-slurm`
# builds it first). Re-runnable: each run starts from an empty ${SLURM_TEST_DIR}.
#   SILVA               silva binary                               [build/silva]
#   SLURM_TEST_DIR      scratch folder, emptied at start           [${TMPDIR:-/tmp}/silva-test-slurm]
#   SLURM_TEST_TIMEOUT  seconds allowed for each phase (start, single run, Slurm jobs) [900]
#   SLURM_TEST_PORTS    slurmctld and slurmd ports                 ["6817 6818"]
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ "$(id -u)" -ne 0 ]; then
  exec sudo -E bash "${BASH_SOURCE[0]}" "$@"
fi

SILVA="${SILVA:-build/silva}"
TEST_DIR="${SLURM_TEST_DIR:-${TMPDIR:-/tmp}/silva-test-slurm}"
TIMEOUT="${SLURM_TEST_TIMEOUT:-900}"
read -r CTLD_PORT SLURMD_PORT <<<"${SLURM_TEST_PORTS:-6817 6818}"
SEED=20240607
SHARDS=2
NODE="$(hostname -s)"

say() { echo "test-slurm: $*" >&2; }
fail() {
  echo "test-slurm: FAIL: $*"
  echo "test-slurm: 0 passed, 1 failed"
  exit 1
}

# ---- packages -------------------------------------------------------------------------
install_missing_packages() {
  local missing=() p status
  for p in munge slurmctld slurmd slurm-client; do
    status="$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)"
    [ "$status" = "installed" ] || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  say "installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q >&2
  apt-get install -y -q --no-install-recommends "${missing[@]}" >&2
}

# ---- daemons --------------------------------------------------------------------------
STARTED_PIDS=()   # daemons this run started, stopped in reverse order on exit
JOBS=()           # Slurm jobs this run submitted, cancelled on exit if still queued

# Stops a process if it still runs: TERM, then KILL after 10 s.
stop_pid() {
  local pid="$1" i
  kill -0 "$pid" 2>/dev/null || return 0
  kill -TERM "$pid" 2>/dev/null || true
  for i in $(seq 50); do
    kill -0 "$pid" 2>/dev/null || return 0
    sleep 0.2
  done
  kill -KILL "$pid" 2>/dev/null || true
}

cleanup() {
  local rc=$? i
  if [ ${#JOBS[@]} -gt 0 ] && [ -n "${SLURM_CONF:-}" ]; then
    scancel "${JOBS[@]}" 2>/dev/null || true
    for i in $(seq 50); do   # let slurmd end the job steps before it stops
      [ -z "$(squeue -h -j "$(IFS=,; echo "${JOBS[*]}")" -t RUNNING,COMPLETING -o %i 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  for ((i = ${#STARTED_PIDS[@]} - 1; i >= 0; i--)); do
    stop_pid "${STARTED_PIDS[i]}"
  done
  rm -f "$TEST_DIR"/*.pid
  exit "$rc"
}

# A previous run killed before its trap ran may have left its daemons: stop those.
stop_stale_daemons() {
  local f pid
  for f in "$TEST_DIR"/*.pid; do
    [ -f "$f" ] || continue
    pid="$(cat "$f")"
    if [[ "$pid" =~ ^[0-9]+$ ]] && grep -qE 'slurmctld|slurmd|munged' "/proc/$pid/comm" 2>/dev/null; then
      say "stopping daemon $pid left by an earlier run ($(basename "$f"))"
      stop_pid "$pid"
    fi
  done
}

start_munge() {
  if munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
    say "munged already running"
    return 0
  fi
  if [ ! -s /etc/munge/munge.key ]; then
    say "creating /etc/munge/munge.key"
    mkdir -p /etc/munge
    dd if=/dev/urandom of=/etc/munge/munge.key bs=1 count=1024 status=none
  fi
  chown -R munge:munge /etc/munge
  chmod 0700 /etc/munge
  chmod 0400 /etc/munge/munge.key
  mkdir -p /run/munge /var/lib/munge /var/log/munge
  chown munge:munge /run/munge /var/lib/munge /var/log/munge
  chmod 0755 /run/munge
  setpriv --reuid=munge --regid=munge --init-groups /usr/sbin/munged --foreground >"$TEST_DIR/munged.log" 2>&1 &
  STARTED_PIDS+=("$!")
  echo "$!" >"$TEST_DIR/munged.pid"
  local i
  for i in $(seq 50); do
    munge -n 2>/dev/null | unmunge >/dev/null 2>&1 && return 0
    kill -0 "$!" 2>/dev/null || break
    sleep 0.2
  done
  tail -n 20 "$TEST_DIR/munged.log" >&2 || true
  fail "munged did not start (log above)"
}

write_slurm_conf() {
  local node_line
  # slurmd -C prints this machine's real CPUs, sockets, cores, threads and memory.
  node_line="$(slurmd -C | head -n 1 | sed "s/^NodeName=[^ ]*/NodeName=$NODE/")"
  mkdir -p "$TEST_DIR/ctld" "$TEST_DIR/slurmd"
  cat >"$TEST_DIR/slurm.conf" <<CONF
# Single-node test cluster written by scripts/test-slurm.sh.
ClusterName=silvatest
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation=$TEST_DIR/ctld
SlurmdSpoolDir=$TEST_DIR/slurmd
SlurmctldPidFile=$TEST_DIR/slurmctld.daemon-pid
SlurmdPidFile=$TEST_DIR/slurmd.daemon-pid
SlurmctldLogFile=$TEST_DIR/slurmctld.log
SlurmdLogFile=$TEST_DIR/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
MinJobAge=3600
MailProg=/bin/true
$node_line NodeAddr=127.0.0.1 State=UNKNOWN
PartitionName=test Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
CONF
  export SLURM_CONF="$TEST_DIR/slurm.conf"
}

# Starts one Slurm daemon in the foreground mode (-D), in the background of this shell.
start_slurm_daemon() {
  local name="$1"; shift
  "$name" -D -f "$SLURM_CONF" "$@" >"$TEST_DIR/$name.stderr" 2>&1 &
  STARTED_PIDS+=("$!")
  echo "$!" >"$TEST_DIR/$name.pid"
}

show_daemon_logs() {
  local f
  for f in "$TEST_DIR"/slurmctld.log "$TEST_DIR"/slurmd.log "$TEST_DIR"/*.stderr; do
    [ -s "$f" ] && { echo "--- $f (last lines)"; tail -n 15 "$f"; } >&2
  done
  return 0
}

wait_node_idle() {
  local deadline=$((SECONDS + TIMEOUT)) state pid
  while [ $SECONDS -lt $deadline ]; do
    state="$(sinfo -h -N -n "$NODE" -o %T 2>/dev/null || true)"
    [ "$state" = "idle" ] && return 0
    for pid in "${STARTED_PIDS[@]}"; do
      kill -0 "$pid" 2>/dev/null || { show_daemon_logs; fail "a Slurm daemon exited during start-up (logs above)"; }
    done
    sleep 1
  done
  show_daemon_logs
  fail "node $NODE not idle after ${TIMEOUT}s (state '${state:-none}'; logs above)"
}

# ---- the test -------------------------------------------------------------------------
write_test_config() {
  cat >"$TEST_DIR/test.toml" <<TOML
# Small dataset for make test-slurm: 3 autopilot points x 3 yaws + 4 random poses.
[output]
resolution = "64x48"

[captures]
sequences = ["autopilot", "random"]
autopilot_points = 3
random_count = 4

[world]
extent = 128
render_distance = 64
TOML
}

# Prints "<job> <state>" lines for the given jobs (array tasks one per line).
job_states() {
  squeue -h -t all -j "$1" -o '%i %T' 2>/dev/null || true
}

# Waits until none of the jobs is pending or running; returns 1 on timeout.
wait_jobs_done() {
  local ids="$1" deadline=$((SECONDS + TIMEOUT))
  while [ $SECONDS -lt $deadline ]; do
    if ! job_states "$ids" | grep -qE ' (PENDING|CONFIGURING|RUNNING|COMPLETING|SUSPENDED|REQUEUED|RESIZING)$'; then
      return 0
    fi
    sleep 2
  done
  return 1
}

show_job_logs() {
  local f
  for f in "$TEST_DIR"/logs/*; do
    [ -f "$f" ] && { echo "--- $f (last lines)"; tail -n 20 "$f"; } >&2
  done
  return 0
}

main() {
  cd "$ROOT"
  [ -x "$SILVA" ] || fail "no silva binary at '$SILVA' (run 'make build' or set SILVA=...)"
  SILVA="$(cd "$(dirname "$SILVA")" && pwd)/$(basename "$SILVA")"

  install_missing_packages
  mkdir -p "$TEST_DIR"
  stop_stale_daemons
  rm -rf "${TEST_DIR:?}"/*
  trap cleanup EXIT
  trap 'exit 130' INT TERM

  start_munge
  write_slurm_conf
  start_slurm_daemon slurmctld
  start_slurm_daemon slurmd -N "$NODE"
  wait_node_idle
  say "single-node Slurm cluster up on $NODE ($(sinfo -h -N -o '%c CPUs, %m MB'))"

  write_test_config
  say "single-process run into $TEST_DIR/A"
  if ! timeout "$TIMEOUT" "$SILVA" generate --config "$TEST_DIR/test.toml" --seed "$SEED" \
      --out "$TEST_DIR/A" --json >"$TEST_DIR/A.json" 2>"$TEST_DIR/A.stderr"; then
    tail -n 20 "$TEST_DIR/A.stderr" >&2
    fail "single-process 'silva generate' failed (stderr above)"
  fi

  say "$SHARDS-shard Slurm array + merge into $TEST_DIR/B"
  local ids array_job merge_job
  ids="$(SILVA="$SILVA" CONFIG="$TEST_DIR/test.toml" SEED="$SEED" OUT="$TEST_DIR/B" \
    LOGS="$TEST_DIR/logs" bash "$ROOT/scripts/slurm/submit.sh" -n "$SHARDS" -c 1)" \
    || fail "scripts/slurm/submit.sh failed"
  array_job="$(sed -n 's/^ARRAY_JOB_ID=\([0-9]\+\)$/\1/p' <<<"$ids")"
  merge_job="$(sed -n 's/^MERGE_JOB_ID=\([0-9]\+\)$/\1/p' <<<"$ids")"
  if [ -z "$array_job" ] || [ -z "$merge_job" ]; then fail "submit.sh printed no job ids: $ids"; fi
  JOBS=("$array_job" "$merge_job")
  wait_jobs_done "$array_job,$merge_job" || { show_job_logs; fail "Slurm jobs not done after ${TIMEOUT}s"; }

  local states
  states="$(job_states "$array_job,$merge_job")"
  say "job states: $(tr '\n' ' ' <<<"$states")"
  if [ "$(grep -c ' COMPLETED$' <<<"$states")" -ne $((SHARDS + 1)) ]; then
    show_job_logs
    fail "expected $SHARDS array tasks and the merge job COMPLETED, got: $(tr '\n' ' ' <<<"$states")"
  fi

  local seed_dir
  seed_dir="$(printf '%010d' "$SEED")"
  [ -f "$TEST_DIR/A/$seed_dir/manifest.json" ] || fail "single-process run wrote no $TEST_DIR/A/$seed_dir/manifest.json"
  [ -f "$TEST_DIR/B/$seed_dir/manifest.json" ] || fail "merge wrote no $TEST_DIR/B/$seed_dir/manifest.json"
  if ! diff -r --exclude='run*.json' --exclude=CARD.md --exclude=card.json "$TEST_DIR/A" "$TEST_DIR/B" >"$TEST_DIR/diff.txt" 2>&1; then
    head -n 20 "$TEST_DIR/diff.txt" >&2
    fail "sharded dataset differs from the single-process one (first differences above, all in $TEST_DIR/diff.txt)"
  fi
  local files
  files="$(find "$TEST_DIR/A" -type f ! -name 'run*.json' | wc -l)"
  echo "test-slurm: PASS: $SHARDS-shard Slurm array + merge equals the single-process run ($files files identical)"
  echo "test-slurm: 1 passed, 0 failed"
}

main "$@"
