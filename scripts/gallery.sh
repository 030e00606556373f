#!/usr/bin/env bash
# Renders the README contact sheet (docs/gallery.png): one trail view from the ground and from the
# air under each lighting preset (day, dusk, night), showing RGB, semantic colours, instances,
# depth preview and normals side by side. Needs python3 with matplotlib + numpy
# (`scripts/install-deps.sh --bench`).
#   SILVA  silva binary [build/silva]   OUT  scratch folder [/tmp/silva-gallery]
#   PYTHON  the Debian python3 that has python3-matplotlib [/usr/bin/python3]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SILVA="${SILVA:-$ROOT/build/silva}"
OUT="${OUT:-/tmp/silva-gallery}"
SEED=1234567890

for time in day dusk night; do
  for view in ground aerial; do
    aerial=false; [ "$view" = aerial ] && aerial=true
    "$SILVA" generate --config "$ROOT/configs/demo.toml" --seed "$SEED" --quiet --overwrite \
      --out "$OUT/$time-$view" \
      --set lighting.time_of_day="$time" --set captures.aerial="$aerial" \
      --set 'captures.sequences=["autopilot"]' --set captures.autopilot_points=3 \
      --set 'captures.autopilot_yaws=[0.0]' --set output.resolution=640x360 \
      --set 'output.types=["rgb","semantic_color","instance","depth_preview","normal"]'
  done
done
"${PYTHON:-/usr/bin/python3}" "$ROOT/scripts/contact_sheet.py" "$OUT" "$SEED" 1 "$ROOT/docs/gallery.png"
echo "wrote $ROOT/docs/gallery.png"
