#!/usr/bin/env bash
# Submits a sharded `silva generate` to Slurm: a job array of SHARDS tasks (one shard each,
# scripts/slurm/silva-array.sbatch) and a final `silva merge` job that starts only when
# every task has succeeded (scripts/slurm/silva-merge.sbatch, --dependency=afterok).
#
# Usage: [SILVA=...] [CONFIG=...] [SEED=...] [OUT=...] [LOGS=...] \
#          scripts/slurm/submit.sh [-n SHARDS] [-c CPUS_PER_SHARD] [-- SBATCH_ARGS...]
#   -n SHARDS          array size N, tasks 0..N-1              [$SHARDS or 4]
#   -c CPUS_PER_SHARD  --cpus-per-task of each array task      [$CPUS_PER_SHARD or 1]
#   SBATCH_ARGS        passed to both sbatch calls (--partition, --time, --account, ...)
#   SILVA   silva binary                   [silva on PATH]
#   CONFIG  TOML config                    [configs/demo.toml]
#   SEED    world seed                     [1]
#   OUT     output.dir, on a filesystem every node shares; dataset in $OUT/<seed %010d>/ [out]
#   LOGS    folder for the jobs' stdout/stderr                                [$OUT/slurm-logs]
# Prints ARRAY_JOB_ID=<id> and MERGE_JOB_ID=<id> on stdout (eval-able); messages on stderr.
set -euo pipefail

die() { echo "submit.sh: $*" >&2; exit 2; }

SHARDS="${SHARDS:-4}"
CPUS_PER_SHARD="${CPUS_PER_SHARD:-1}"
while [ $# -gt 0 ]; do
  case "$1" in
    -n) [ $# -ge 2 ] || die "-n needs a value"; SHARDS="$2"; shift 2 ;;
    -c) [ $# -ge 2 ] || die "-c needs a value"; CPUS_PER_SHARD="$2"; shift 2 ;;
    --) shift; break ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) die "unknown argument '$1' (allowed: -n SHARDS, -c CPUS_PER_SHARD, -- SBATCH_ARGS...)" ;;
  esac
done
[[ "$SHARDS" =~ ^[1-9][0-9]*$ ]] || die "SHARDS '$SHARDS' must be a whole number >= 1"
[[ "$CPUS_PER_SHARD" =~ ^[1-9][0-9]*$ ]] || die "CPUS_PER_SHARD '$CPUS_PER_SHARD' must be a whole number >= 1"

SLURM_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
SILVA="${SILVA:-silva}"
CONFIG="${CONFIG:-configs/demo.toml}"
SEED="${SEED:-1}"
OUT="${OUT:-out}"
LOGS="${LOGS:-$OUT/slurm-logs}"

[[ "$SEED" =~ ^[0-9]{1,10}$ ]] || die "SEED '$SEED' must be a whole number 0 ... 9999999999"
SEED=$((10#$SEED))
[ -f "$CONFIG" ] || die "CONFIG '$CONFIG' is not a file"
if [[ "$SILVA" != */* ]]; then
  found="$(command -v "$SILVA")" || die "SILVA '$SILVA' is not on PATH (set SILVA=/path/to/silva)"
  SILVA="$found"
fi
[ -x "$SILVA" ] || die "SILVA '$SILVA' is not an executable file"
command -v sbatch >/dev/null || die "sbatch is not on PATH (is this a Slurm login node?)"

mkdir -p "$OUT" "$LOGS" || { echo "submit.sh: cannot create '$OUT' or '$LOGS'" >&2; exit 3; }
# Jobs may start in another folder on another node: hand them absolute paths.
SILVA="$(cd "$(dirname "$SILVA")" && pwd)/$(basename "$SILVA")"
CONFIG="$(cd "$(dirname "$CONFIG")" && pwd)/$(basename "$CONFIG")"
OUT="$(cd "$OUT" && pwd)"
LOGS="$(cd "$LOGS" && pwd)"
export SILVA CONFIG SEED OUT

# sbatch --parsable prints "<job id>" or "<job id>;<cluster>".
array_out="$(sbatch --parsable --export=ALL --array="0-$((SHARDS - 1))" \
  --cpus-per-task="$CPUS_PER_SHARD" --output="$LOGS/silva-%A_%a.out" \
  "$@" "$SLURM_DIR/silva-array.sbatch")"
array_job="${array_out%%;*}"
merge_out="$(sbatch --parsable --export=ALL --dependency="afterok:$array_job" \
  --kill-on-invalid-dep=yes --output="$LOGS/silva-merge-%j.out" \
  "$@" "$SLURM_DIR/silva-merge.sbatch")"
merge_job="${merge_out%%;*}"

echo "submit.sh: array job $array_job (${SHARDS} shards x ${CPUS_PER_SHARD} CPUs), merge job $merge_job; dataset $OUT/$(printf '%010d' "$SEED"), logs $LOGS" >&2
echo "ARRAY_JOB_ID=$array_job"
echo "MERGE_JOB_ID=$merge_job"
