#!/usr/bin/env bash
# Installs exactly the Debian packages Silva's build and tests need.
# A fast no-op when every package is already installed.
set -euo pipefail
PKGS=(
  cmake make g++ pkg-config
  libeigen3-dev
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libassimp-dev libfcl-dev libtbb-dev libmeshoptimizer-dev libhwy-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libtinygltf-dev
  libdeflate-dev libxxhash-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
missing=()
for p in "${PKGS[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
