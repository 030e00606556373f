#!/usr/bin/env bash
# Checks that `make run` installs no package that only the tests need: simulates
# `apt-get install --no-install-recommends` of the run list (scripts/install-deps.sh --list) on a
# fresh machine (an empty dpkg status, so apt counts nothing as installed) and fails, naming each
# one, if the packages apt would install include a test-only package: one of the test list
# (install-deps.sh --test) not in the run list, or one in TEST_ONLY below.
# Usage: scripts/check-run-deps.sh [REPO_ROOT]
# Exit 0: clean; 1: a test-only package, or apt cannot resolve the run list;
# 77 (skipped): no apt-get, or no apt package lists to resolve against (run `apt-get update`).
set -euo pipefail

root="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
# The test tools and what only they bring in; they stay test-only even when moved to the run list.
TEST_ONLY=(
  libgtest-dev libgmock-dev googletest libbenchmark-dev libbenchmark1debian
  python3 python3-numpy python3-opencv python3-yaml
  chromium chromium-common
)

command -v apt-get >/dev/null || { echo "check-run-deps: skipped, no apt-get here" >&2; exit 77; }
lists=$(apt-config shell d Dir::State::lists/d | sed "s/^d='\(.*\)'$/\1/")
if ! compgen -G "${lists:-/var/lib/apt/lists/}*_Packages*" >/dev/null; then
  echo "check-run-deps: skipped, no apt package lists in ${lists:-/var/lib/apt/lists/} (run apt-get update)" >&2
  exit 77
fi

mapfile -t run < <(bash "$root/scripts/install-deps.sh" --list)
mapfile -t with_tests < <(bash "$root/scripts/install-deps.sh" --list --test)
declare -A in_run=() forbidden=()
for p in "${run[@]}"; do in_run[$p]=1; done
for p in "${with_tests[@]}"; do [ -n "${in_run[$p]:-}" ] || forbidden[$p]=1; done
for p in "${TEST_ONLY[@]}"; do forbidden[$p]=1; done

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
: >"$work/status"
if ! apt-get install --simulate --no-install-recommends -q -o Dir::State::status="$work/status" \
     -o Debug::NoLocking=1 "${run[@]}" >"$work/out" 2>&1; then
  cat "$work/out" >&2
  echo "check-run-deps: apt cannot resolve the run list on a fresh machine (output above)" >&2
  exit 1
fi
mapfile -t closure < <(awk '$1 == "Inst" { sub(/:.*/, "", $2); print $2 }' "$work/out")
bad=()
for p in "${closure[@]}"; do [ -z "${forbidden[$p]:-}" ] || bad+=("$p"); done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check-run-deps: \`make run\` would install test-only packages: ${bad[*]}" >&2
  exit 1
fi
echo "check-run-deps: the run list installs ${#closure[@]} packages on a fresh machine, none test-only"
