#!/usr/bin/env bash
# Installs exactly the Debian (bookworm) packages Silva's build and tests need; a fast no-op
# (one dpkg-query call) when every one is already installed. Runs as root, or through sudo.
# Usage: scripts/install-deps.sh [--bench] [--tidy] [--fuzz]
#   --bench  also what `make bench` needs (OpenGL/EGL for the llvmpipe comparison renderer,
#            matplotlib/numpy for the plots)
#   --tidy   also clang-tidy, for `make tidy`
#   --fuzz   also clang and libFuzzer, for `make fuzz`
# ccache is optional (CMake uses it when present) and git only names the revision; neither is listed.
# chromium is only for the browser test of `silva view` (headless, driven over its DevTools pipe).
set -euo pipefail

PKGS=(
  cmake make g++ pkg-config
  libeigen3-dev
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libassimp-dev libfcl-dev libtbb-dev libmeshoptimizer-dev libhwy-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libtinygltf-dev
  libdeflate-dev libxxhash-dev libssl-dev libcpp-httplib-dev libembree-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-opencv python3-yaml
  chromium
)
BENCH_PKGS=(
  libegl-dev libgl-dev libgles-dev libgl1-mesa-dri libegl-mesa0
  python3-matplotlib python3-numpy
)
TIDY_PKGS=(clang-tidy)
FUZZ_PKGS=(clang-14 libfuzzer-14-dev)

for arg in "$@"; do
  case "$arg" in
    --bench) PKGS+=("${BENCH_PKGS[@]}") ;;
    --tidy) PKGS+=("${TIDY_PKGS[@]}") ;;
    --fuzz) PKGS+=("${FUZZ_PKGS[@]}") ;;
    -h | --help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-deps: unknown option '$arg' (allowed: --bench, --tidy, --fuzz)" >&2; exit 2 ;;
  esac
done

# One dpkg-query for all packages; unknown ones print nothing (and make it exit 1).
installed=$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${PKGS[@]}" 2>/dev/null || true)
declare -A state=()
while read -r name status; do [ -n "$name" ] && state[$name]=$status; done <<<"$installed"
missing=()
for p in "${PKGS[@]}"; do
  [ "${state[$p]:-}" = installed ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root (or install sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
install=("${SUDO[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}")
# Try the current package lists first (works offline from the apt cache); refresh them on failure.
if ! "${install[@]}"; then
  "${SUDO[@]}" apt-get update -q
  "${install[@]}"
fi
