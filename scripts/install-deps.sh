#!/usr/bin/env bash
# Installs the Debian (bookworm) packages a make target needs; a fast no-op (one dpkg-query call)
# when every one is already installed. Runs as root, or through sudo.
# Usage: scripts/install-deps.sh [--test] [--bench] [--tidy] [--fuzz] [--list]
#   (none)   what building and running the silva CLI needs (`make run`)
#   --test   also the test tools (GTest, Google Benchmark, Python checks, Chromium), for `make test`
#   --bench  also what `make bench` needs (Google Benchmark, OpenGL/EGL for the llvmpipe
#            comparison renderer, matplotlib/numpy for the plots)
#   --tidy   also clang-tidy, for `make tidy`
#   --fuzz   also clang and libFuzzer, for `make fuzz`
#   --list   print the packages of the chosen options, one a line, and install nothing
# ccache is optional (CMake uses it when present) and git only names the revision; neither is listed.
# chromium is only for the browser test of `silva view` (headless, driven over its DevTools pipe); node and npm
# only for the rosbag2 test's independent bag readers, which --test installs into tests/node/ (npm ci, pinned by
# its package-lock.json).
set -euo pipefail

# The toolchain and the -dev libraries the silva CLI links (CMakeLists.txt).
RUN_PKGS=(
  cmake make g++ pkg-config
  libeigen3-dev
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev
  libassimp-dev libfcl-dev libtbb-dev libmeshoptimizer-dev libhwy-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libtinygltf-dev
  libdeflate-dev libxxhash-dev libssl-dev libcpp-httplib-dev libembree-dev
)
# What only the tests need (tests/, and bench/, which `make test` builds too);
# scripts/check-run-deps.sh checks that the run list pulls in none of them.
TEST_PKGS=(
  libgtest-dev libgmock-dev libbenchmark-dev
  python3-numpy python3-opencv python3-yaml
  chromium nodejs
)
BENCH_PKGS=(
  libbenchmark-dev
  libegl-dev libgl-dev libgles-dev libgl1-mesa-dri libegl-mesa0
  python3-matplotlib python3-numpy
)
TIDY_PKGS=(clang-tidy)
FUZZ_PKGS=(clang-14 libfuzzer-14-dev)

PKGS=("${RUN_PKGS[@]}")
list=0
test=0
for arg in "$@"; do
  case "$arg" in
    --test) PKGS+=("${TEST_PKGS[@]}"); test=1
            # Debian's npm, unless an npm is already there (a nodejs build that ships its own conflicts with it).
            command -v npm >/dev/null || PKGS+=(npm) ;;
    --bench) PKGS+=("${BENCH_PKGS[@]}") ;;
    --tidy) PKGS+=("${TIDY_PKGS[@]}") ;;
    --fuzz) PKGS+=("${FUZZ_PKGS[@]}") ;;
    --list) list=1 ;;
    -h | --help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-deps: unknown option '$arg' (allowed: --test, --bench, --tidy, --fuzz, --list)" >&2; exit 2 ;;
  esac
done
# Each package once, in first-listed order.
declare -A seen=()
unique=()
for p in "${PKGS[@]}"; do
  [ -n "${seen[$p]:-}" ] || unique+=("$p")
  seen[$p]=1
done
PKGS=("${unique[@]}")
if [ $list -eq 1 ]; then
  printf '%s\n' "${PKGS[@]}"
  exit 0
fi

# One dpkg-query for all packages; unknown ones print nothing (and make it exit 1).
installed=$(dpkg-query -W -f='${Package} ${db:Status-Status}\n' "${PKGS[@]}" 2>/dev/null || true)
declare -A state=()
while read -r name status; do [ -n "$name" ] && state[$name]=$status; done <<<"$installed"
missing=()
for p in "${PKGS[@]}"; do
  [ "${state[$p]:-}" = installed ] || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then

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
fi

# The rosbag2 test's bag readers (tests/node/package.json), from the npm registry; skipped when installed.
if [ $test -eq 1 ]; then
  node_dir="$(cd "$(dirname "$0")/.." && pwd)/tests/node"
  if [ ! -f "$node_dir/node_modules/.package-lock.json" ] || ! cmp -s "$node_dir/package-lock.json" "$node_dir/node_modules/.silva-lock"; then
    (cd "$node_dir" && npm ci --no-audit --no-fund --loglevel=error && cp package-lock.json node_modules/.silva-lock)
  fi
fi
