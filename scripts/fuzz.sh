#!/usr/bin/env bash
# Runs every libFuzzer harness of a fuzz build folder for a set time from its seed corpus.
# Usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]   (default: every target)
# New interesting inputs go to BUILD_DIR/fuzz-corpus/<target>/ (the repository's corpus is only
# read); a crash, leak, timeout or out-of-memory leaves its input in BUILD_DIR/crashes/<target>/ and
# makes the script exit 1 (inputs slower than 10 s land there too, as slow-unit-*, and are only counted).
# One summary line per target: seconds run (wall and CPU: on a busy machine they differ), executions,
# coverage, crashes.
set -uo pipefail
build=${1:?usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]}
seconds=${2:?usage: scripts/fuzz.sh BUILD_DIR SECONDS [TARGET...]}
shift 2
root=$(cd "$(dirname "$0")/.." && pwd)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(config set pose_json pose_csv ontology lighting library gltf glb obj marker camera_json png manifest
  label_png imu_csv imu_yaml trajectory_file mesh_pack)
failed=0
for t in "${targets[@]}"; do
  exe="$build/tests/fuzz/silva_fuzz_$t"
  [ -x "$exe" ] || { echo "fuzz: $exe missing; build the fuzz_harnesses target first" >&2; exit 2; }
  mkdir -p "$build/fuzz-corpus/$t" "$build/crashes/$t"
  log="$build/crashes/$t.log"
  start=$(date +%s)
  TIMEFORMAT='%U %S'
  { time ASAN_OPTIONS=detect_leaks=0 "$exe" -max_total_time="$seconds" -rss_limit_mb=4096 -timeout=30 \
      -artifact_prefix="$build/crashes/$t/" "$build/fuzz-corpus/$t" "$root/tests/fuzz/corpus/$t" >"$log" 2>&1; } \
    2>"$build/crashes/$t.time"
  rc=$?
  elapsed=$(( $(date +%s) - start ))
  cpu=$(awk '{printf "%.0f", $1 + $2}' "$build/crashes/$t.time")
  stats=$(grep -E '^#[0-9]+' "$log" | tail -1)  # '#runs DONE cov: ft: corp: exec/s: rss:'
  crashes=$(find "$build/crashes/$t" -type f ! -name 'slow-unit-*' | wc -l)
  slow=$(find "$build/crashes/$t" -type f -name 'slow-unit-*' | wc -l)
  echo "fuzz $t: ${elapsed} s (${cpu} s CPU), exit $rc, crashes $crashes, slow units $slow, last: $stats"
  [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ] && failed=1
done
exit $failed
