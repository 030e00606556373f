#!/usr/bin/env bash
# Runs clang-tidy (checks and their rationale in .clang-tidy) over the project's own library and
# app sources (core/ ecs/ components/ world/ systems/ render/ raycast/ assets/ io/ pipeline/ app/ web/ bench/harness/, and their headers) with
# the compile database of BUILD_DIR, two files at a time. Tests and the benchmark programs are not checked.
# Usage: scripts/tidy.sh [BUILD_DIR] [JOBS]     exit 0 when clean, 1 on any finding.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-build-tidy}
jobs=${2:-2}
dirs='(core|ecs|components|world|systems|render|raycast|assets|io|pipeline|app|web|bench/harness)'
[ -f "$build/compile_commands.json" ] || { echo "tidy: no $build/compile_commands.json (configure with cmake first)" >&2; exit 2; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
run-clang-tidy -p "$build" -j "$jobs" -quiet -header-filter "^$root/$dirs/" "^$root/$dirs/.*\.cpp$" \
  >"$log" 2>&1 || status=1
# Keep the findings, drop clang-tidy's per-file chatter ("N warnings generated", command lines).
grep -v -E '^([0-9]+ warnings? (and [0-9]+ errors? )?generated\.|clang-tidy-?[0-9]* |Suppressed [0-9]+ warnings|Use -header-filter|Error while processing|Running clang-tidy|Enabled checks:)' "$log" || true
[ $status -eq 0 ] && echo "tidy: clean" >&2 || echo "tidy: findings above" >&2
exit $status
