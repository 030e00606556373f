#!/usr/bin/env bash
# Renders the README's asset contact sheets into docs/assets/: one sheet per group of built-in
# generators, one row per generator (its first variants), each variant's RGB beside its semantic
# colours (`silva assets sheet`).
#   SILVA  silva binary [build/silva]   COUNT  variants per generator [4]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SILVA="${SILVA:-$ROOT/build/silva}"
COUNT="${COUNT:-4}"
mkdir -p "$ROOT/docs/assets"
sheet() {  # sheet NAME KINDS...
  local name="$1"
  shift
  local kinds
  kinds="$(IFS=,; echo "$*")"
  "$SILVA" assets sheet --kind "$kinds" --count "$COUNT" --columns "$COUNT" --cell 200 \
    --out "$ROOT/docs/assets/$name.png"
}
sheet trees conifer_tree broadleaf_tree
sheet dead-wood dead_tree log stump
sheet understory grass fern shrub
sheet ground-cover ground_cover rock
