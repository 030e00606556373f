#!/usr/bin/env bash
# Checks that every repository path the docs name exists.
#
# Usage: scripts/check-doc-paths.sh [REPO_ROOT]     (default: the folder above this script)
#
# Reads docs/DESIGN.md, README.md and bench/README.md and takes every backticked token
# (`...`, outside fenced code blocks) that looks like a repository path: it contains a `/` or
# ends in .cpp .hpp .toml .json .md .py .sh, does not start with `-`, `/` or `~`, is not a URL and
# contains no space, `<`, `*`, `{` or `$` (so placeholders are written `<DIR>/library.json`).
# Left out as well, since they cannot be repository paths: tokens starting with `../` (outside
# the repository), C++ scopes (`a::b`) and paths git ignores (`build/`, `out/`).
# Every other token must exist relative to REPO_ROOT, or relative to a folder named in an
# earlier backticked token on the same line (a table row `app/` ... `cli/` names `app/cli/`).
# Each one that does not is printed as `file: path`, and the exit status is 1.
set -euo pipefail

root="${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}"
cd "$root"

docs=(docs/DESIGN.md README.md bench/README.md)
checked=0
missing=0

have_git=0
if command -v git >/dev/null 2>&1 && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  have_git=1
fi

ignored() {  # does git ignore $1, or the folder it starts with?
  ((have_git)) || return 1
  local path="$1" first="${1%%/*}"
  git check-ignore -q --no-index -- "$path" 2>/dev/null && return 0
  git check-ignore -q --no-index -- "$path/" 2>/dev/null && return 0
  git check-ignore -q --no-index -- "$first/" 2>/dev/null && return 0
  return 1
}

is_path() {  # does token $1 look like a repository path?
  case "$1" in
    '' | -* | /* | '~'* | ../* | *://* | *' '* | *'<'* | *'*'* | *'{'* | *'$'* | *::*) return 1 ;;
  esac
  [[ "$1" == */* ]] && return 0
  case "$1" in
    *.cpp | *.hpp | *.toml | *.json | *.md | *.py | *.sh) return 0 ;;
  esac
  return 1
}

# One line per backticked token outside ``` fences: the token, a tab, the folders named by
# earlier backticked tokens on its line (space-separated).
tokens() {
  awk '
    /^[[:space:]]*```/ { fence = !fence; next }
    fence { next }
    {
      line = $0; folders = ""
      while (match(line, /`[^`]*`/)) {
        tok = substr(line, RSTART + 1, RLENGTH - 2)
        line = substr(line, RSTART + RLENGTH)
        print tok "\t" folders
        if (tok ~ /\/$/ && tok !~ /[ <*{$]/) folders = folders " " tok
      }
    }' "$1"
}

for doc in "${docs[@]}"; do
  if [[ ! -f "$doc" ]]; then
    echo "$doc: (the document itself is missing)"
    missing=$((missing + 1))
    continue
  fi
  declare -A seen=()
  while IFS=$'\t' read -r token folders; do
    is_path "$token" || continue
    path="${token#./}"
    path="${path%/}"
    ignored "$path" && continue
    found=0
    if [[ -e "$path" ]]; then
      found=1
    else
      for folder in $folders; do
        if [[ -e "${folder%/}/$path" ]]; then found=1; break; fi
      done
    fi
    [[ -n "${seen[$token]:-}" ]] && continue
    seen[$token]=1
    checked=$((checked + 1))
    if ((!found)); then
      echo "$doc: $token"
      missing=$((missing + 1))
    fi
  done < <(tokens "$doc")
  unset seen
done

if ((missing > 0)); then
  echo "doc paths: $missing of $checked missing" >&2
  exit 1
fi
echo "doc paths: $checked checked, all exist"
