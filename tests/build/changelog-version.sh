#!/usr/bin/env bash
# The newest release heading of CHANGELOG.md names the version CMake builds (project() in
# CMakeLists.txt), so a version bump without its changelog entry, or the reverse, fails.
#   changelog-version.sh SOURCE_DIR VERSION
set -euo pipefail
changelog="$1/CHANGELOG.md"
[ -f "$changelog" ] || { echo "changelog-version: $changelog is missing" >&2; exit 1; }
newest=$(grep -m1 -oE '^## \[[0-9]+\.[0-9]+\.[0-9]+\]' "$changelog" | grep -oE '[0-9]+\.[0-9]+\.[0-9]+' || true)
if [ "$newest" != "$2" ]; then
  echo "changelog-version: CHANGELOG.md's newest release is '${newest:-none}', CMakeLists.txt builds $2;" \
       "add a '## [$2]' section (or fix the version)" >&2
  exit 1
fi
echo "changelog-version: CHANGELOG.md and CMakeLists.txt both name $2"
