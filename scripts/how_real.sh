#!/bin/bash
# The frames README "How real" measures: 24 ground views (12 random poses of seeds 7 and 21) at 640x360
# under each condition, RGB + semantic + depth, then their tone statistics (scripts/image_stats.py); and
# the clear day's views without sensor noise, with and without the sun (scripts/sun_shade_ratio.py).
# Usage: scripts/how_real.sh SILVA_BINARY OUT_DIR [image_stats.py options]
set -euo pipefail
silva=${1:?usage: scripts/how_real.sh SILVA_BINARY OUT_DIR}
out=${2:?usage: scripts/how_real.sh SILVA_BINARY OUT_DIR}
here=$(cd "$(dirname "$0")" && pwd)
conditions=("day clear" "day overcast" "day rain" "dusk clear" "night clear")
views() {  # views OUT_SUBDIR [generate options]: the 24 views into $out/OUT_SUBDIR
  local dir=$1
  shift
  for seed in 7 21; do
    "$silva" generate --seed "$seed" --out "$out/$dir" --overwrite --quiet \
      --set output.resolution=640x360 --set 'output.types=["rgb","semantic","depth"]' \
      --set 'captures.sequences=["random"]' --set captures.random_count=12 "$@" >/dev/null
  done
}
for condition in "${conditions[@]}"; do
  read -r time weather <<< "$condition"
  views "$time-$weather" --set lighting.time_of_day="$time" --set lighting.weather="$weather"
done
sunless=$(mktemp --suffix .toml)
trap 'rm -f "$sunless"' EXIT
printf '[lighting.presets.day]\nsun_intensity = 0.0\n' > "$sunless"
views sun --set camera.noise=false
views sunless --config "$sunless" --set camera.noise=false
runs=()
for condition in "${conditions[@]}"; do
  read -r time weather <<< "$condition"
  runs+=("$out/$time-$weather")
done
/usr/bin/python3 "$here/image_stats.py" "${runs[@]}" "${@:3}"
/usr/bin/python3 "$here/sun_shade_ratio.py" "$out/sun" "$out/sunless" "${@:3}"
