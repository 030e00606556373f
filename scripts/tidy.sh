#!/usr/bin/env bash
# Runs clang-tidy (checks in .clang-tidy) over every project .cpp using the build's compile database.
set -euo pipefail
build=${1:-build}
files=$(git ls-files '*.cpp' | grep -v -E '^(tests|bench)/')
status=0
for f in $files; do
  clang-tidy -p "$build" --quiet "$f" 2>/dev/null || status=1
done
exit $status
