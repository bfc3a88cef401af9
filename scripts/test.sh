#!/usr/bin/env bash
# The whole test suite, from a clean clone: installs what is missing, checks the formatting
# (scripts/format-check.sh), builds the release and the sanitizer (ASan + UBSan) builds, and runs every
# test in the release build and the library stages' tests in the sanitizer build (CMakePresets.json;
# docs/testing.md, "The test suite"). README quick start, command 2.
# Unity builds (CMAKE_UNITY_BUILD: each target's sources compiled a few at a time in one translation
# unit) take a build from scratch in about half the time; `-DCMAKE_UNITY_BUILD=OFF` on a later configure
# goes back to one object per source for incremental work.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --tests
bash scripts/format-check.sh
for preset in release debug; do
  start=$SECONDS
  cmake --preset "$preset" -DCMAKE_UNITY_BUILD=ON >/dev/null
  cmake --build --preset "$preset"
  built=$SECONDS
  ctest --preset "$preset"
  echo "test.sh: $preset: built in $((built - start)) s, tested in $((SECONDS - built)) s"
done
