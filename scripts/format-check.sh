#!/usr/bin/env bash
# Checks that every C++ and OpenCL source is formatted as .clang-format says (clang-format 14, Debian 12's);
# `scripts/format-check.sh --fix` rewrites them in place. scripts/test.sh runs the check first, so CI
# fails within seconds on a file that was not formatted.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null ||
  { echo "format-check: clang-format is not installed (Debian package clang-format; scripts/install-deps.sh)" >&2; exit 1; }
# Tracked files and new ones not yet added (but not ignored ones: build/ holds generated sources), so that a
# file written since the last `git add` is formatted before it is committed.
mapfile -t files < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.hpp' '*.h' '*.cl')
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
  echo "format-check: formatted ${#files[@]} files"
  exit 0
fi
if ! clang-format --dry-run --Werror "${files[@]}" 2>/tmp/format-check.$$; then
  grep -oE '^[^:]+\.(cpp|hpp|h|cl)' /tmp/format-check.$$ | sort -u | sed 's/^/format-check: not formatted: /' >&2
  rm -f /tmp/format-check.$$
  echo "format-check: run scripts/format-check.sh --fix" >&2
  exit 1
fi
rm -f /tmp/format-check.$$
echo "format-check: ${#files[@]} files formatted as .clang-format says"
