#!/usr/bin/env bash
# The C++ sources in VTK's style (.clang-format): `scripts/format.sh` reformats them in place,
# `scripts/format.sh --check` lists the files that differ and exits 1 (the test source.format).
# The files git tracks: a build folder inside the tree holds generated C++ of its own.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
format="${CLANG_FORMAT:-clang-format}"
if ! command -v "$format" >/dev/null 2>&1; then
  echo "clang-format not found (Debian: apt-get install clang-format)" >&2
  exit 2
fi
mapfile -t files < <(git ls-files -- '*.cxx' '*.h' '*.txx' | \
  while read -r f; do [ -f "$f" ] && echo "$f"; done)
if [ "${1:-}" = "--check" ]; then
  # one run over every file; only when it finds something, one run per file to name them
  if "$format" --style=file --dry-run -Werror "${files[@]}" >/dev/null 2>&1; then
    echo "${#files[@]} files checked, 0 not formatted"
    exit 0
  fi
  bad=0
  for f in "${files[@]}"; do
    if ! "$format" --style=file --dry-run -Werror "$f" >/dev/null 2>&1; then
      echo "not formatted: $f"
      bad=$((bad + 1))
    fi
  done
  echo "${#files[@]} files checked, $bad not formatted (scripts/format.sh reformats them)"
  [ "$bad" -eq 0 ]
else
  "$format" --style=file -i "${files[@]}"
  echo "${#files[@]} files formatted"
fi
